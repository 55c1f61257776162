/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "forcedRegions.H"
#include "dlmParticleCloud.H"
#include "syncTools.H"
#include "emptyFvPatch.H"
#include "cyclicPolyPatch.H"
#include "processorPolyPatch.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace
{
    // Sample code for the second cell across a coupled face
    const Foam::label secondLayerSample = -2;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::forcedRegions::forcedRegions(const fvMesh& mesh)
:
    mesh_(mesh),
    relayed_(false)
{
    setMeshGeometry();
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::forcedRegions::setMeshGeometry()
{
    const label nCells = mesh_.nCells();
    const label nBoundaryFaces = mesh_.nBoundaryFaces();
    inside_.setSize(nCells);
    inside_ = false;
    regionOwner_.setSize(nCells);
    regionOwner_ = -1;
    insideOf_.setSize(nCells);
    insideOf_ = -1;
    nextTo_.setSize(nCells);
    nextTo_ = -1;
    leftToFlow_.setSize(nCells);
    leftToFlow_ = 0;
    leftToFlowCells_.clear();
    blendedFaces_.clear();
    blendingSet_ = false;
    for
    (
        labelList* faceList :
        {
            &insideAcross_, &insideSecondLayer_, &nextToAcross_,
            &nextToSecondLayer_, &secondLayerCell_, &secondLayerRelay_
        }
    )
    {
        faceList->setSize(nBoundaryFaces);
        *faceList = -1;
    }
    leftToFlowAcross_.setSize(nBoundaryFaces);
    leftToFlowAcross_ = 0;
    leftToFlowSecondLayer_.setSize(nBoundaryFaces);
    leftToFlowSecondLayer_ = 0;
    secondLayerDelta_.setSize(nBoundaryFaces);
    secondLayerDelta_ = Zero;
    secondLayerAcross_.setSize(nBoundaryFaces);
    secondLayerAcross_ = false;
    coupledDeltas_.clear();
    coupledDeltas_.setSize(mesh_.boundary().size());
    forAll(mesh_.boundary(), patchi)
    {
        if (mesh_.boundary()[patchi].coupled())
        {
            coupledDeltas_.set
            (
                patchi,
                new vectorField(mesh_.boundary()[patchi].delta())
            );
        }
    }

    // The cell behind each boundary face's cell, along the inward normal,
    // and its offset; the offsets of the other side of coupled faces. The
    // cell behind may lie across a cyclic patch of this processor (a
    // processor boundary next to a cyclic one: without it the profile
    // there lost its second sample, which the serial run has), or across
    // another processor face, on a third rank where this rank's subdomain
    // is a cell thick: its value is relayed (exchangeAcross)
    const vectorField& C = mesh_.C();
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    forAll(secondLayerCell_, bFacei)
    {
        const label facei = mesh_.nInternalFaces() + bFacei;
        const label celli = mesh_.faceOwner()[facei];
        const vector inward(-mesh_.faceAreas()[facei]/mag(mesh_.faceAreas()[facei]));
        scalar bestCos = 0.9;
        for (const label facej : mesh_.cells()[celli])
        {
            label cellj = -1;
            label relay = -1;
            vector d(Zero);
            if (mesh_.isInternalFace(facej))
            {
                cellj =
                    mesh_.faceOwner()[facej] == celli
                  ? mesh_.faceNeighbour()[facej]
                  : mesh_.faceOwner()[facej];
                d = C[cellj] - C[celli];
            }
            else
            {
                const label patchj = patches.whichPatch(facej);
                const label localFacej = facej - patches[patchj].start();
                if (isA<cyclicPolyPatch>(patches[patchj]))
                {
                    cellj =
                        refCast<const cyclicPolyPatch>(patches[patchj])
                       .neighbPatch().faceCells()[localFacej];
                    d = coupledDeltas_[patchj][localFacej];
                }
                else if (isA<processorPolyPatch>(patches[patchj]))
                {
                    relay = facej - mesh_.nInternalFaces();
                    d = coupledDeltas_[patchj][localFacej];
                }
            }
            if (cellj < 0 && relay < 0)
            {
                continue;
            }
            const scalar c = (d & inward)/mag(d);
            if (c > bestCos)
            {
                bestCos = c;
                secondLayerCell_[bFacei] = cellj;
                secondLayerRelay_[bFacei] = relay;
                secondLayerDelta_[bFacei] = d;
            }
        }
    }
    syncTools::swapBoundaryFaceList(mesh_, secondLayerDelta_);
    labelList hasSecondLayer(mesh_.nBoundaryFaces());
    forAll(hasSecondLayer, bFacei)
    {
        hasSecondLayer[bFacei] =
            secondLayerCell_[bFacei] >= 0 || secondLayerRelay_[bFacei] >= 0
          ? 1 : 0;
    }
    syncTools::swapBoundaryFaceList(mesh_, hasSecondLayer);
    forAll(hasSecondLayer, bFacei)
    {
        secondLayerAcross_[bFacei] = hasSecondLayer[bFacei] > 0;
    }
    relayed_ = false;
    for (const label relay : secondLayerRelay_)
    {
        relayed_ = relayed_ || relay >= 0;
    }
    reduce(relayed_, orOp<bool>());
}


void Foam::forcedRegions::blendExcessMass()
{
    const dlmParticleCloud& cloud =
        mesh_.lookupObject<dlmParticleCloud>("particles");
    const scalarField& rho = cloud.rho();
    const scalar rhoFluid = cloud.rhoFluid().value();
    const vectorField& C = mesh_.C();
    scalarField fraction(mesh_.nCells(), Zero);

    forAll(cloud.particles(), i)
    {
        const dlmParticle& p = cloud.particles()[i];
        const scalar excess = p.mixtureDensity(rhoFluid) - rhoFluid;
        if (excess <= 0)
        {
            continue;
        }
        const DynamicList<label>& covered = cloud.cells(i);
        const DynamicList<scalar>& fractions = cloud.fractions(i);
        forAll(covered, k)
        {
            fraction[covered[k]] = fractions[k];
        }
        const DynamicList<label>& cells = regionCells_[i];
        forAll(cells, k)
        {
            const label celli = cells[k];
            const scalar b = excess*fraction[celli]/rho[celli];
            regionWeights_[i][k] = b + (1 - b)*regionWeights_[i][k];
            regionArms_[i][k] =
                b*(C[celli] - p.position()) + (1 - b)*regionArms_[i][k];
            regionRigidShares_[i][k] = b + (1 - b)*regionRigidShares_[i][k];
            for
            (
                label s = sampleStarts_[i][k];
                s < sampleStarts_[i][k + 1];
                ++s
            )
            {
                sampleCoeffs_[i][s] *= 1 - b;
            }
        }
        for (const label celli : covered)
        {
            fraction[celli] = 0;
        }
    }
}


void Foam::forcedRegions::findRegions()
{
    forAll(regionCells_, i)
    {
        findRegion(i);
    }
    resolveSharedCells();
}


void Foam::forcedRegions::exchangeAcross
(
    const labelList& cellValues,
    labelList& across,
    labelList& secondLayer
) const
{
    syncTools::swapBoundaryCellList(mesh_, cellValues, across);
    forAll(secondLayer, bFacei)
    {
        if (secondLayerCell_[bFacei] >= 0)
        {
            secondLayer[bFacei] = cellValues[secondLayerCell_[bFacei]];
        }
        else if (secondLayerRelay_[bFacei] >= 0)
        {
            secondLayer[bFacei] = across[secondLayerRelay_[bFacei]];
        }
        else
        {
            secondLayer[bFacei] = -1;
        }
    }
    syncTools::swapBoundaryFaceList(mesh_, secondLayer);
}


void Foam::forcedRegions::findNearDistances()
{
    const dlmParticleCloud& cloud =
        mesh_.lookupObject<dlmParticleCloud>("particles");
    const PtrList<dlmParticle>& particles = cloud.particles();
    const vectorField& C = mesh_.C();

    nearDistance_.setSize(particles.size());
    nearNormal_.setSize(particles.size());
    forAll(particles, i)
    {
        const dlmParticle& p = particles[i];
        const labelUList& cells = cloud.nearCells(i);
        scalarField& distance = nearDistance_[i];
        vectorField& normal = nearNormal_[i];

        const bool fixed = p.motion() == dlmParticle::motionType::fixed;
        const word key
        (
            i < cloud.nParticles()
          ? p.name()
          : word(p.name() + ":image" + Foam::name(i - cloud.nParticles()))
        );
        if (fixed)
        {
            const auto iter = fixedNear_.cfind(key);
            if
            (
                iter.found()
             && iter().position == p.position()
             && iter().orientation == p.orientation()
             && iter().cells == cells
            )
            {
                distance = iter().distance;
                normal = iter().normal;
                continue;
            }
        }

        const tensor Rt(p.R().T());
        distance.setSize(cells.size());
        normal.setSize(cells.size());
        forAll(cells, k)
        {
            distance[k] = p.shape().signedDistance
            (
                Rt & (C[cells[k]] - p.position()),
                normal[k]
            );
        }
        if (fixed)
        {
            fixedNear_.set
            (
                key,
                fixedNear
                {
                    p.position(), p.orientation(), labelList(cells),
                    distance, normal
                }
            );
        }
    }
}


void Foam::forcedRegions::markInsideCells()
{
    const dlmParticleCloud& cloud =
        mesh_.lookupObject<dlmParticleCloud>("particles");
    const PtrList<dlmParticle>& particles = cloud.particles();

    insideOf_ = -1;
    DynamicList<label> insideCells;
    forAll(particles, i)
    {
        const labelUList& cells = cloud.nearCells(i);
        forAll(cells, k)
        {
            if (nearDistance_[i][k] < 0)
            {
                insideOf_[cells[k]] = cloud.source(i);
                insideCells.append(cells[k]);
            }
        }
    }

    exchangeAcross(insideOf_, insideAcross_, insideSecondLayer_);

    // The body next to each fluid cell, across its faces
    auto addBody = [](label& next, const label body)
    {
        if (body >= 0 && next != body)
        {
            next = next == -1 ? body : -2;
        }
    };
    // Only the faces of inside cells can make a neighbour next to a body
    // (a cell listed twice adds its body twice, which changes nothing)
    nextTo_ = -1;
    for (const label celli : insideCells)
    {
        for (const label facei : mesh_.cells()[celli])
        {
            if (mesh_.isInternalFace(facei))
            {
                const label own = mesh_.owner()[facei];
                addBody
                (
                    nextTo_[own == celli ? mesh_.neighbour()[facei] : own],
                    insideOf_[celli]
                );
            }
        }
    }
    const labelUList& faceCells = mesh_.faceOwner();
    forAll(insideAcross_, bFacei)
    {
        addBody
        (
            nextTo_[faceCells[mesh_.nInternalFaces() + bFacei]],
            insideAcross_[bFacei]
        );
    }
    exchangeAcross(nextTo_, nextToAcross_, nextToSecondLayer_);

    leftToFlow_ = 0;
    leftToFlowCells_.clear();
    leftToFlowAcross_ = 0;
    leftToFlowSecondLayer_ = 0;
}


bool Foam::forcedRegions::markLeftToFlow()
{
    labelList forced(mesh_.nCells(), 0);
    for (const DynamicList<label>& cells : regionCells_)
    {
        for (const label celli : cells)
        {
            forced[celli] = 1;
        }
    }
    forAll(leftToFlow_, celli)
    {
        if (insideOf_[celli] < 0 && nextTo_[celli] != -1 && !forced[celli])
        {
            leftToFlow_[celli] = 1;
            leftToFlowCells_.append(celli);
        }
    }
    exchangeAcross(leftToFlow_, leftToFlowAcross_, leftToFlowSecondLayer_);

    bool sampled = false;
    forAll(sampleCells_, i)
    {
        forAll(sampleCells_[i], s)
        {
            sampled =
                sampled
             || sampleLeftToFlow(sampleCells_[i][s], sampleFaces_[i][s]);
        }
    }
    return returnReduce(sampled, orOp<bool>());
}


bool Foam::forcedRegions::sampleUsable
(
    const label body,
    const label celli,
    const labelPair& face
) const
{
    label inside = -1;
    label next = -1;
    if (celli >= 0)
    {
        inside = insideOf_[celli];
        next = nextTo_[celli];
    }
    else
    {
        const fvPatch& fp = mesh_.boundary()[face.first()];
        if (!fp.coupled())
        {
            return true;
        }
        const label bFacei = fp.start() + face.second() - mesh_.nInternalFaces();
        const bool second = celli == secondLayerSample;
        inside = second ? insideSecondLayer_[bFacei] : insideAcross_[bFacei];
        next = second ? nextToSecondLayer_[bFacei] : nextToAcross_[bFacei];
    }
    return inside < 0 && (next == -1 || next == body);
}


bool Foam::forcedRegions::sampleLeftToFlow
(
    const label celli,
    const labelPair& face
) const
{
    if (celli >= 0)
    {
        return leftToFlow_[celli] > 0;
    }
    const fvPatch& fp = mesh_.boundary()[face.first()];
    if (!fp.coupled())
    {
        return false;
    }
    const label bFacei = fp.start() + face.second() - mesh_.nInternalFaces();
    return
        celli == secondLayerSample
      ? leftToFlowSecondLayer_[bFacei] > 0
      : leftToFlowAcross_[bFacei] > 0;
}


void Foam::forcedRegions::findRegion(const label i)
{
    const dlmParticleCloud& cloud =
        mesh_.lookupObject<dlmParticleCloud>("particles");
    const dlmParticle& p = cloud.particles()[i];
    const label body = cloud.source(i);
    const particleShape& shape = p.shape();
    const point& X = p.position();
    const tensor Rt(p.R().T());

    const vectorField& C = mesh_.C();
    const labelUList& owner = mesh_.owner();
    const labelUList& neighbour = mesh_.neighbour();
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();

    DynamicList<label>& cells = regionCells_[i];
    DynamicList<scalar>& weights = regionWeights_[i];
    DynamicList<vector>& arms = regionArms_[i];
    DynamicList<vector>& normals = regionNormals_[i];
    DynamicList<scalar>& rigidShares = regionRigidShares_[i];
    DynamicList<label>& starts = sampleStarts_[i];
    DynamicList<label>& sampleCells = sampleCells_[i];
    DynamicList<labelPair>& sampleFaces = sampleFaces_[i];
    DynamicList<scalar>& sampleCoeffs = sampleCoeffs_[i];
    cells.clear();
    weights.clear();
    arms.clear();
    normals.clear();
    rigidShares.clear();
    starts.clear();
    sampleCells.clear();
    sampleFaces.clear();
    sampleCoeffs.clear();

    // An interface cell's centre lies within a neighbour distance of the
    // surface: it is among the particle's near cells
    const labelUList& candidates = cloud.nearCells(i);
    const scalar cellSizeMax = cloud.cellSizeMax();

    // Which candidates have their centre inside
    const scalarField& distance = nearDistance_[i];
    forAll(candidates, k)
    {
        inside_[candidates[k]] = distance[k] < 0;
    }

    // Neighbours of a cell across its faces: direction, sample, inside
    struct neighbourSample
    {
        vector delta;
        label celli;
        labelPair face;
        bool inside;
    };
    DynamicList<neighbourSample> nbrs(6);

    vector normal;
    forAll(candidates, k)
    {
        const label celli = candidates[k];
        if (inside_[celli])
        {
            cells.append(celli);
            weights.append(1);
            arms.append(C[celli] - X);
            normals.append(Zero);
            rigidShares.append(1);
            starts.append(sampleCells.size());
            continue;
        }

        if (distance[k] >= cellSizeMax)
        {
            continue;
        }

        nbrs.clear();
        bool anyInside = false;
        for (const label facei : mesh_.cells()[celli])
        {
            neighbourSample nbr{Zero, -1, labelPair(-1, -1), false};
            if (mesh_.isInternalFace(facei))
            {
                nbr.celli =
                    owner[facei] == celli ? neighbour[facei] : owner[facei];
                nbr.delta = C[nbr.celli] - C[celli];
            }
            else
            {
                const label patchi = patches.whichPatch(facei);
                const fvPatch& fp = mesh_.boundary()[patchi];
                if (isA<emptyFvPatch>(fp))
                {
                    continue;
                }
                const label localFacei = facei - fp.start();
                nbr.face = labelPair(patchi, localFacei);
                nbr.delta =
                    fp.coupled()
                  ? coupledDeltas_[patchi][localFacei]
                  : fp.Cf()[localFacei] - C[celli];
            }
            if (nbr.celli >= 0)
            {
                nbr.inside = inside_[nbr.celli];
            }
            else if (mesh_.boundary()[nbr.face.first()].coupled())
            {
                nbr.inside =
                    shape.signedDistance
                    (
                        Rt & (C[celli] + nbr.delta - X),
                        normal
                    ) < 0;
            }
            anyInside = anyInside || nbr.inside;
            nbrs.append(nbr);
        }

        if (!anyInside)
        {
            continue;
        }

        // Normal at the surface point nearest to the cell centre
        const vector n(p.R() & nearNormal_[i][k]);

        // One linear profile per grid line from the cell to an inside
        // neighbour, between the surface and the opposite neighbour
        scalar weightSum = 0;
        scalar a = 0;
        vector q(Zero);
        const label start = sampleCells.size();
        for (const neighbourSample& in : nbrs)
        {
            if (!in.inside)
            {
                continue;
            }
            const scalar L = mag(in.delta);
            const vector e(in.delta/L);

            const neighbourSample* out = nullptr;
            scalar cosOut = -0.7;
            for (const neighbourSample& cand : nbrs)
            {
                const scalar c = (e & cand.delta)/mag(cand.delta);
                if
                (
                    !cand.inside
                 && sampleUsable(body, cand.celli, cand.face)
                 && c < cosOut
                )
                {
                    out = &cand;
                    cosOut = c;
                }
            }
            if (!out)
            {
                continue;
            }

            const scalar t =
                shape.surfaceCrossing(Rt & (C[celli] - X), Rt & e, L);
            const scalar Lout = -(e & out->delta);
            const scalar w = sqr(e & n) + SMALL;

            // The next sample out along the line, for a quadratic profile:
            // a cell or face beyond an inner cell, or the cell beyond a
            // coupled face (second layer, exchanged at each correction)
            label out2Cell = -1;
            labelPair out2Face(-1, -1);
            vector delta2(Zero);
            bool quadratic = false;
            if (out->celli >= 0)
            {
                quadratic =
                    nextAlong(out->celli, -e, out2Cell, out2Face, delta2);
            }
            else if (mesh_.boundary()[out->face.first()].coupled())
            {
                const label bFacei =
                    mesh_.boundary()[out->face.first()].start()
                  + out->face.second() - mesh_.nInternalFaces();
                if (secondLayerAcross_[bFacei])
                {
                    out2Cell = secondLayerSample;
                    out2Face = out->face;
                    delta2 = secondLayerDelta_[bFacei];
                    quadratic = true;
                }
            }
            // Two or three fluid cells between surfaces: forced towards
            // each other they would block the gap, so leave the line to the
            // flow
            if (quadratic && !sampleUsable(body, out2Cell, out2Face))
            {
                continue;
            }
            const scalar Lout2 = -(e & delta2);
            // A first sample left to the flow takes the linear profile's
            // weight, at most a half, not the quadratic's, up to 1. A wall
            // half a cell beyond the first sample (a uniform mesh's) gives
            // a linear profile: the margin keeps the round-off of the cell
            // centres, which differs between a mesh and its decomposition,
            // from deciding
            quadratic =
                quadratic && Lout2 > (0.5 + 1e-6)*Lout
             && !sampleLeftToFlow(out->celli, out->face);

            scalar aLine, cOut, cOut2 = 0;
            if (quadratic)
            {
                aLine = Lout*(Lout + Lout2)/((t + Lout)*(t + Lout + Lout2));
                cOut = t*(Lout + Lout2)/((t + Lout)*Lout2);
                cOut2 = -t*Lout/((t + Lout + Lout2)*Lout2);
            }
            else
            {
                aLine = Lout/(t + Lout);
                cOut = 1 - aLine;
            }

            weightSum += w;
            a += w*aLine;
            q += w*aLine*(C[celli] + t*e - X);
            sampleCells.append(out->celli);
            sampleFaces.append(out->face);
            sampleCoeffs.append(w*cOut);
            if (quadratic)
            {
                sampleCells.append(out2Cell);
                sampleFaces.append(out2Face);
                sampleCoeffs.append(w*cOut2);
            }
        }

        if (weightSum > 0)
        {
            cells.append(celli);
            weights.append(a/weightSum);
            arms.append(q/weightSum);
            normals.append(n);
            rigidShares.append(0);
            starts.append(start);
            for (label k = start; k < sampleCoeffs.size(); ++k)
            {
                sampleCoeffs[k] /= weightSum;
            }
        }
        else
        {
            sampleCells.setSize(start);
            sampleFaces.setSize(start);
            sampleCoeffs.setSize(start);
        }
    }
    starts.append(sampleCells.size());

    for (const label celli : candidates)
    {
        inside_[celli] = false;
    }
}


void Foam::forcedRegions::resolveSharedCells()
{
    const dlmParticleCloud& cloud =
        mesh_.lookupObject<dlmParticleCloud>("particles");
    const PtrList<dlmParticle>& particles = cloud.particles();
    const vectorField& C = mesh_.C();

    auto signedDistance = [&](const label i, const label celli)
    {
        const dlmParticle& p = particles[i];
        vector normal;
        return p.shape().signedDistance
        (
            p.R().T() & (C[celli] - p.position()),
            normal
        );
    };

    bool shared = false;
    forAll(particles, i)
    {
        for (const label celli : regionCells_[i])
        {
            label& owner = regionOwner_[celli];
            if (owner < 0)
            {
                owner = i;
            }
            else
            {
                shared = true;
                if (signedDistance(i, celli) < signedDistance(owner, celli))
                {
                    owner = i;
                }
            }
        }
    }

    if (shared)
    {
        forAll(particles, i)
        {
            DynamicList<label>& cells = regionCells_[i];
            DynamicList<scalar>& weights = regionWeights_[i];
            DynamicList<vector>& arms = regionArms_[i];
            DynamicList<vector>& normals = regionNormals_[i];
            DynamicList<scalar>& rigidShares = regionRigidShares_[i];
            DynamicList<label>& starts = sampleStarts_[i];
            DynamicList<label>& sampleCells = sampleCells_[i];
            DynamicList<labelPair>& sampleFaces = sampleFaces_[i];
            DynamicList<scalar>& sampleCoeffs = sampleCoeffs_[i];

            // Compact in place: kept entries only move towards the front
            label nKept = 0;
            label nSamples = 0;
            forAll(cells, k)
            {
                if (regionOwner_[cells[k]] != i)
                {
                    continue;
                }
                const label first = starts[k];
                const label last = starts[k + 1];
                cells[nKept] = cells[k];
                weights[nKept] = weights[k];
                arms[nKept] = arms[k];
                normals[nKept] = normals[k];
                rigidShares[nKept] = rigidShares[k];
                starts[nKept] = nSamples;
                for (label s = first; s < last; ++s)
                {
                    sampleCells[nSamples] = sampleCells[s];
                    sampleFaces[nSamples] = sampleFaces[s];
                    sampleCoeffs[nSamples] = sampleCoeffs[s];
                    ++nSamples;
                }
                ++nKept;
            }
            starts[nKept] = nSamples;
            cells.setSize(nKept);
            weights.setSize(nKept);
            arms.setSize(nKept);
            normals.setSize(nKept);
            rigidShares.setSize(nKept);
            starts.setSize(nKept + 1);
            sampleCells.setSize(nSamples);
            sampleFaces.setSize(nSamples);
            sampleCoeffs.setSize(nSamples);
        }
    }

    // Every shared cell stays in its owner's list: reset through them
    forAll(particles, i)
    {
        for (const label celli : regionCells_[i])
        {
            regionOwner_[celli] = -1;
        }
    }
}


bool Foam::forcedRegions::nextAlong
(
    const label celli,
    const vector& e,
    label& nbrCell,
    labelPair& nbrFace,
    vector& delta
) const
{
    const vectorField& C = mesh_.C();
    scalar bestCos = 0.9;
    bool found = false;
    for (const label facei : mesh_.cells()[celli])
    {
        label cellj = -1;
        labelPair face(-1, -1);
        vector d;
        if (mesh_.isInternalFace(facei))
        {
            cellj =
                mesh_.owner()[facei] == celli
              ? mesh_.neighbour()[facei]
              : mesh_.owner()[facei];
            d = C[cellj] - C[celli];
        }
        else
        {
            const label patchi = mesh_.boundaryMesh().whichPatch(facei);
            const fvPatch& fp = mesh_.boundary()[patchi];
            if (isA<emptyFvPatch>(fp))
            {
                continue;
            }
            face = labelPair(patchi, facei - fp.start());
            d =
                fp.coupled()
              ? coupledDeltas_[patchi][face.second()]
              : fp.Cf()[face.second()] - C[celli];
        }
        const scalar c = (d & e)/mag(d);
        if (c > bestCos)
        {
            bestCos = c;
            nbrCell = cellj;
            nbrFace = face;
            delta = d;
            found = true;
        }
    }
    return found;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::forcedRegions::setBlendingFactor
(
    surfaceScalarField& factor,
    const scalar gapBlending
) const
{
    // Only the faces of the last gaps and of the new ones change, except
    // after a mesh change, which sets every face
    scalarField& internal = factor.primitiveFieldRef();
    surfaceScalarField::Boundary& boundary = factor.boundaryFieldRef();
    const label nInternal = mesh_.nInternalFaces();
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    const auto set = [&](const label facei, const scalar value)
    {
        if (facei < nInternal)
        {
            internal[facei] = value;
            return;
        }
        const label patchi = patches.whichPatch(facei);
        if (boundary[patchi].size())
        {
            boundary[patchi][facei - patches[patchi].start()] = value;
        }
    };

    if (blendingSet_)
    {
        for (const label facei : blendedFaces_)
        {
            set(facei, 1);
        }
    }
    else
    {
        internal = 1;
        boundary = 1;
        blendingSet_ = true;
    }
    blendedFaces_.clear();

    for (const label celli : leftToFlowCells_)
    {
        for (const label facei : mesh_.cells()[celli])
        {
            set(facei, gapBlending);
            blendedFaces_.append(facei);
        }
    }
    forAll(leftToFlowAcross_, bFacei)
    {
        const label facei = nInternal + bFacei;
        if
        (
            leftToFlowAcross_[bFacei]
         && patches[patches.whichPatch(facei)].coupled()
        )
        {
            set(facei, gapBlending);
            blendedFaces_.append(facei);
        }
    }
}


Foam::List<Foam::vectorField>
Foam::forcedRegions::sampledVelocities(const volVectorField& U) const
{
    const vectorField& u = U.primitiveField();

    // Values across coupled faces, fetched once per patch
    PtrList<vectorField> neighbourValues(mesh_.boundary().size());
    // Second-layer values across coupled faces: each side sends the value
    // of the cell behind each of its coupled faces
    vectorField secondLayerU(mesh_.nBoundaryFaces(), Zero);
    vectorField uAcross;
    if (relayed_)
    {
        syncTools::swapBoundaryCellList(mesh_, u, uAcross);
    }
    forAll(secondLayerU, bFacei)
    {
        if (secondLayerCell_[bFacei] >= 0)
        {
            secondLayerU[bFacei] = u[secondLayerCell_[bFacei]];
        }
        else if (secondLayerRelay_[bFacei] >= 0)
        {
            secondLayerU[bFacei] = uAcross[secondLayerRelay_[bFacei]];
        }
    }
    syncTools::swapBoundaryFaceList(mesh_, secondLayerU);

    auto sampleValue = [&](const label i, const label k) -> vector
    {
        const label celli = sampleCells_[i][k];
        if (celli >= 0)
        {
            return u[celli];
        }
        const labelPair& face = sampleFaces_[i][k];
        if (celli == secondLayerSample)
        {
            return secondLayerU
            [
                mesh_.boundary()[face.first()].start() + face.second()
              - mesh_.nInternalFaces()
            ];
        }
        const fvPatchVectorField& pf = U.boundaryField()[face.first()];
        if (pf.coupled())
        {
            if (!neighbourValues.set(face.first()))
            {
                neighbourValues.set
                (
                    face.first(),
                    pf.patchNeighbourField().ptr()
                );
            }
            return neighbourValues[face.first()][face.second()];
        }
        return pf[face.second()];
    };

    // Velocity of the samples of forced cell k of particle i, as weighted
    auto sampledVelocity = [&](const label i, const label k) -> vector
    {
        vector sum(Zero);
        for
        (
            label s = sampleStarts_[i][k];
            s < sampleStarts_[i][k + 1];
            ++s
        )
        {
            sum += sampleCoeffs_[i][s]*sampleValue(i, s);
        }
        return sum;
    };

    List<vectorField> sampled(regionCells_.size());
    forAll(sampled, i)
    {
        sampled[i].setSize(regionCells_[i].size());
        forAll(sampled[i], k)
        {
            sampled[i][k] = sampledVelocity(i, k);
        }
    }
    return sampled;
}


void Foam::forcedRegions::updateMesh()
{
    setMeshGeometry();
    fixedNear_.clear();
    for
    (
        List<DynamicList<label>>* perParticle :
        {&regionCells_, &sampleStarts_, &sampleCells_}
    )
    {
        perParticle->clear();
    }
    regionWeights_.clear();
    regionArms_.clear();
    regionNormals_.clear();
    regionRigidShares_.clear();
    sampleFaces_.clear();
    sampleCoeffs_.clear();
    nearDistance_.clear();
    nearNormal_.clear();
}


Foam::label Foam::forcedRegions::update()
{
    const label nParticles =
        mesh_.lookupObject<dlmParticleCloud>("particles").particles().size();
    regionCells_.setSize(nParticles);
    regionWeights_.setSize(nParticles);
    regionArms_.setSize(nParticles);
    regionNormals_.setSize(nParticles);
    regionRigidShares_.setSize(nParticles);
    sampleStarts_.setSize(nParticles);
    sampleCells_.setSize(nParticles);
    sampleFaces_.setSize(nParticles);
    sampleCoeffs_.setSize(nParticles);

    // A profile whose first sample is a cell left to the flow is linear;
    // those cells are known once the regions are, which are then found
    // again where one is sampled (the same cells, other weights)
    findNearDistances();
    markInsideCells();
    label nSearches = 1;
    findRegions();
    if (markLeftToFlow())
    {
        findRegions();
        ++nSearches;
    }
    blendExcessMass();
    return nSearches;
}


// ************************************************************************* //
