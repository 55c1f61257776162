/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "cutCellFraction.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

Foam::scalar Foam::cutCellFraction::unitCube
(
    scalar m1,
    scalar m2,
    scalar m3,
    scalar alpha
)
{
    if (alpha <= 0)
    {
        return 0;
    }
    if (alpha >= 1)
    {
        return 1;
    }

    // The fraction is symmetric: V(alpha) = 1 - V(1 - alpha)
    const bool upperHalf = alpha > 0.5;
    if (upperHalf)
    {
        alpha = 1 - alpha;
    }

    // Below this a component is treated as zero: the lower-dimensional
    // formulas avoid dividing by it (error of the order of the component)
    constexpr scalar negligible = 1e-9;

    scalar V;

    if (m2 < negligible)
    {
        // Plane normal to one axis
        V = alpha;
    }
    else if (m1 < negligible)
    {
        // Square cut by a line
        V =
            alpha < m2
          ? sqr(alpha)/(2*m2*m3)
          : (alpha - 0.5*m2)/m3;
    }
    else
    {
        const scalar m12 = m1 + m2;

        if (alpha < m1)
        {
            V = pow3(alpha)/(6*m1*m2*m3);
        }
        else if (alpha < m2)
        {
            V = alpha*(alpha - m1)/(2*m2*m3) + sqr(m1)/(6*m2*m3);
        }
        else if (alpha < min(m12, m3))
        {
            V =
            (
                sqr(alpha)*(3*m12 - alpha)
              + sqr(m1)*(m1 - 3*alpha)
              + sqr(m2)*(m2 - 3*alpha)
            )/(6*m1*m2*m3);
        }
        else if (m3 < m12)
        {
            V =
            (
                sqr(alpha)*(3 - 2*alpha)
              + sqr(m1)*(m1 - 3*alpha)
              + sqr(m2)*(m2 - 3*alpha)
              + sqr(m3)*(m3 - 3*alpha)
            )/(6*m1*m2*m3);
        }
        else
        {
            V = (2*alpha - m12)/(2*m3);
        }
    }

    V = min(max(V, scalar(0)), scalar(0.5));

    return upperHalf ? 1 - V : V;
}


Foam::scalar Foam::cutCellFraction::box
(
    const vector& n,
    const scalar d,
    const vector& span
)
{
    // In unit-cube coordinates s in [0,1]^3 (axes flipped so that every
    // coefficient is non-negative) the inside is sum(m_i s_i) < alpha
    scalar m[3] =
    {
        mag(n.x())*span.x(),
        mag(n.y())*span.y(),
        mag(n.z())*span.z()
    };
    const scalar sum = m[0] + m[1] + m[2];

    if (sum <= 0)
    {
        return d < 0 ? 1 : 0;
    }

    const scalar alpha = 0.5 - d/sum;

    m[0] /= sum;
    m[1] /= sum;
    m[2] /= sum;

    // Sort ascending
    if (m[0] > m[1]) std::swap(m[0], m[1]);
    if (m[1] > m[2]) std::swap(m[1], m[2]);
    if (m[0] > m[1]) std::swap(m[0], m[1]);

    return unitCube(m[0], m[1], m[2], alpha);
}


// ************************************************************************* //
