/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "particleShape.H"
#include "cutCellFraction.H"
#include "edgeHashes.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(particleShape, 0);
    defineRunTimeSelectionTable(particleShape, dictionary);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::particleShape::subBoxFraction
(
    const vector& span,
    const vector& r,
    const tensor& R,
    const vector& splitDirections,
    const scalar leafSize,
    const boundBox& bodyBounds
) const
{
    const vector halfSpan(0.5*span);
    const vector rCentre(r + halfSpan);
    const vector rBody(R.T() & rCentre);
    const scalar halfDiagonal = mag(halfSpan);

    // Outside the body-frame bounding box by more than the box's
    // circumscribed sphere: outside, without the (dear) distance
    if
    (
        cmptMax(bodyBounds.min() - rBody) >= halfDiagonal
     || cmptMax(rBody - bodyBounds.max()) >= halfDiagonal
    )
    {
        return 0;
    }

    vector normal;
    const scalar d = signedDistance(rBody, normal);

    // The signed distance is a true distance: a box whose circumscribed
    // sphere does not reach the surface is entirely inside or outside
    if (d >= halfDiagonal)
    {
        return 0;
    }
    if (d <= -halfDiagonal)
    {
        return 1;
    }

    const scalar largestSplit = max
    (
        max(splitDirections.x()*span.x(), splitDirections.y()*span.y()),
        splitDirections.z()*span.z()
    );

    if (largestSplit <= leafSize)
    {
        return cutCellFraction::box(R & normal, d, span);
    }

    // Split in two along each split direction
    const vector childSpan
    (
        splitDirections.x() > 0 ? halfSpan.x() : span.x(),
        splitDirections.y() > 0 ? halfSpan.y() : span.y(),
        splitDirections.z() > 0 ? halfSpan.z() : span.z()
    );
    const label nx = splitDirections.x() > 0 ? 2 : 1;
    const label ny = splitDirections.y() > 0 ? 2 : 1;
    const label nz = splitDirections.z() > 0 ? 2 : 1;

    scalar sum = 0;
    for (label i = 0; i < nx; ++i)
    {
        for (label j = 0; j < ny; ++j)
        {
            for (label k = 0; k < nz; ++k)
            {
                const vector offset
                (
                    i*childSpan.x(),
                    j*childSpan.y(),
                    k*childSpan.z()
                );
                sum += subBoxFraction
                (
                    childSpan,
                    r + offset,
                    R,
                    splitDirections,
                    leafSize,
                    bodyBounds
                );
            }
        }
    }

    return sum/(nx*ny*nz);
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

bool Foam::particleShape::meshPlaneLine
(
    const vector& n,
    const scalar distance,
    vector& lineNormal,
    scalar& lineDistance
)
{
    const scalar inPlane = Foam::sqrt(sqr(n.x()) + sqr(n.y()));
    if (inPlane < SMALL)
    {
        lineNormal = vector(1, 0, 0);
        lineDistance = 0;
        return false;
    }
    lineNormal = vector(n.x()/inPlane, n.y()/inPlane, 0);
    lineDistance = distance/inPlane;
    return true;
}


void Foam::particleShape::addFaceBeyondPlane
(
    const point* corners,
    const label nCorners,
    const vector& n,
    const scalar distance,
    scalar& volume,
    vector& moment,
    vector& areaSum
)
{
    // Sutherland-Hodgman against the one plane, then a fan
    const point apex(distance*n);
    FixedList<point, 8> clipped;
    label nClipped = 0;
    for (label k = 0; k < nCorners; ++k)
    {
        const point& a = corners[k];
        const point& b = corners[(k + 1) % nCorners];
        const scalar sa = (n & a) - distance;
        const scalar sb = (n & b) - distance;
        if (sa >= 0)
        {
            clipped[nClipped++] = a;
        }
        if ((sa >= 0) != (sb >= 0))
        {
            clipped[nClipped++] = a + sa/(sa - sb)*(b - a);
        }
    }
    for (label k = 1; k + 1 < nClipped; ++k)
    {
        const vector a(clipped[0] - apex);
        const vector b(clipped[k] - apex);
        const vector c(clipped[k + 1] - apex);
        const scalar v = (a & (b ^ c))/6;
        volume += v;
        moment += v*(a + b + c)/4;
        areaSum +=
            0.5*((clipped[k] - clipped[0]) ^ (clipped[k + 1] - clipped[0]));
    }
}


Foam::point Foam::particleShape::cutCentroid
(
    const point& apex,
    const vector& moment,
    const scalar volume,
    const scalar size
)
{
    // Each tetrahedron's volume is good to round-off of size^3: a sum
    // below a thousand times that is a sheet in the plane
    if (volume <= 1e3*SMALL*pow3(size))
    {
        return apex;
    }
    return apex + moment/volume;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::particleShape::surfaceCrossing
(
    const vector& r0,
    const vector& e,
    const scalar L
) const
{
    vector normal;
    scalar ta = 0;
    scalar tb = L;
    scalar da = signedDistance(r0, normal);
    scalar db = signedDistance(r0 + L*e, normal);
    if (da <= 0)
    {
        return 0;
    }

    scalar t = ta;
    for (label iter = 0; iter < 60; ++iter)
    {
        t = (ta*db - tb*da)/(db - da);
        const scalar d = signedDistance(r0 + t*e, normal);
        if (mag(d) < 1e-12*L)
        {
            break;
        }
        if (d > 0)
        {
            ta = t;
            da = d;
            db *= 0.5;
        }
        else
        {
            tb = t;
            db = d;
            da *= 0.5;
        }
    }
    return t;
}


Foam::scalar Foam::particleShape::boxFraction
(
    const boundBox& bb,
    const point& X,
    const tensor& R,
    const vector& splitDirections,
    const scalar leafSize
) const
{
    const boundBox bodyBounds
    (
        point
        (
            -support(vector(-1, 0, 0)),
            -support(vector(0, -1, 0)),
            -support(vector(0, 0, -1))
        ),
        point
        (
            support(vector(1, 0, 0)),
            support(vector(0, 1, 0)),
            support(vector(0, 0, 1))
        )
    );
    return subBoxFraction
    (
        bb.span(),
        bb.min() - X,
        R,
        splitDirections,
        leafSize,
        bodyBounds
    );
}


Foam::scalar Foam::particleShape::planeOverlap
(
    const vector& n,
    const scalar distance
) const
{
    scalar volume, sectionArea;
    vector centroid;
    if (!planeCut(n, distance, volume, centroid, sectionArea))
    {
        FatalErrorInFunction
            << "Shape " << type() << " has no exact formula for its overlap"
            << " with a wall" << exit(FatalError);
    }
    return volume;
}


bool Foam::particleShape::pairOverlap
(
    const particleShape& other,
    const scalar distance,
    scalar& volume,
    scalar& planeDistance
) const
{
    return false;
}


void Foam::particleShape::supportKinks
(
    DynamicList<vector>& ridgeAxes,
    DynamicList<vector>& cornerDirections
) const
{}


bool Foam::particleShape::planeCut
(
    const vector& n,
    const scalar distance,
    scalar& volume,
    vector& centroid,
    scalar& sectionArea
) const
{
    return false;
}


void Foam::particleShape::drawing(pointField& points, faceList& faces) const
{
    DynamicList<point> directions;
    DynamicList<face> polygons;

    if (nDimensions() == 2)
    {
        const label n = 64;
        face polygon(n);
        for (label i = 0; i < n; ++i)
        {
            const scalar angle = constant::mathematical::twoPi*i/n;
            directions.append(vector(cos(angle), sin(angle), 0));
            polygon[i] = i;
        }
        polygons.append(polygon);
    }
    else
    {
        // Icosahedron, each triangle split in four three times
        const scalar g = 0.5*(1 + sqrt(5.0));
        for (const scalar a : {-1.0, 1.0})
        {
            for (const scalar b : {-g, g})
            {
                directions.append(vector(0, a, b));
                directions.append(vector(a, b, 0));
                directions.append(vector(b, 0, a));
            }
        }
        // Faces: the triangles of mutually nearest vertices, outward
        const scalar edge2 = 4;
        forAll(directions, i)
        {
            for (label j = i + 1; j < directions.size(); ++j)
            {
                for (label k = j + 1; k < directions.size(); ++k)
                {
                    const point& a = directions[i];
                    const point& b = directions[j];
                    const point& c = directions[k];
                    if
                    (
                        mag(magSqr(a - b) - edge2) < 1e-9
                     && mag(magSqr(b - c) - edge2) < 1e-9
                     && mag(magSqr(c - a) - edge2) < 1e-9
                    )
                    {
                        const bool outward = (((b - a) ^ (c - a)) & a) > 0;
                        polygons.append
                        (
                            outward ? face{i, j, k} : face{i, k, j}
                        );
                    }
                }
            }
        }
        for (label level = 0; level < 3; ++level)
        {
            EdgeMap<label> midPoints;
            auto midPoint = [&](const label a, const label b)
            {
                const edge e(a, b);
                const auto iter = midPoints.cfind(e);
                if (iter.found())
                {
                    return *iter;
                }
                directions.append(0.5*(directions[a] + directions[b]));
                midPoints.insert(e, directions.size() - 1);
                return directions.size() - 1;
            };
            DynamicList<face> split(4*polygons.size());
            for (const face& f : polygons)
            {
                const label ab = midPoint(f[0], f[1]);
                const label bc = midPoint(f[1], f[2]);
                const label ca = midPoint(f[2], f[0]);
                split.append(face{f[0], ab, ca});
                split.append(face{ab, f[1], bc});
                split.append(face{ca, bc, f[2]});
                split.append(face{ab, bc, ca});
            }
            polygons.transfer(split);
        }
    }

    // Onto the surface along each direction, from just outside
    const scalar reach = 1.01*boundingRadius();
    points.setSize(directions.size());
    forAll(directions, i)
    {
        const vector e(directions[i]/mag(directions[i]));
        const point r0(reach*e);
        points[i] = r0 - surfaceCrossing(r0, -e, reach)*e;
    }
    faces.transfer(polygons);
}


// ************************************************************************* //
