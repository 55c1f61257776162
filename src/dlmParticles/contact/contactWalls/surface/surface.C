/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "surface.H"
#include "surfaceFile.H"
#include "polyMesh.H"
#include "Time.H"
#include "EdgeMap.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace contactWalls
{
    defineTypeNameAndDebug(surface, 0);
    addToRunTimeSelectionTable(contactWall, surface, dictionary);
}
}

namespace
{
    //- Normals within this of parallel are coplanar faces
    const Foam::scalar coplanarTol = 1e-6;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::contactWalls::surface::analyse()
{
    const triSurface& surf = *surface_;
    const pointField& points = surf.points();

    EdgeMap<labelList> edgeFaces;
    forAll(surf, facei)
    {
        for (label k = 0; k < 3; ++k)
        {
            edgeFaces(surf[facei].faceEdge(k)).append(facei);
        }
    }

    rimEdge_.setSize(3*surf.size());
    rimPoint_.setSize(points.size(), false);
    forAll(surf, facei)
    {
        for (label k = 0; k < 3; ++k)
        {
            const edge e(surf[facei].faceEdge(k));
            rimEdge_[3*facei + k] = edgeFaces[e].size() == 1;
            if (rimEdge_[3*facei + k])
            {
                rimPoint_[e.first()] = true;
                rimPoint_[e.second()] = true;
            }
        }
    }

    // Flood coplanar neighbours into facets
    facet_.setSize(surf.size(), -1);
    label nFacets = 0;
    forAll(surf, seed)
    {
        if (facet_[seed] >= 0)
        {
            continue;
        }
        const vector n(surf[seed].unitNormal(points));
        DynamicList<label> front({seed});
        facet_[seed] = nFacets;
        while (front.size())
        {
            const label facei = front.remove();
            for (label k = 0; k < 3; ++k)
            {
                for (const label nbr : edgeFaces[surf[facei].faceEdge(k)])
                {
                    if
                    (
                        facet_[nbr] < 0
                     && mag(surf[nbr].unitNormal(points) & n) > 1 - coplanarTol
                    )
                    {
                        facet_[nbr] = nFacets;
                        front.append(nbr);
                    }
                }
            }
        }
        ++nFacets;
    }

    search_.reset(new triSurfaceSearch(surf));
}


void Foam::contactWalls::surface::setSurface(autoPtr<triSurface>&& surf)
{
    surface_ = std::move(surf);
    analyse();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactWalls::surface::surface
(
    const dictionary& dict,
    const polyMesh& mesh
)
:
    contactWall(dict)
{
    setSurface
    (
        surfaceFile::read
        (
            dict,
            mesh.time().constantPath()/"triSurface",
            "Wall " + name()
        )
    );
    Info<< "Contact wall " << name() << ": " << surface_->size()
        << " faces from " << dict.get<fileName>("file") << endl;
}


Foam::contactWalls::surface::surface
(
    const dictionary& dict,
    const bool meshWall
)
:
    contactWall(dict, meshWall)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::contactWalls::surface::typeKeywords()
{
    wordList words(contactWall::typeKeywords());
    words.append(wordList({"file", "scale"}));
    return words;
}


Foam::wordList Foam::contactWalls::surface::keywords() const
{
    return typeKeywords();
}


void Foam::contactWalls::surface::near
(
    const point& X,
    const scalar reach,
    DynamicList<label>& features
) const
{
    features.append(search_->tree().findSphere(X, sqr(reach)));
}


void Foam::contactWalls::surface::contacts
(
    const point& X,
    const scalar R,
    const labelUList& features,
    DynamicList<wallContact>& found
) const
{
    const triSurface& surf = *surface_;
    const pointField& points = surf.points();
    const scalar mergeTol = 1e-6*R;

    // Contacts with faces, then with rims; triangles' normals alongside
    DynamicList<wallContact> faceHits;
    DynamicList<vector> faceNormals;
    DynamicList<wallContact> rimHits;
    DynamicList<vector> rimNormals;

    for (const label facei : features)
    {
        const triPointRef tri(surf[facei].tri(points));
        label nearType, nearLabel;
        const pointHit hit(tri.nearestPointClassify(X, nearType, nearLabel));
        const vector d(X - hit.rawPoint());
        const scalar distance = mag(d);
        if (distance >= R)
        {
            continue;
        }
        const vector n(tri.unitNormal());

        wallContact c;
        c.location = hit.rawPoint();
        c.distance = distance;
        if (distance < VSMALL)
        {
            // The centroid on the surface: the face's normal stands for the
            // unknown side, so that the contact (an overlap of R, refused
            // at the start) is not lost
            c.normal = n;
            c.feature = facet_[facei];
            faceHits.append(c);
            faceNormals.append(n);
            continue;
        }
        c.normal = d/distance;

        if
        (
            nearType == triPointRef::NONE
         || mag(d & n) > (1 - coplanarTol)*distance
        )
        {
            c.feature = facet_[facei];
            faceHits.append(c);
            faceNormals.append(n);
        }
        else if
        (
            nearType == triPointRef::EDGE
          ? rimEdge_[3*facei + nearLabel]
          : rimPoint_[surf[facei][nearLabel]]
        )
        {
            c.feature = -1 - facei;
            rimHits.append(c);
            rimNormals.append(n);
        }
    }

    // One contact per facet, at its nearest point: faces of the facet next
    // to the one under the centroid pass the normal test when the centroid
    // is within round-off of their edge or corner, at a point apart from it
    const label start = found.size();
    for (const wallContact& c : faceHits)
    {
        bool seen = false;
        for (label i = start; i < found.size() && !seen; ++i)
        {
            if (found[i].feature == c.feature)
            {
                seen = true;
                if (c.distance < found[i].distance)
                {
                    found[i] = c;
                }
            }
        }
        if (!seen)
        {
            found.append(c);
        }
    }

    // Neighbouring rim edges give the same point once
    auto merged = [&](const wallContact& c)
    {
        for (label i = start; i < found.size(); ++i)
        {
            if (mag(found[i].location - c.location) < mergeTol)
            {
                return true;
            }
        }
        return false;
    };
    forAll(rimHits, hiti)
    {
        bool onTouchedPlane = false;
        for (const vector& n : faceNormals)
        {
            onTouchedPlane =
                onTouchedPlane || mag(n & rimNormals[hiti]) > 1 - coplanarTol;
        }
        if (!onTouchedPlane && !merged(rimHits[hiti]))
        {
            found.append(rimHits[hiti]);
        }
    }
}


// ************************************************************************* //
