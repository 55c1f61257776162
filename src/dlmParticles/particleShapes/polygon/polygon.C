/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "polygon.H"
#include "Tuple2.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace particleShapes
{
    defineTypeNameAndDebug(polygon, 0);
    addToRunTimeSelectionTable(particleShape, polygon, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using Foam::scalar;
using Foam::vector;

// z component of a ^ b for vectors in the plane z = 0
inline scalar cross2D(const vector& a, const vector& b)
{
    return a.x()*b.y() - a.y()*b.x();
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::particleShapes::polygon::areaAndCentroid
(
    const UList<point>& points,
    scalar& area,
    point& centroid
)
{
    // Triangles fanned from the first point
    area = 0;
    vector moment(Zero);
    for (label i = 1; i + 1 < points.size(); ++i)
    {
        const vector a(points[i] - points[0]);
        const vector b(points[i + 1] - points[0]);
        const scalar twice = cross2D(a, b);
        area += 0.5*twice;
        moment += twice*(a + b)/6;
    }
    centroid =
        points.empty() ? point(Zero)
      : mag(area) > 0 ? points[0] + moment/area
      : points[0];
}


void Foam::particleShapes::polygon::clip
(
    const UList<point>& points,
    const vector& n,
    const scalar distance,
    DynamicList<point>& clipped
)
{
    clipped.clear();
    forAll(points, i)
    {
        const point& a = points[i];
        const point& b = points[points.fcIndex(i)];
        const scalar sa = (n & a) - distance;
        const scalar sb = (n & b) - distance;
        if (sa >= 0)
        {
            clipped.append(a);
        }
        if ((sa >= 0) != (sb >= 0))
        {
            clipped.append(a + sa/(sa - sb)*(b - a));
        }
    }
}


void Foam::particleShapes::polygon::set
(
    const List<vector2D>& vertices,
    const dictionary* dictPtr
)
{
    auto fail = [&](const string& message)
    {
        if (dictPtr)
        {
            FatalIOErrorInFunction(*dictPtr)
                << "vertices of particle " << dictPtr->dictName() << ": "
                << message.c_str() << exit(FatalIOError);
        }
        else
        {
            FatalErrorInFunction
                << "polygon vertices: " << message.c_str()
                << exit(FatalError);
        }
    };

    const label n = vertices.size();
    if (n < 3)
    {
        fail
        (
            "a polygon needs at least 3 vertices, " + std::to_string(n)
          + " given"
        );
    }

    pointField p(n);
    scalar size = 0;
    forAll(vertices, i)
    {
        p[i] = point(vertices[i].x(), vertices[i].y(), 0);
        size = max(size, mag(p[i] - p[0]));
    }
    // Round-off of coordinates of the polygon's size
    const scalar tol = 1e-12*size;

    forAll(p, i)
    {
        if (mag(p[p.fcIndex(i)] - p[i]) <= tol)
        {
            fail
            (
                "vertex " + std::to_string(p.fcIndex(i)) + " repeats vertex "
              + std::to_string(i) + " (an edge of zero length)"
            );
        }
    }

    // Collinear vertices, or a bow tie whose loops cancel
    point centroid;
    areaAndCentroid(p, area_, centroid);
    if (mag(area_) <= 1e-12*sqr(size))
    {
        fail("the polygon has zero area");
    }

    // Edges i and j meet only at a vertex they share: neighbours must not
    // fold back onto each other, others must not touch
    auto onSegment = [&](const point& x, const point& a, const point& b)
    {
        const vector ab(b - a);
        const scalar along = (x - a) & ab;
        return
            mag(cross2D(ab, x - a)) <= tol*mag(ab)
         && along >= -tol*mag(ab) && along <= magSqr(ab) + tol*mag(ab);
    };
    for (label i = 0; i < n; ++i)
    {
        const point& a = p[i];
        const point& b = p[p.fcIndex(i)];
        for (label j = i + 1; j < n; ++j)
        {
            const point& c = p[j];
            const point& d = p[p.fcIndex(j)];
            const bool next = j == i + 1;
            const bool previous = p.fcIndex(j) == i;
            bool meet = false;
            if (next)
            {
                meet = onSegment(d, a, b) || onSegment(a, c, d);
            }
            else if (previous)
            {
                meet = onSegment(b, c, d) || onSegment(c, a, b);
            }
            else
            {
                const scalar s1 = cross2D(b - a, c - a);
                const scalar s2 = cross2D(b - a, d - a);
                const scalar s3 = cross2D(d - c, a - c);
                const scalar s4 = cross2D(d - c, b - c);
                meet =
                    (
                        ((s1 > 0 && s2 < 0) || (s1 < 0 && s2 > 0))
                     && ((s3 > 0 && s4 < 0) || (s3 < 0 && s4 > 0))
                    )
                 || onSegment(c, a, b) || onSegment(d, a, b)
                 || onSegment(a, c, d) || onSegment(b, c, d);
            }
            if (meet)
            {
                fail
                (
                    "the polygon intersects itself: edge "
                  + std::to_string(i) + "-" + std::to_string(p.fcIndex(i))
                  + " meets edge " + std::to_string(j) + "-"
                  + std::to_string(p.fcIndex(j))
                  + " (the vertices must go round a simple polygon once)"
                );
            }
        }
    }

    if (area_ < 0)
    {
        Foam::reverse(p);
        area_ = -area_;
    }

    vertices_ = p - centroid;
    forAll(vertices_, i)
    {
        vertices_[i].z() = 0;
    }
    edgeNormals_.setSize(n);
    boundingRadius_ = 0;
    convex_ = true;
    forAll(vertices_, i)
    {
        const vector edge(vertices_[vertices_.fcIndex(i)] - vertices_[i]);
        edgeNormals_[i] = vector(edge.y(), -edge.x(), 0)/mag(edge);
        boundingRadius_ = max(boundingRadius_, mag(vertices_[i]));
        const vector nextEdge
        (
            vertices_[vertices_.fcIndex(vertices_.fcIndex(i))]
          - vertices_[vertices_.fcIndex(i)]
        );
        if (cross2D(edge, nextEdge) < -tol*mag(edge))
        {
            convex_ = false;
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleShapes::polygon::polygon(const List<vector2D>& vertices)
:
    area_(0),
    boundingRadius_(0),
    convex_(true)
{
    set(vertices, nullptr);
}


Foam::particleShapes::polygon::polygon(const dictionary& dict)
:
    area_(0),
    boundingRadius_(0),
    convex_(true)
{
    set(dict.get<List<vector2D>>("vertices"), &dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::particleShapes::polygon::typeKeywords()
{
    return wordList({"vertices"});
}


Foam::wordList Foam::particleShapes::polygon::keywords() const
{
    return typeKeywords();
}


Foam::label Foam::particleShapes::polygon::nDimensions() const
{
    return 2;
}


Foam::scalar Foam::particleShapes::polygon::boundingRadius() const
{
    return boundingRadius_;
}


bool Foam::particleShapes::polygon::convex() const
{
    return convex_;
}


Foam::scalar Foam::particleShapes::polygon::volume() const
{
    return area_;
}


Foam::symmTensor Foam::particleShapes::polygon::inertiaPerUnitDensity() const
{
    // Second moments of area over the triangles from the centroid to each
    // edge, per unit depth as the disk's: about x the integral of y^2,
    // about y of x^2, about z their sum; the product -integral of xy
    scalar xx = 0, yy = 0, xy = 0;
    forAll(vertices_, i)
    {
        const point& a = vertices_[i];
        const point& b = vertices_[vertices_.fcIndex(i)];
        const scalar twice = cross2D(a, b);
        xx += twice*(sqr(a.x()) + a.x()*b.x() + sqr(b.x()))/12;
        yy += twice*(sqr(a.y()) + a.y()*b.y() + sqr(b.y()))/12;
        xy += twice*(2*a.x()*a.y() + a.x()*b.y() + b.x()*a.y() + 2*b.x()*b.y())/24;
    }
    return symmTensor(yy, -xy, 0, xx, 0, xx + yy);
}


Foam::scalar Foam::particleShapes::polygon::signedDistance
(
    const vector& r,
    vector& normal
) const
{
    const point x(r.x(), r.y(), 0);

    // Nearest point over the edges, and the crossing number of a ray
    // along +x for the inside test
    scalar nearest = GREAT;
    label nearestEdge = -1;
    scalar nearestAlong = 0;
    bool inside = false;
    forAll(vertices_, i)
    {
        const point& a = vertices_[i];
        const point& b = vertices_[vertices_.fcIndex(i)];
        const vector ab(b - a);
        const scalar s = min(max(((x - a) & ab)/magSqr(ab), scalar(0)), scalar(1));
        const scalar d = mag(x - (a + s*ab));
        if (d < nearest)
        {
            nearest = d;
            nearestEdge = i;
            nearestAlong = s;
        }
        if ((a.y() > x.y()) != (b.y() > x.y()))
        {
            const scalar xCross = a.x() + (x.y() - a.y())/ab.y()*ab.x();
            if (x.x() < xCross)
            {
                inside = !inside;
            }
        }
    }

    // Along the edge's normal off its middle; off a vertex, along the
    // line from it (outward: from the vertex when outside, towards it
    // when inside)
    const label i = nearestEdge;
    if (nearestAlong > 0 && nearestAlong < 1)
    {
        normal = edgeNormals_[i];
    }
    else
    {
        const point& v =
            nearestAlong <= 0 ? vertices_[i] : vertices_[vertices_.fcIndex(i)];
        const vector away(x - v);
        const scalar magAway = mag(away);
        if (magAway > VSMALL)
        {
            normal = inside ? -away/magAway : away/magAway;
        }
        else
        {
            const label k = nearestAlong <= 0 ? i : vertices_.fcIndex(i);
            const vector bisector
            (
                edgeNormals_[vertices_.rcIndex(k)] + edgeNormals_[k]
            );
            normal = bisector/mag(bisector);
        }
    }
    return inside ? -nearest : nearest;
}


Foam::scalar Foam::particleShapes::polygon::surfaceCrossing
(
    const vector& r0,
    const vector& e,
    const scalar L
) const
{
    // The first edge the line meets from r0 (outside) is where it enters
    const point x0(r0.x(), r0.y(), 0);
    const vector d(e.x(), e.y(), 0);
    if (magSqr(d) < SMALL)
    {
        return 0;
    }
    scalar first = L;
    forAll(vertices_, i)
    {
        const point& a = vertices_[i];
        const vector ab(vertices_[vertices_.fcIndex(i)] - a);
        const scalar denom = cross2D(d, ab);
        if (mag(denom) < VSMALL)
        {
            continue;
        }
        const scalar t = cross2D(a - x0, ab)/denom;
        const scalar s = cross2D(a - x0, d)/denom;
        if (s >= 0 && s <= 1 && t >= 0)
        {
            first = min(first, t);
        }
    }
    return first;
}


Foam::scalar Foam::particleShapes::polygon::boxFraction
(
    const boundBox& bb,
    const point& X,
    const tensor& R,
    const vector& splitDirections,
    const scalar leafSize
) const
{
    // The polygon placed and turned, relative to the cell's lower corner,
    // clipped by the cell's four sides
    const vector span(bb.span());
    const point lo(bb.min() - X);
    DynamicList<point> current(vertices_.size() + 4);
    for (const point& v : vertices_)
    {
        const point g((R & v) - lo);
        current.append(point(g.x(), g.y(), 0));
    }
    DynamicList<point> next(current.size() + 4);
    const vector sides[4] =
    {
        vector(1, 0, 0), vector(-1, 0, 0), vector(0, 1, 0), vector(0, -1, 0)
    };
    const scalar offsets[4] = {0, -span.x(), 0, -span.y()};
    for (label k = 0; k < 4 && current.size(); ++k)
    {
        clip(current, sides[k], offsets[k], next);
        current.transfer(next);
    }
    if (current.size() < 3)
    {
        return 0;
    }
    scalar area;
    point centroid;
    areaAndCentroid(current, area, centroid);
    return min(max(area/(span.x()*span.y()), scalar(0)), scalar(1));
}


bool Foam::particleShapes::polygon::planeCut
(
    const vector& n,
    const scalar distance,
    scalar& volume,
    vector& centroid,
    scalar& sectionArea
) const
{
    centroid = Zero;
    sectionArea = 0;
    vector m;
    scalar lineDistance;
    if (!meshPlaneLine(n, distance, m, lineDistance))
    {
        volume = distance < 0 ? area_ : 0;
        return true;
    }

    DynamicList<point> part(vertices_.size() + 2);
    clip(vertices_, m, lineDistance, part);
    volume = 0;
    if (part.size() >= 3)
    {
        areaAndCentroid(part, volume, centroid);
        volume = max(volume, scalar(0));
    }

    // The line inside the polygon: between alternate crossings of the
    // edges, ordered along it
    const vector t(-m.y(), m.x(), 0);
    DynamicList<scalar> crossings;
    forAll(vertices_, i)
    {
        const point& a = vertices_[i];
        const point& b = vertices_[vertices_.fcIndex(i)];
        const scalar sa = (m & a) - lineDistance;
        const scalar sb = (m & b) - lineDistance;
        if ((sa >= 0) != (sb >= 0))
        {
            crossings.append(t & (a + sa/(sa - sb)*(b - a)));
        }
    }
    Foam::sort(crossings);
    for (label k = 0; k + 1 < crossings.size(); k += 2)
    {
        sectionArea += crossings[k + 1] - crossings[k];
    }
    return true;
}


Foam::scalar Foam::particleShapes::polygon::support(const vector& u) const
{
    scalar farthest = -GREAT;
    for (const point& v : vertices_)
    {
        farthest = max(farthest, v.x()*u.x() + v.y()*u.y());
    }
    return farthest;
}


void Foam::particleShapes::polygon::supportKinks
(
    DynamicList<vector>& ridgeAxes,
    DynamicList<vector>& cornerDirections
) const
{
    cornerDirections.append(edgeNormals_);
}


void Foam::particleShapes::polygon::drawing
(
    pointField& points,
    faceList& faces
) const
{
    points = vertices_;
    faces = faceList(1, face(identity(vertices_.size())));
}


void Foam::particleShapes::polygon::write(Ostream& os) const
{
    List<vector2D> vertices(vertices_.size());
    forAll(vertices_, i)
    {
        vertices[i] = vector2D(vertices_[i].x(), vertices_[i].y());
    }
    os.writeEntry("shape", typeName);
    os.writeEntry("vertices", vertices);
}


// ************************************************************************* //
