/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "triSurfaceShape.H"
#include "surfaceFile.H"
#include "triSurfaceTools.H"
#include "HashTable.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace particleShapes
{
    defineTypeNameAndDebug(triSurfaceShape, 0);
    addToRunTimeSelectionTable(particleShape, triSurfaceShape, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// Unit directions, each once up to sign when signed is false: more than
// limit of them gives none (a finely tessellated surface has no few kinks)
void appendDistinct
(
    DynamicList<vector>& directions,
    const vector& d,
    const bool signedDirection
)
{
    for (const vector& e : directions)
    {
        const scalar cosine = e & d;
        if (cosine > 1 - 1e-10 || (!signedDirection && cosine < -1 + 1e-10))
        {
            return;
        }
    }
    directions.append(d);
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

std::shared_ptr<const Foam::particleShapes::triSurfaceShape::geometry>
Foam::particleShapes::triSurfaceShape::load(const dictionary& dict)
{
    fileName file(dict.get<fileName>("file"));
    file.expand();
    if (!file.isAbsolute())
    {
        file = surfaceFile::caseDirectory()/file;
    }
    const scalar scale = dict.getOrDefault<scalar>("scale", 1);

    // Shared by the particles that read the same file at the same scale,
    // for as long as one of them lives
    static HashTable<std::weak_ptr<const geometry>, string, string::hash>
        loaded;
    const string key(file + " " + Foam::name(scale));
    const auto found = loaded.cfind(key);
    if (found.found())
    {
        std::shared_ptr<const geometry> shared(found().lock());
        if (shared)
        {
            return shared;
        }
    }

    autoPtr<triSurface> surf
    (
        surfaceFile::read
        (
            dict,
            surfaceFile::caseDirectory(),
            "Particle " + dict.dictName()
        )
    );
    std::shared_ptr<const geometry> result(analyse(*surf, dict, file));
    loaded.set(key, result);
    return result;
}


std::shared_ptr<const Foam::particleShapes::triSurfaceShape::geometry>
Foam::particleShapes::triSurfaceShape::analyse
(
    const triSurface& surf,
    const dictionary& dict,
    const fileName& file
)
{
    const word& name = dict.dictName();
    const pointField& points = surf.localPoints();
    const List<labelledTri>& faces = surf.localFaces();
    const edgeList& edges = surf.edges();
    const labelListList& edgeFaces = surf.edgeFaces();

    // Closed, a manifold, consistently oriented: the edge where each
    // fails first is where to look
    label nOpen = 0, nShared = 0, nMisoriented = 0;
    point atOpen(Zero), atShared(Zero), atMisoriented(Zero);
    forAll(edges, edgei)
    {
        const labelList& ef = edgeFaces[edgei];
        const point middle(edges[edgei].centre(points));
        if (ef.size() < 2)
        {
            atOpen = nOpen++ ? atOpen : middle;
        }
        else if (ef.size() > 2)
        {
            atShared = nShared++ ? atShared : middle;
        }
        else if
        (
            faces[ef[0]].edgeDirection(edges[edgei])
         == faces[ef[1]].edgeDirection(edges[edgei])
        )
        {
            atMisoriented = nMisoriented++ ? atMisoriented : middle;
        }
    }
    if (nOpen)
    {
        FatalIOErrorInFunction(dict)
            << "Particle " << name << ": the surface " << file << " is not"
            << " closed: " << nOpen << " of its edges are on one triangle"
            << " only, e.g. at " << atOpen << nl
            << "A particle's surface must enclose its solid (surfaceCheck"
            << " lists the open edges)." << exit(FatalIOError);
    }
    if (nShared)
    {
        FatalIOErrorInFunction(dict)
            << "Particle " << name << ": the surface " << file << " is not a"
            << " manifold: " << nShared << " of its edges are on more than"
            << " two triangles, e.g. at " << atShared << exit(FatalIOError);
    }
    if (nMisoriented)
    {
        FatalIOErrorInFunction(dict)
            << "Particle " << name << ": the triangles of the surface "
            << file << " are not consistently oriented: " << nMisoriented
            << " edges are traversed the same way by both their triangles,"
            << " e.g. at " << atMisoriented << nl
            << "Orient them (OpenFOAM's surfaceOrient) and check with"
            << " surfaceCheck." << exit(FatalIOError);
    }

    // Six times the signed volume, from the tetrahedra between the origin
    // and each triangle
    scalar volume6 = 0;
    vector moment24(Zero);
    for (const labelledTri& f : faces)
    {
        const point& a = points[f[0]];
        const point& b = points[f[1]];
        const point& c = points[f[2]];
        const scalar v6 = a & (b ^ c);
        volume6 += v6;
        moment24 += v6*(a + b + c);
    }
    const boundBox bounds(points);
    if (mag(volume6) <= 1e-12*6*bounds.volume())
    {
        FatalIOErrorInFunction(dict)
            << "Particle " << name << ": the surface " << file
            << " encloses no volume" << exit(FatalIOError);
    }

    List<labelledTri> oriented(faces);
    if (volume6 < 0)
    {
        WarningInFunction
            << "Particle " << name << ": the triangles of " << file
            << " face inwards: turned outwards" << endl;
        for (labelledTri& f : oriented)
        {
            f = labelledTri(f[0], f[2], f[1], f.region());
        }
    }
    const point centroid(moment24/(4*volume6));

    auto result = std::make_shared<geometry>();
    geometry& g = *result;
    g.surface = triSurface(oriented, surf.patches(), points - centroid);
    const pointField& body = g.surface.points();

    // Volume and second moments about the centroid
    g.volume = 0;
    symmTensor second(Zero);
    for (const labelledTri& f : g.surface)
    {
        const point& a = body[f[0]];
        const point& b = body[f[1]];
        const point& c = body[f[2]];
        const scalar v = (a & (b ^ c))/6;
        const vector s(a + b + c);
        g.volume += v;
        second += v/20*(sqr(a) + sqr(b) + sqr(c) + sqr(s));
    }
    g.inertia = tr(second)*symmTensor::I - second;
    g.boundingRadius = max(mag(body));
    g.search.reset(new triSurfaceSearch(g.surface));

    // Convex: one shell (flood fill over shared edges) with no concave
    // edge (the far corner of each edge's second triangle below the
    // first's plane)
    const scalar tol = 1e-9*g.boundingRadius;
    const labelListList& faceFaces = g.surface.faceFaces();
    const labelListList& bodyEdgeFaces = g.surface.edgeFaces();
    const edgeList& bodyEdges = g.surface.edges();
    const pointField& local = g.surface.localPoints();
    const List<labelledTri>& localFaces = g.surface.localFaces();
    boolList reached(g.surface.size(), false);
    DynamicList<label> front({0});
    reached[0] = true;
    label nReached = 1;
    while (front.size())
    {
        const label facei = front.remove();
        for (const label nbr : faceFaces[facei])
        {
            if (!reached[nbr])
            {
                reached[nbr] = true;
                ++nReached;
                front.append(nbr);
            }
        }
    }
    g.convex = nReached == g.surface.size();

    vectorField normals(localFaces.size());
    forAll(localFaces, facei)
    {
        const vector area(localFaces[facei].areaNormal(local));
        normals[facei] =
            mag(area) > SMALL*sqr(g.boundingRadius)
          ? area/mag(area) : vector::zero;
    }
    DynamicList<vector> corners, ridges;
    forAll(bodyEdges, edgei)
    {
        const edge& e = bodyEdges[edgei];
        const labelList& ef = bodyEdgeFaces[edgei];
        const labelledTri& other = localFaces[ef[1]];
        label far = other[0];
        for (const label pointi : other)
        {
            if (!e.found(pointi))
            {
                far = pointi;
            }
        }
        if (((local[far] - local[e.first()]) & normals[ef[0]]) > tol)
        {
            g.convex = false;
        }
        if ((normals[ef[0]] & normals[ef[1]]) < 1 - 1e-10)
        {
            appendDistinct(ridges, e.unitVec(local), false);
        }
    }
    for (const vector& n : normals)
    {
        if (n != vector::zero)
        {
            appendDistinct(corners, n, true);
        }
    }
    g.pointNeighbours.setSize(local.size());
    const labelListList& pointEdges = g.surface.pointEdges();
    forAll(pointEdges, pointi)
    {
        for (const label edgei : pointEdges[pointi])
        {
            g.pointNeighbours[pointi].append
            (
                bodyEdges[edgei].otherVertex(pointi)
            );
        }
    }
    if (g.convex && corners.size() <= 64 && ridges.size() <= 16)
    {
        g.cornerDirections.transfer(corners);
        g.ridgeAxes.transfer(ridges);
    }

    Info<< "Particle " << name << ": " << g.surface.size()
        << " triangles from " << file << ", volume " << g.volume
        << (g.convex ? ", convex" : ", not convex") << endl;
    return result;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleShapes::triSurfaceShape::triSurfaceShape(const dictionary& dict)
:
    file_(dict.get<fileName>("file")),
    scale_(dict.getOrDefault<scalar>("scale", 1)),
    geometry_(load(dict)),
    lastSupport_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::particleShapes::triSurfaceShape::typeKeywords()
{
    return wordList({"file", "scale"});
}


Foam::wordList Foam::particleShapes::triSurfaceShape::keywords() const
{
    return typeKeywords();
}


Foam::label Foam::particleShapes::triSurfaceShape::nDimensions() const
{
    return 3;
}


Foam::scalar Foam::particleShapes::triSurfaceShape::boundingRadius() const
{
    return geometry_->boundingRadius;
}


bool Foam::particleShapes::triSurfaceShape::convex() const
{
    return geometry_->convex;
}


Foam::scalar Foam::particleShapes::triSurfaceShape::volume() const
{
    return geometry_->volume;
}


Foam::symmTensor
Foam::particleShapes::triSurfaceShape::inertiaPerUnitDensity() const
{
    return geometry_->inertia;
}


Foam::scalar Foam::particleShapes::triSurfaceShape::signedDistance
(
    const vector& r,
    vector& normal
) const
{
    const geometry& g = *geometry_;

    // The surface is within |r| + boundingRadius of any point
    const pointIndexHit hit
    (
        g.search->tree().findNearest
        (
            r,
            sqr(1.01*(mag(r) + g.boundingRadius))
        )
    );
    const vector d(r - hit.hitPoint());
    const scalar distance = mag(d);
    const bool inside =
        triSurfaceTools::surfaceSide(g.surface, r, hit.index())
     == triSurfaceTools::INSIDE;

    if (distance > 1e-12*g.boundingRadius)
    {
        normal = inside ? -d/distance : d/distance;
    }
    else
    {
        normal = g.surface[hit.index()].unitNormal(g.surface.points());
    }
    return inside ? -distance : distance;
}


Foam::scalar Foam::particleShapes::triSurfaceShape::support
(
    const vector& u
) const
{
    const geometry& g = *geometry_;
    const pointField& points = g.surface.localPoints();
    if (!g.convex)
    {
        scalar extent = -GREAT;
        for (const point& p : points)
        {
            extent = max(extent, p & u);
        }
        return extent;
    }

    // Uphill along the edges from the last search's end
    label best = lastSupport_;
    scalar extent = points[best] & u;
    bool moved = true;
    while (moved)
    {
        moved = false;
        for (const label nbr : g.pointNeighbours[best])
        {
            const scalar reach = points[nbr] & u;
            if (reach > extent)
            {
                extent = reach;
                best = nbr;
                moved = true;
            }
        }
    }
    lastSupport_ = best;
    return extent;
}


void Foam::particleShapes::triSurfaceShape::supportKinks
(
    DynamicList<vector>& ridgeAxes,
    DynamicList<vector>& cornerDirections
) const
{
    ridgeAxes.append(geometry_->ridgeAxes);
    cornerDirections.append(geometry_->cornerDirections);
}


bool Foam::particleShapes::triSurfaceShape::planeCut
(
    const vector& n,
    const scalar distance,
    scalar& volume,
    vector& centroid,
    scalar& sectionArea
) const
{
    volume = 0;
    centroid = Zero;
    sectionArea = 0;
    if (support(n) <= distance)
    {
        return true;
    }

    // Each triangle's part beyond the plane: the volume and centroid of
    // the tetrahedra from a point on the plane, the section from the area
    // vectors
    const point apex(distance*n);
    const triSurface& surf = geometry_->surface;
    const pointField& points = surf.points();
    vector moment(Zero);
    vector areaSum(Zero);
    for (const labelledTri& f : surf)
    {
        const FixedList<point, 3> triangle
        ({
            points[f[0]], points[f[1]], points[f[2]]
        });
        addFaceBeyondPlane
        (
            triangle.cdata(), 3, n, distance, volume, moment, areaSum
        );
    }
    if (volume > 0)
    {
        centroid = cutCentroid(apex, moment, volume, boundingRadius());
        sectionArea = areaSum & n;
    }
    else
    {
        volume = 0;
    }
    return true;
}


void Foam::particleShapes::triSurfaceShape::drawing
(
    pointField& points,
    faceList& faces
) const
{
    const triSurface& surf = geometry_->surface;
    points = surf.points();
    faces.setSize(surf.size());
    forAll(surf, facei)
    {
        faces[facei] = surf[facei].triFaceFace();
    }
}


void Foam::particleShapes::triSurfaceShape::write(Ostream& os) const
{
    os.writeEntry("shape", typeName);
    os.writeEntry("file", file_);
    os.writeEntry("scale", scale_);
}


// ************************************************************************* //
