/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "contactWall.H"
#include "particleShape.H"
#include "mathematicalConstants.H"
#include "checkKeywords.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(contactWall, 0);
    defineRunTimeSelectionTable(contactWall, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactWall::contactWall(const dictionary& dict, const bool meshWall)
:
    name_(dict.dictName()),
    material_(dict.getOrDefault<word>("material", "wall")),
    lubricated_(dict.getOrDefault<bool>("lubrication", meshWall))
{}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::contactWall> Foam::contactWall::New
(
    const dictionary& dict,
    const polyMesh& mesh
)
{
    const word wallType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(wallType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "type",
            wallType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    autoPtr<contactWall> wall(cstrIter()(dict, mesh));

    checkKeywords
    (
        dict,
        wordHashSet(wall->keywords()),
        "for wall " + dict.dictName() + " (type " + wallType + ")"
    );

    return wall;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::contactWall::nearest
(
    const point& X,
    point& location,
    vector& normal,
    scalar& distance
) const
{
    NotImplemented;
}


void Foam::contactWall::near
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


void Foam::contactWall::contacts
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


void Foam::contactWall::shapeContacts
(
    const particleShape& shape,
    const point& X,
    const tensor& R,
    const wallContact& c,
    DynamicList<wallContact>& planes
) const
{
    planes.append(c);
}


void Foam::contactWall::revolutionContacts
(
    const particleShape& shape,
    const point& X,
    const tensor& R,
    const point& origin,
    const vector& axis,
    const scalar length,
    const scalar r1,
    const scalar r2,
    DynamicList<wallContact>& planes
)
{
    // Angles about the axis from e1, towards the centroid
    const vector r(X - origin);
    const vector radial(r - (r & axis)*axis);
    const scalar rho = mag(radial);
    const vector e1
    (
        rho > SMALL*length
      ? radial/rho
      : normalised(axis ^ (mag(axis.x()) < 0.9 ? vector(1, 0, 0) : vector(0, 1, 0)))
    );
    const vector e2(axis ^ e1);

    // The generator's outward normal, in its axial and radial components
    const scalar generator = Foam::sqrt(sqr(length) + sqr(r2 - r1));
    const scalar normalAxial = -(r2 - r1)/generator;
    const scalar normalRadial = length/generator;

    auto direction = [&](const scalar phi)
    {
        return cos(phi)*e1 + sin(phi)*e2;
    };
    auto normal = [&](const scalar phi)
    {
        return normalAxial*axis + normalRadial*direction(phi);
    };
    // How far the shape reaches beyond the tangent plane at phi
    auto reach = [&](const scalar phi)
    {
        const vector n(normal(phi));
        return shape.support(R.T() & n) + ((X - origin - r1*direction(phi)) & n);
    };

    // The shape's points are within its bounding radius B of X: seen from
    // the axis, within asin(B/rho) of e1 (all round when B >= rho)
    const scalar B = shape.boundingRadius();
    const bool allRound = B >= 0.95*rho;
    const scalar halfRange =
        allRound ? constant::mathematical::pi : 1.05*Foam::asin(B/rho);
    const label nSamples = 48;
    const scalar spacing = 2*halfRange/(allRound ? nSamples : nSamples - 1);
    scalarField sampled(nSamples);
    forAll(sampled, k)
    {
        sampled[k] = reach(-halfRange + k*spacing);
    }

    auto plane = [&](const scalar phi, const label feature)
    {
        const vector n(normal(phi));
        wallContact c;
        c.distance = -((X - origin - r1*direction(phi)) & n);
        c.normal = -n;
        c.location = X + c.distance*n;
        c.feature = feature;
        return c;
    };

    const scalar golden = 0.5*(Foam::sqrt(scalar(5)) - 1);
    const label start = planes.size();
    forAll(sampled, k)
    {
        const bool first = k == 0, last = k == nSamples - 1;
        const scalar before =
            first ? (allRound ? sampled[nSamples - 1] : -GREAT) : sampled[k - 1];
        const scalar after =
            last ? (allRound ? sampled[0] : -GREAT) : sampled[k + 1];
        if (sampled[k] <= 0 || sampled[k] < before || sampled[k] <= after)
        {
            continue;
        }
        scalar lo = -halfRange + (k - 1)*spacing;
        scalar hi = -halfRange + (k + 1)*spacing;
        scalar x1 = hi - golden*(hi - lo);
        scalar x2 = lo + golden*(hi - lo);
        scalar f1 = reach(x1);
        scalar f2 = reach(x2);
        while (hi - lo > 1e-10)
        {
            if (f1 > f2)
            {
                hi = x2;
                x2 = x1;
                f2 = f1;
                x1 = hi - golden*(hi - lo);
                f1 = reach(x1);
            }
            else
            {
                lo = x1;
                x1 = x2;
                f1 = f2;
                x2 = lo + golden*(hi - lo);
                f2 = reach(x2);
            }
        }
        planes.append(plane(0.5*(lo + hi), planes.size() - start));
    }

    // The same reach all round (a disk about the axis): one plane
    const label best = findMax(sampled);
    if (planes.size() == start && sampled[best] > 0)
    {
        planes.append(plane(-halfRange + best*spacing, 0));
    }
}


Foam::wordList Foam::contactWall::typeKeywords()
{
    return wordList({"type", "material", "lubrication"});
}


Foam::wordList Foam::contactWall::keywords() const
{
    return typeKeywords();
}


// ************************************************************************* //
