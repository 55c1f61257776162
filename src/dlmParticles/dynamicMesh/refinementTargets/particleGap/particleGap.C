/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "particleGap.H"
#include "dlmParticleCloud.H"
#include "wallPolyPatch.H"
#include "indexedOctree.H"
#include "treeDataFace.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace refinementTargets
{
    defineTypeNameAndDebug(particleGap, 0);
    addToRunTimeSelectionTable(refinementTarget, particleGap, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::refinementTargets::particleGap::particleGap(const dictionary& dict)
:
    refinementTarget(dict),
    cells_(dict.getCheckOrDefault<scalar>("cells", 4, scalarMinMax::ge(0))),
    walls_(dict.getOrDefault<bool>("walls", true))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::refinementTargets::particleGap::typeKeywords()
{
    wordList known(refinementTarget::typeKeywords());
    known.append(wordList({"cells", "walls"}));
    return known;
}


Foam::wordList Foam::refinementTargets::particleGap::keywords() const
{
    return typeKeywords();
}


void Foam::refinementTargets::particleGap::mark
(
    const dlmParticleCloud& cloud,
    const labelList& cellLevel,
    const scalar lookAhead,
    const bool keep,
    labelList& targetLevel
) const
{
    const fvMesh& mesh = cloud.mesh();
    const vectorField& C = mesh.C();
    const PtrList<dlmParticle>& particles = cloud.particles();

    const scalar widestGap = searchMargin(cloud, cellLevel, cells_, keep);

    // Whether cell celli lies within the gap's width of the surface of
    // particle p (moving by motion until the next update)
    auto inGap = [&](const label celli, const dlmParticle& p, const scalar motion)
    {
        return
            surfaceDistance(p, C[celli]) - reach(cloud, celli, keep)
         <= bandWidth(cloud, cellLevel, cells_, celli) + motion;
    };

    DynamicList<label> nearCells;

    // Pairs of particles
    forAll(particles, i)
    {
        const dlmParticle& pi = particles[i];
        const scalar motioni = pi.surfaceSpeed()*lookAhead;
        for (label j = i + 1; j < particles.size(); ++j)
        {
            const dlmParticle& pj = particles[j];
            const scalar motionj = pj.surfaceSpeed()*lookAhead;
            const scalar gapBound =
                mag(pj.position() - pi.position())
              - pi.shape().boundingRadius() - pj.shape().boundingRadius();
            if (gapBound > 2*widestGap + motioni + motionj)
            {
                continue;
            }

            // The cells near both particles
            const scalar marginI =
                pi.shape().boundingRadius() + widestGap + motioni;
            const scalar marginJ =
                pj.shape().boundingRadius() + widestGap + motionj;
            boundBox both
            (
                pi.position() - marginI*vector::one,
                pi.position() + marginI*vector::one
            );
            both.min() = max(both.min(), pj.position() - marginJ*vector::one);
            both.max() = min(both.max(), pj.position() + marginJ*vector::one);
            if (!both.valid())
            {
                continue;
            }
            nearCells.clear();
            cloud.findCells(both, nearCells);
            for (const label celli : nearCells)
            {
                if
                (
                    targetLevel[celli] < level()
                 && inGap(celli, pi, motioni)
                 && inGap(celli, pj, motionj)
                )
                {
                    targetLevel[celli] = level();
                }
            }
        }
    }

    if (!walls_)
    {
        return;
    }

    // Particles and wall patches
    DynamicList<label> wallFaces;
    for (const polyPatch& patch : mesh.boundaryMesh())
    {
        if (isA<wallPolyPatch>(patch))
        {
            wallFaces.append(identity(patch.size(), patch.start()));
        }
    }
    if (wallFaces.empty())
    {
        return;
    }

    treeBoundBox wallBox(mesh.points());
    wallBox.inflate(1e-4);
    const indexedOctree<treeDataFace> wallTree
    (
        treeDataFace(false, mesh, wallFaces),
        wallBox,
        8,
        10,
        3.0
    );

    for (const dlmParticle& p : particles)
    {
        const scalar motion = p.surfaceSpeed()*lookAhead;
        const scalar margin = p.shape().boundingRadius() + widestGap + motion;
        if (!wallTree.findNearest(p.position(), sqr(margin + widestGap)).hit())
        {
            continue;
        }
        findCellsNear(cloud, p.position(), margin, nearCells);
        for (const label celli : nearCells)
        {
            if (targetLevel[celli] >= level() || !inGap(celli, p, motion))
            {
                continue;
            }
            const scalar width =
                bandWidth(cloud, cellLevel, cells_, celli)
              + reach(cloud, celli, keep);
            if (wallTree.findNearest(C[celli], sqr(width)).hit())
            {
                targetLevel[celli] = level();
            }
        }
    }
}


// ************************************************************************* //
