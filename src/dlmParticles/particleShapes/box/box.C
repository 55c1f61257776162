/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "box.H"
#include "cutCellFraction.H"
#include "Tuple2.H"
#include "DynamicList.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace particleShapes
{
    defineTypeNameAndDebug(box, 0);
    addToRunTimeSelectionTable(particleShape, box, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleShapes::box::box(const vector& halfExtents)
:
    halfExtents_(halfExtents)
{}


Foam::particleShapes::box::box(const dictionary& dict)
:
    halfExtents_(dict.get<vector>("halfExtents"))
{
    if (cmptMin(halfExtents_) <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "halfExtents " << halfExtents_ << " of particle "
            << dict.dictName() << " must all be positive"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::particleShapes::box::keywords() const
{
    return wordList({"halfExtents"});
}


Foam::label Foam::particleShapes::box::nDimensions() const
{
    return 3;
}


Foam::scalar Foam::particleShapes::box::boundingRadius() const
{
    return mag(halfExtents_);
}


Foam::scalar Foam::particleShapes::box::volume() const
{
    return 8*cmptProduct(halfExtents_);
}


Foam::symmTensor Foam::particleShapes::box::inertiaPerUnitDensity() const
{
    const vector h2(cmptMultiply(halfExtents_, halfExtents_));
    const scalar V3 = volume()/3;
    return symmTensor
    (
        V3*(h2.y() + h2.z()), 0, 0,
        V3*(h2.x() + h2.z()), 0,
        V3*(h2.x() + h2.y())
    );
}


Foam::scalar Foam::particleShapes::box::signedDistance
(
    const vector& r,
    vector& normal
) const
{
    const vector sign
    (
        r.x() < 0 ? -1 : 1,
        r.y() < 0 ? -1 : 1,
        r.z() < 0 ? -1 : 1
    );
    // Beyond each pair of faces (positive outside them)
    const vector q(cmptMag(r) - halfExtents_);
    const vector beyond(max(q, vector::zero));
    const scalar outside = mag(beyond);
    if (outside > 0)
    {
        // Nearest a face, an edge or a corner
        normal = cmptMultiply(sign, beyond)/outside;
        return outside;
    }

    // Inside: nearest the face least deep below
    const direction nearest =
        q.x() >= q.y()
      ? (q.x() >= q.z() ? 0 : 2)
      : (q.y() >= q.z() ? 1 : 2);
    normal = Zero;
    normal[nearest] = sign[nearest];
    return q[nearest];
}


Foam::scalar Foam::particleShapes::box::surfaceCrossing
(
    const vector& r0,
    const vector& e,
    const scalar L
) const
{
    // Entering the solid is entering the slabs of all three pairs of faces:
    // the latest of the three entries
    scalar t = 0;
    for (direction d = 0; d < 3; ++d)
    {
        if (mag(e[d]) > SMALL)
        {
            const scalar t1 = (-halfExtents_[d] - r0[d])/e[d];
            const scalar t2 = (halfExtents_[d] - r0[d])/e[d];
            t = max(t, min(t1, t2));
        }
    }
    return min(t, L);
}


Foam::scalar Foam::particleShapes::box::boxFraction
(
    const boundBox& bb,
    const point& X,
    const tensor& R,
    const vector& splitDirections,
    const scalar leafSize
) const
{
    // Axes along the mesh axes: each row of R, a unit vector, then holds a
    // single +-1, and only then do its components' magnitudes sum to 1
    const tensor magR(cmptMag(R));
    const vector rowSums
    (
        magR.xx() + magR.xy() + magR.xz(),
        magR.yx() + magR.yy() + magR.yz(),
        magR.zx() + magR.zy() + magR.zz()
    );
    if (cmptMax(cmptMag(rowSums - vector::one)) > 1e-12)
    {
        return particleShape::boxFraction
        (
            bb, X, R, splitDirections, leafSize
        );
    }

    const vector H(magR & halfExtents_);
    const vector lo(bb.min() - X);
    const vector hi(bb.max() - X);
    scalar fraction = 1;
    for (direction d = 0; d < 3; ++d)
    {
        const scalar overlap = min(hi[d], H[d]) - max(lo[d], -H[d]);
        if (overlap <= 0)
        {
            return 0;
        }
        fraction *= overlap/(hi[d] - lo[d]);
    }
    return fraction;
}


Foam::scalar Foam::particleShapes::box::planeOverlap
(
    const vector& n,
    const scalar distance
) const
{
    // The part beyond the plane is the part below the plane of normal -n
    // at the centroid's distance
    return volume()*cutCellFraction::box(-n, distance, 2*halfExtents_);
}


void Foam::particleShapes::box::drawing
(
    pointField& points,
    faceList& faces
) const
{
    // Corner i has the sign pattern of i's bits (x: 1, y: 2, z: 4)
    points.setSize(8);
    forAll(points, i)
    {
        points[i] = cmptMultiply
        (
            halfExtents_,
            vector(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1)
        );
    }
    faces = faceList
    ({
        face{0, 4, 6, 2}, face{1, 3, 7, 5},     // -x, +x
        face{0, 1, 5, 4}, face{2, 6, 7, 3},     // -y, +y
        face{0, 2, 3, 1}, face{4, 5, 7, 6}      // -z, +z
    });
}


Foam::scalar Foam::particleShapes::box::support(const vector& u) const
{
    return cmptSum(cmptMultiply(halfExtents_, cmptMag(u)));
}


bool Foam::particleShapes::box::planeCut
(
    const vector& n,
    const scalar distance,
    scalar& volume,
    vector& centroid,
    scalar& sectionArea
) const
{
    volume = planeOverlap(n, distance);
    centroid = Zero;
    sectionArea = 0;
    if (volume <= 0)
    {
        return true;
    }

    // Clip each face to the side n.r >= distance (Sutherland-Hodgman); the
    // edges' crossings of the plane bound the section
    pointField corners;
    faceList faces;
    drawing(corners, faces);
    const scalar tol = 1e-12*mag(halfExtents_);
    auto side = [&](const point& r) { return (n & r) - distance; };

    DynamicList<DynamicList<point>> polygons;
    DynamicList<point> crossings;
    for (const face& f : faces)
    {
        DynamicList<point> clipped;
        forAll(f, k)
        {
            const point& a = corners[f[k]];
            const point& b = corners[f.nextLabel(k)];
            const scalar sa = side(a);
            const scalar sb = side(b);
            if (sa >= 0)
            {
                clipped.append(a);
            }
            if ((sa >= 0) != (sb >= 0))
            {
                const point x(a + sa/(sa - sb)*(b - a));
                clipped.append(x);
                bool seen = false;
                for (const point& c : crossings)
                {
                    seen = seen || mag(c - x) < tol;
                }
                if (!seen)
                {
                    crossings.append(x);
                }
            }
        }
        if (clipped.size() >= 3)
        {
            polygons.append(clipped);
        }
    }

    // The section: the crossings in order of angle about their mean
    point middle(Zero);
    for (const point& c : crossings)
    {
        middle += c/crossings.size();
    }
    const vector e1
    (
        normalised(n ^ (mag(n.x()) < 0.9 ? vector(1, 0, 0) : vector(0, 1, 0)))
    );
    const vector e2(n ^ e1);
    List<Tuple2<scalar, label>> order(crossings.size());
    forAll(crossings, k)
    {
        const vector d(crossings[k] - middle);
        order[k] = Tuple2<scalar, label>(atan2(d & e2, d & e1), k);
    }
    Foam::sort(order);
    DynamicList<point> section(crossings.size());
    for (const auto& o : order)
    {
        section.append(crossings[o.second()]);
    }
    if (section.size() >= 3)
    {
        polygons.append(section);
    }

    // Volume-weighted centroid of the tetrahedra from an inner point to
    // each face's fan of triangles (the clipped part is convex)
    point inner(Zero);
    label nPoints = 0;
    for (const DynamicList<point>& poly : polygons)
    {
        for (const point& r : poly)
        {
            inner += r;
            ++nPoints;
        }
    }
    inner /= nPoints;
    scalar sumV = 0;
    vector sumC(Zero);
    for (const DynamicList<point>& poly : polygons)
    {
        for (label k = 1; k + 1 < poly.size(); ++k)
        {
            const scalar v =
                mag(((poly[k] - poly[0]) ^ (poly[k + 1] - poly[0])) & (poly[0] - inner))/6;
            sumV += v;
            sumC += v*0.25*(inner + poly[0] + poly[k] + poly[k + 1]);
        }
    }
    centroid = sumC/max(sumV, VSMALL);
    for (label k = 1; k + 1 < section.size(); ++k)
    {
        sectionArea += 0.5*mag((section[k] - section[0]) ^ (section[k + 1] - section[0]));
    }
    return true;
}


void Foam::particleShapes::box::supportKinks
(
    DynamicList<vector>& ridgeAxes,
    DynamicList<vector>& cornerDirections
) const
{
    ridgeAxes.append(vector(1, 0, 0));
    ridgeAxes.append(vector(0, 1, 0));
    ridgeAxes.append(vector(0, 0, 1));
}


void Foam::particleShapes::box::write(Ostream& os) const
{
    os.writeEntry("shape", typeName);
    os.writeEntry("halfExtents", halfExtents_);
}


// ************************************************************************* //
