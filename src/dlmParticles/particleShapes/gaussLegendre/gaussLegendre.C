/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "gaussLegendre.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::gaussLegendre::gaussLegendre(const label n)
:
    nodes_(n),
    weights_(n)
{
    for (label i = 0; i < n; ++i)
    {
        scalar x = Foam::cos(constant::mathematical::pi*(i + 0.75)/(n + 0.5));
        scalar derivative = 1;
        for (int iter = 0; iter < 100; ++iter)
        {
            scalar p0 = 1;
            scalar p1 = x;
            for (label k = 2; k <= n; ++k)
            {
                const scalar p2 = ((2*k - 1)*x*p1 - (k - 1)*p0)/k;
                p0 = p1;
                p1 = p2;
            }
            derivative = n*(x*p1 - p0)/(x*x - 1);
            const scalar dx = p1/derivative;
            x -= dx;
            if (mag(dx) < 1e-16)
            {
                break;
            }
        }
        nodes_[i] = x;
        weights_[i] = 2/((1 - x*x)*sqr(derivative));
    }
}


// ************************************************************************* //
