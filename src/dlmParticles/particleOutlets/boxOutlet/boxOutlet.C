/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "boxOutlet.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace particleOutlets
{
    defineTypeNameAndDebug(boxOutlet, 0);
    addToRunTimeSelectionTable(particleOutlet, boxOutlet, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleOutlets::boxOutlet::boxOutlet(const dictionary& dict)
:
    particleOutlet(dict),
    box_(dict.get<point>("min"), dict.get<point>("max"))
{
    const vector span(box_.span());
    if (cmptMin(span) <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "outlet " << name() << ": min " << box_.min() << " is not"
            << " below max " << box_.max() << " in every direction"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::particleOutlets::boxOutlet::holds(const point& X) const
{
    return box_.contains(X);
}


Foam::wordList Foam::particleOutlets::boxOutlet::typeKeywords()
{
    wordList words(particleOutlet::typeKeywords());
    words.append(wordList({"min", "max"}));
    return words;
}


Foam::wordList Foam::particleOutlets::boxOutlet::keywords() const
{
    return typeKeywords();
}


// ************************************************************************* //
