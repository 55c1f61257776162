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
    contactLaw(dict, nDimensions),
    stiffness_(1)
{
    setDamping();

    if (dict.found("stiffness") == dict.found("contactTime"))
    {
        FatalIOErrorInFunction(dict)
            << "Contact pair " << dict.dictName() << " (law"
            << " linearSpringDashpot) needs either 'stiffness' or"
            << " 'contactTime'" << exit(FatalIOError);
    }
    if (dict.found("stiffness"))
    {
        stiffness_ = dict.get<scalar>("stiffness");
    }
    else
    {
        // t = tau sqrt(m/k)
        const scalar time = dict.get<scalar>("contactTime");
        if (time <= 0)
        {
            FatalIOErrorInFunction(dict)
                << "contactTime of contact pair " << dict.dictName()
                << " must be positive" << exit(FatalIOError);
        }
        stiffness_ = ref.mass*sqr(tau_/time);
    }
    if (stiffness_ <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "stiffness " << stiffness_ << " of contact pair "
            << dict.dictName() << " must be positive" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::contactLaws::linearSpringDashpot::keywords() const
{
    wordList words(contactLaw::keywords());
    words.append(wordList({"stiffness", "contactTime"}));
    return words;
}


Foam::scalar Foam::contactLaws::linearSpringDashpot::exponent() const
{
    return 1;
}


Foam::scalar Foam::contactLaws::linearSpringDashpot::leadingCoefficient
(
    const scalar radius
) const
{
    return stiffness_;
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
