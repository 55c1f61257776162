/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "periodicImages.H"
#include "cyclicPolyPatch.H"
#include "SubList.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::periodicImages::periodicImages(const fvMesh& mesh)
:
    mesh_(mesh),
    translations_(translations(mesh)),
    nParticles_(0),
    wraps_(false)
{}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::List<Foam::vector> Foam::periodicImages::translations(const fvMesh& mesh)
{
    DynamicList<vector> translations;
    for (const polyPatch& patch : mesh.boundaryMesh())
    {
        const cyclicPolyPatch* cyclicPtr = isA<cyclicPolyPatch>(patch);
        if (!cyclicPtr || !cyclicPtr->owner())
        {
            continue;
        }
        // Known where the pair (or a processor part of it) has faces
        vector translation(Zero);
        if (cyclicPtr->separated() && cyclicPtr->separation().size())
        {
            translation = cyclicPtr->separation()[0];
        }
        reduce(translation, maxMagSqrOp<vector>());
        if (magSqr(translation) > 0)
        {
            translations.append(translation);
        }
    }
    return translations;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::periodicImages::add(PtrList<dlmParticle>& particles)
{
    nParticles_ = particles.size();

    // Every combination of -1, 0 and 1 times each translation
    DynamicList<vector> offsets(1, Zero);
    DynamicList<labelVector> periods(1, labelVector::zero);
    forAll(translations_, d)
    {
        const label n = offsets.size();
        for (label k = 0; k < n; ++k)
        {
            for (const label sign : {1, -1})
            {
                offsets.append(offsets[k] + sign*translations_[d]);
                labelVector shifted(periods[k]);
                shifted[d] += sign;
                periods.append(shifted);
            }
        }
    }

    const boundBox& bounds = mesh_.bounds();
    DynamicList<label> sources;
    DynamicList<vector> sourceOffsets;
    DynamicList<labelVector> sourcePeriods;
    wraps_ = false;
    for (label i = 0; i < nParticles_; ++i)
    {
        const dlmParticle& p = particles[i];
        const scalar Rb = p.shape().boundingRadius();

        // A free particle, or a prescribed particle moving across the
        // periodic boundaries, needs each image at some time
        bool movesAcross = p.isFree() && periodic();
        if (p.motion() == dlmParticle::motionType::prescribed)
        {
            for (const vector& t : translations_)
            {
                movesAcross = movesAcross || mag(p.velocity() & t) > 0;
            }
        }
        wraps_ = wraps_ || movesAcross;

        for (label k = 1; k < offsets.size(); ++k)
        {
            // Images that only touch the mesh (a packing touching the
            // periodic faces) are left out
            const point X(p.position() + offsets[k]);
            const scalar touch = 1e-9*Rb;
            bool inside = true;
            for (direction d = 0; d < vector::nComponents; ++d)
            {
                inside = inside
                 && X[d] - Rb < bounds.max()[d] - touch
                 && X[d] + Rb > bounds.min()[d] + touch;
            }
            if (!inside && !movesAcross)
            {
                continue;
            }
            particles.append
            (
                new dlmParticle(p, p.name() + "_image" + Foam::name(k), X)
            );
            sources.append(i);
            sourceOffsets.append(offsets[k]);
            sourcePeriods.append(periods[k]);
        }
    }
    source_.transfer(sources);
    offset_.transfer(sourceOffsets);
    periods_.transfer(sourcePeriods);

    if (size())
    {
        Info<< "Periodic images: " << size() << endl;
    }
}


void Foam::periodicImages::wrap(PtrList<dlmParticle>& particles) const
{
    if (!wraps_)
    {
        return;
    }

    // Each translation pointing from the mesh's low bounds to its high
    // ones: a centroid inside has 0 <= (X - min).t/|t|^2 < 1
    const boundBox& bounds = mesh_.bounds();
    List<vector> translations(translations_);
    for (vector& t : translations)
    {
        if ((bounds.span() & t) < 0)
        {
            t = -t;
        }
    }

    for (label i = 0; i < nParticles_; ++i)
    {
        const dlmParticle& p = particles[i];
        if (p.motion() == dlmParticle::motionType::fixed)
        {
            continue;
        }
        vector shift(Zero);
        for (const vector& t : translations)
        {
            shift -=
                std::floor(((p.position() - bounds.min()) & t)/magSqr(t))*t;
        }
        if (magSqr(shift) > 0)
        {
            particles[i].setPosition(p.position() + shift);
        }
    }
}


void Foam::periodicImages::follow(PtrList<dlmParticle>& particles) const
{
    forAll(source_, k)
    {
        particles[nParticles_ + k].followSource
        (
            particles[source_[k]],
            offset_[k]
        );
    }
}


void Foam::periodicImages::reduceSums
(
    scalarList& sums,
    const label nSums
) const
{
    if (source_.empty())
    {
        Pstream::listCombineGather(sums, plusEqOp<scalar>());
        Pstream::listCombineScatter(sums);
        return;
    }

    forAll(source_, k)
    {
        const scalar* image = &sums[nSums*(nParticles_ + k)];
        scalar* body = &sums[nSums*source_[k]];
        for (label n = 0; n < nSums; ++n)
        {
            body[n] += image[n];
        }
    }

    scalarList particleSums(SubList<scalar>(sums, nSums*nParticles_));
    Pstream::listCombineGather(particleSums, plusEqOp<scalar>());
    Pstream::listCombineScatter(particleSums);
    SubList<scalar>(sums, particleSums.size()) = particleSums;

    forAll(source_, k)
    {
        const scalar* body = &sums[nSums*source_[k]];
        scalar* image = &sums[nSums*(nParticles_ + k)];
        for (label n = 0; n < nSums; ++n)
        {
            image[n] = body[n];
        }
    }
}


void Foam::periodicImages::removeWithSources(labelList& oldToNew) const
{
    forAll(source_, k)
    {
        if (oldToNew[source_[k]] < 0)
        {
            oldToNew[nParticles_ + k] = -1;
        }
    }
}


void Foam::periodicImages::renumber(const labelList& oldToNew)
{
    label nKept = 0;
    for (label i = 0; i < nParticles_; ++i)
    {
        if (oldToNew[i] >= 0)
        {
            ++nKept;
        }
    }

    label nImagesKept = 0;
    forAll(source_, k)
    {
        if (oldToNew[nParticles_ + k] >= 0)
        {
            source_[nImagesKept] = oldToNew[source_[k]];
            offset_[nImagesKept] = offset_[k];
            periods_[nImagesKept] = periods_[k];
            ++nImagesKept;
        }
    }
    source_.resize(nImagesKept);
    offset_.resize(nImagesKept);
    periods_.resize(nImagesKept);
    nParticles_ = nKept;
}


// ************************************************************************* //
