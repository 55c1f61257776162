/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "cone.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace contactWalls
{
    defineTypeNameAndDebug(cone, 0);
    addToRunTimeSelectionTable(contactWall, cone, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactWalls::cone::cone
(
    const dictionary& dict,
    const polyMesh& mesh
)
:
    contactWall(dict),
    point1_(dict.get<point>("point1")),
    radius1_(dict.get<scalar>("radius1")),
    point2_(dict.get<point>("point2")),
    radius2_(dict.get<scalar>("radius2")),
    axis_(normalised(point2_ - point1_)),
    length_(mag(point2_ - point1_))
{
    if (length_ < VSMALL || radius1_ < 0 || radius2_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Wall " << name() << " needs distinct point1 and point2 and"
            << " radii not negative" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::contactWalls::cone::typeKeywords()
{
    wordList words(contactWall::typeKeywords());
    words.append(wordList({"point1", "radius1", "point2", "radius2"}));
    return words;
}


Foam::wordList Foam::contactWalls::cone::keywords() const
{
    return typeKeywords();
}


void Foam::contactWalls::cone::nearest
(
    const point& X,
    point& location,
    vector& normal,
    scalar& distance
) const
{
    // In the plane through the axis and X: axial a, radial rho; the
    // surface's generator runs from (0, radius1) to (length, radius2)
    const vector r(X - point1_);
    const scalar a = r & axis_;
    const vector radial(r - a*axis_);
    const scalar rho = mag(radial);
    const vector outward(rho > VSMALL ? radial/rho : vector(Zero));

    const scalar da = length_;
    const scalar dr = radius2_ - radius1_;
    const scalar s = min
    (
        max(((a*da) + (rho - radius1_)*dr)/(sqr(da) + sqr(dr)), scalar(0)),
        scalar(1)
    );
    const scalar aNear = s*da;
    const scalar rhoNear = radius1_ + s*dr;

    location = point1_ + aNear*axis_ + rhoNear*outward;
    const vector d(X - location);
    distance = mag(d);
    normal = distance > VSMALL ? d/distance : vector(Zero);
}


void Foam::contactWalls::cone::shapeContacts
(
    const particleShape& shape,
    const point& X,
    const tensor& R,
    const wallContact& c,
    DynamicList<wallContact>& planes
) const
{
    // Inside the lateral surface between the two circles: the concave side
    const vector r(X - point1_);
    const scalar a = r & axis_;
    const scalar rho = mag(r - a*axis_);
    if
    (
        a > 0 && a < length_
     && rho < radius1_ + (radius2_ - radius1_)*a/length_
    )
    {
        revolutionContacts
        (
            shape, X, R, point1_, axis_, length_, radius1_, radius2_, planes
        );
    }
    else
    {
        planes.append(c);
    }
}


// ************************************************************************* //
