/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "planeOutlet.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace particleOutlets
{
    defineTypeNameAndDebug(planeOutlet, 0);
    addToRunTimeSelectionTable(particleOutlet, planeOutlet, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleOutlets::planeOutlet::planeOutlet(const dictionary& dict)
:
    particleOutlet(dict),
    point_(dict.get<point>("point")),
    normal_(normalised(dict.get<vector>("normal")))
{
    if (mag(dict.get<vector>("normal")) < VSMALL)
    {
        FatalIOErrorInFunction(dict)
            << "normal of outlet " << name() << " is zero"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::particleOutlets::planeOutlet::holds(const point& X) const
{
    return ((X - point_) & normal_) > 0;
}


Foam::wordList Foam::particleOutlets::planeOutlet::typeKeywords()
{
    wordList words(particleOutlet::typeKeywords());
    words.append(wordList({"point", "normal"}));
    return words;
}


Foam::wordList Foam::particleOutlets::planeOutlet::keywords() const
{
    return typeKeywords();
}


// ************************************************************************* //
