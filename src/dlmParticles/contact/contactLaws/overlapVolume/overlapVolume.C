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
    contactLaw(dict, nDimensions),
    stiffness_(1)
{
    setDamping();

    if (dict.found("stiffness") == dict.found("contactTime"))
    {
        FatalIOErrorInFunction(dict)
            << "Contact pair " << dict.dictName() << " (law overlapVolume)"
            << " needs either 'stiffness' or 'contactTime' with"
            << " 'impactVelocity'" << exit(FatalIOError);
    }
    if (dict.found("stiffness"))
    {
        stiffness_ = dict.get<scalar>("stiffness");
    }
    else
    {
        const scalar time = dict.get<scalar>("contactTime");
        const scalar v = dict.get<scalar>("impactVelocity");
        if (time <= 0 || v <= 0)
        {
            FatalIOErrorInFunction(dict)
                << "contactTime and impactVelocity of contact pair "
                << dict.dictName() << " must be positive" << exit(FatalIOError);
        }
        // t = tau delta0/v with K delta0^(n+1) = m v^2
        const scalar n = exponent();
        stiffness_ = ref.mass*sqr(v)/pow(time*v/tau_, n + 1)
           /leadingCoefficient(ref.radius);
    }
    if (stiffness_ <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "stiffness " << stiffness_ << " of contact pair "
            << dict.dictName() << " must be positive" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::contactLaws::overlapVolume::keywords() const
{
    wordList words(contactLaw::keywords());
    words.append(wordList({"stiffness", "contactTime", "impactVelocity"}));
    return words;
}


Foam::scalar Foam::contactLaws::overlapVolume::exponent() const
{
    return nDimensions_ == 3 ? 2 : 1.5;
}


Foam::scalar Foam::contactLaws::overlapVolume::leadingCoefficient
(
    const scalar radius
) const
{
    return
        nDimensions_ == 3
      ? stiffness_*pi*radius
      : stiffness_*4.0/3.0*sqrt(2*radius);
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
