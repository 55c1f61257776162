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


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

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

Foam::wordList Foam::contactWalls::plane::keywords() const
{
    wordList words(contactWall::keywords());
    words.append(wordList({"point", "normal"}));
    return words;
}


void Foam::contactWalls::plane::near
(
    const point& X,
    const scalar reach,
    DynamicList<label>& features
) const
{
    point location;
    vector normal;
    scalar distance;
    nearest(X, location, normal, distance);
    if (distance < reach)
    {
        features.append(0);
    }
}


void Foam::contactWalls::plane::contacts
(
    const point& X,
    const scalar R,
    const labelUList& features,
    DynamicList<wallContact>& found
) const
{
    wallContact c;
    nearest(X, c.location, c.normal, c.distance);
    if (c.distance < R)
    {
        c.feature = 0;
        found.append(c);
    }
}


// ************************************************************************* //
