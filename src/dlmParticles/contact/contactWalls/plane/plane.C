/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "plane.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace contactWalls
{
    defineTypeNameAndDebug(plane, 0);
    addToRunTimeSelectionTable(contactWall, plane, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactWalls::plane::plane
(
    const dictionary& dict,
    const polyMesh& mesh
)
:
    contactWall(dict),
    point_(dict.get<point>("point")),
    normal_(normalised(dict.get<vector>("normal")))
{
    if (mag(dict.get<vector>("normal")) < VSMALL)
    {
        FatalIOErrorInFunction(dict)
            << "normal of wall " << name() << " is zero" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::contactWalls::plane::typeKeywords()
{
    wordList words(contactWall::typeKeywords());
    words.append(wordList({"point", "normal"}));
    return words;
}


Foam::wordList Foam::contactWalls::plane::keywords() const
{
    return typeKeywords();
}


void Foam::contactWalls::plane::nearest
(
    const point& X,
    point& location,
    vector& normal,
    scalar& distance
) const
{
    distance = (X - point_) & normal_;
    location = X - distance*normal_;
    normal = normal_;
}


// ************************************************************************* //
