/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "overlapVolume.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace contactLaws
{
    defineTypeNameAndDebug(overlapVolume, 0);
    addToRunTimeSelectionTable(contactLaw, overlapVolume, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactLaws::overlapVolume::overlapVolume
(
    const dictionary& dict,
    const label nDimensions,
    const reference& ref
)
:
    contactLaw(dict, nDimensions)
{
    initialise(ref);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::contactLaws::overlapVolume::typeKeywords()
{
    // Nonlinear: a contact time needs the impact velocity it holds at
    wordList words(contactLaw::typeKeywords());
    words.append("impactVelocity");
    return words;
}


Foam::wordList Foam::contactLaws::overlapVolume::keywords() const
{
    return typeKeywords();
}


Foam::scalar Foam::contactLaws::overlapVolume::exponent() const
{
    return nDimensions_ == 3 ? 2 : 1.5;
}


Foam::scalar Foam::contactLaws::overlapVolume::geometryFactor
(
    const scalar radius
) const
{
    // Small-overlap lens: V = pi R* delta^2, or 4/3 sqrt(2 R*) delta^1.5
    return nDimensions_ == 3 ? pi*radius : 4.0/3.0*sqrt(2*radius);
}


void Foam::contactLaws::overlapVolume::elastic
(
    const scalar V,
    const scalar delta,
    const scalar radius,
    scalar& force,
    scalar& stiffness
) const
{
    force = stiffness_*V;

    // dV/ddelta from the small-overlap relation, so that the exact and the
    // grid overlap (which has no depth) are damped alike
    if (nDimensions_ == 3)
    {
        stiffness = stiffness_*2*sqrt(pi*radius*V);
    }
    else
    {
        const scalar depth = pow(0.75*V/sqrt(2*radius), 2.0/3.0);
        stiffness = stiffness_*2*sqrt(2*radius*depth);
    }
}


// ************************************************************************* //
