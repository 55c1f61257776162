/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "cylinder.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace contactWalls
{
    defineTypeNameAndDebug(cylinder, 0);
    addToRunTimeSelectionTable(contactWall, cylinder, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactWalls::cylinder::cylinder
(
    const dictionary& dict,
    const polyMesh& mesh
)
:
    contactWall(dict),
    point_(dict.get<point>("point")),
    axis_(normalised(dict.get<vector>("axis"))),
    radius_(dict.get<scalar>("radius"))
{
    if (radius_ <= 0 || mag(dict.get<vector>("axis")) < VSMALL)
    {
        FatalIOErrorInFunction(dict)
            << "Wall " << name() << " needs a positive radius and a non-zero"
            << " axis" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::contactWalls::cylinder::typeKeywords()
{
    wordList words(contactWall::typeKeywords());
    words.append(wordList({"point", "axis", "radius"}));
    return words;
}


Foam::wordList Foam::contactWalls::cylinder::keywords() const
{
    return typeKeywords();
}


void Foam::contactWalls::cylinder::nearest
(
    const point& X,
    point& location,
    vector& normal,
    scalar& distance
) const
{
    const vector r(X - point_);
    const vector radial(r - (r & axis_)*axis_);
    const scalar rho = mag(radial);
    const vector outward(rho > VSMALL ? radial/rho : vector(Zero));
    location = X - radial + radius_*outward;
    distance = mag(rho - radius_);
    normal = rho < radius_ ? -outward : outward;
}


void Foam::contactWalls::cylinder::shapeContacts
(
    const particleShape& shape,
    const point& X,
    const tensor& R,
    const wallContact& c,
    DynamicList<wallContact>& planes
) const
{
    const vector r(X - point_);
    const vector radial(r - (r & axis_)*axis_);
    if (mag(radial) < radius_)
    {
        revolutionContacts
        (
            shape, X, R, point_, axis_, radius_, radius_, radius_, planes
        );
    }
    else
    {
        planes.append(c);
    }
}


// ************************************************************************* //
