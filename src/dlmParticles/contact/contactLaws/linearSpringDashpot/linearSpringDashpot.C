/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "linearSpringDashpot.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace contactLaws
{
    defineTypeNameAndDebug(linearSpringDashpot, 0);
    addToRunTimeSelectionTable(contactLaw, linearSpringDashpot, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactLaws::linearSpringDashpot::linearSpringDashpot
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

Foam::wordList Foam::contactLaws::linearSpringDashpot::typeKeywords()
{
    // Linear: the contact time does not depend on the impact velocity
    return contactLaw::typeKeywords();
}


Foam::wordList Foam::contactLaws::linearSpringDashpot::keywords() const
{
    return typeKeywords();
}


Foam::scalar Foam::contactLaws::linearSpringDashpot::exponent() const
{
    return 1;
}


Foam::scalar Foam::contactLaws::linearSpringDashpot::geometryFactor
(
    const scalar radius
) const
{
    return 1;
}


void Foam::contactLaws::linearSpringDashpot::elastic
(
    const scalar V,
    const scalar delta,
    const scalar radius,
    scalar& force,
    scalar& stiffness
) const
{
    force = stiffness_*delta;
    stiffness = stiffness_;
}


// ************************************************************************* //
