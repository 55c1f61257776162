/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "particleContact.H"
#include "overlapGeometry.H"
#include "dlmParticleCloud.H"
#include "mathematicalConstants.H"
#include "checkKeywords.H"
#include "wallPolyPatch.H"
#include "IOdictionary.H"

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::particleContact::materialIndex(const word& name)
{
    const label index = materials_.find(name);
    if (index >= 0)
    {
        return index;
    }
    materials_.append(name);
    return materials_.size() - 1;
}


void Foam::particleContact::readLaws()
{
    const PtrList<dlmParticle>& particles = cloud_.particles();
    // Particles' materials come first
    const label nParticleMaterials =
        particleMaterial_.empty() ? 0 : max(particleMaterial_) + 1;
    const label nM = materials_.size();
    materialLaw_.setSize(nM*nM, noLaw);

    const dictionary& pairsDict = dict_.subDict("pairs");
    const label nDims = cloud_.twoD() ? 2 : 3;

    for (const entry& e : pairsDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(pairsDict)
                << "Entry '" << e.keyword() << "' of 'pairs' is not a"
                << " dictionary" << exit(FatalIOError);
        }
        const dictionary& pairDict = e.dict();
        const Pair<word> names(pairDict.get<Pair<word>>("materials"));
        const label a = materials_.find(names.first());
        const label b = materials_.find(names.second());
        if (a < 0 || b < 0)
        {
            // No particle or wall of this material: nothing to do
            continue;
        }

        if (pairDict.get<word>("law") == "none")
        {
            checkKeywords
            (
                pairDict,
                wordHashSet(noLawKeywords()),
                "for contact pair " + e.keyword()
            );
            law(a, b) = noContact;
            law(b, a) = noContact;
            Info<< "Contact pair " << e.keyword() << " (" << names.first()
                << ", " << names.second() << "): none (they pass through each"
                << " other)" << endl;
            continue;
        }

        // Reference contact of the pair's mean particles, for contact times
        scalar mass = 0;
        scalar radius = 0;
        label n = 0;
        forAll(particles, i)
        {
            if (particleMaterial_[i] == a || particleMaterial_[i] == b)
            {
                mass += particles[i].density()*particles[i].shape().volume();
                radius += particles[i].shape().boundingRadius();
                ++n;
            }
        }
        contactLaw::reference ref{mass/max(n, 1), radius/max(n, 1)};
        const bool withWall = a >= nParticleMaterials || b >= nParticleMaterials;
        if (!withWall)
        {
            ref.mass /= 2;
            ref.radius /= 2;
        }

        laws_.append(contactLaw::New(pairDict, nDims, ref));
        const contactLaw& newLaw = laws_.last();

        checkKeywords
        (
            pairDict,
            wordHashSet(newLaw.keywords()),
            "for contact pair " + e.keyword()
        );

        law(a, b) = laws_.size() - 1;
        law(b, a) = laws_.size() - 1;

        Info<< "Contact pair " << e.keyword() << " (" << names.first() << ", "
            << names.second() << "): " << pairDict.get<word>("law")
            << ", restitution " << newLaw.restitution() << " (damping beta "
            << newLaw.beta() << "), friction " << newLaw.friction() << " ("
            << contactLaw::tangentialTypeNames[newLaw.tangential()]
            << "); collision of the mean particles at 1 m/s lasts "
            << newLaw.contactTime(ref.radius, ref.mass, 1) << " s" << endl;
    }

    // Every pair of materials that may meet needs a law: a free particle
    // meets walls and particles; fixed and prescribed ones meet only free
    // ones
    labelList nOfMaterial(nM, Zero);
    labelList nFreeOfMaterial(nM, Zero);
    forAll(particles, i)
    {
        ++nOfMaterial[particleMaterial_[i]];
        if (particles[i].isFree())
        {
            ++nFreeOfMaterial[particleMaterial_[i]];
        }
    }
    for (label a = 0; a < nParticleMaterials; ++a)
    {
        for (label b = 0; b < nM; ++b)
        {
            const bool mayMeet =
                b < nParticleMaterials
              ? (a != b || nOfMaterial[a] > 1)
             && (nFreeOfMaterial[a] > 0 || nFreeOfMaterial[b] > 0)
              : nFreeOfMaterial[a] > 0;
            if (mayMeet && law(a, b) == noLaw)
            {
                FatalIOErrorInFunction(pairsDict)
                    << "No contact law for materials (" << materials_[a] << " "
                    << materials_[b] << "): add an entry with 'materials ("
                    << materials_[a] << " " << materials_[b] << ")' to"
                    << " 'pairs' (with 'law none;' if they pass through each"
                    << " other)" << exit(FatalIOError);
            }
        }
    }
}


void Foam::particleContact::gatherConstants()
{
    const PtrList<dlmParticle>& particles = cloud_.particles();
    inverseMass_.setSize(particles.size());
    inverseInertiaBody_.setSize(particles.size());
    radius_.setSize(particles.size());
    moving_.setSize(particles.size());
    isotropic_.setSize(particles.size());
    isotropicInverseInertia_.setSize(particles.size());
    forAll(particles, i)
    {
        const dlmParticle& p = particles[i];
        radius_[i] = p.shape().boundingRadius();
        moving_[i] = p.motion() != dlmParticle::motionType::fixed;
        if (p.isFree())
        {
            // With the fluid the rigid projection moves with it: the
            // follow step gives the contacts' change to those cells
            inverseMass_[i] =
                1/(p.coupledMassRatio()*p.density()*p.shape().volume());
            inverseInertiaBody_[i] =
                inv
                (
                    p.coupledInertiaRatio()*p.density()
                   *p.shape().inertiaPerUnitDensity()
                );
        }
        else
        {
            inverseMass_[i] = 0;
            inverseInertiaBody_[i] = Zero;
        }
        // Spheres and disks about their axis: the same in every frame
        const symmTensor& I = inverseInertiaBody_[i];
        isotropic_[i] =
            I.xy() == 0 && I.xz() == 0 && I.yz() == 0
         && I.xx() == I.yy() && I.yy() == I.zz();
        isotropicInverseInertia_[i] = isotropic_[i] ? I.xx() : 0;
    }
}


Foam::vector Foam::particleContact::angularAcceleration
(
    const label i,
    const quaternion& q,
    const vector& T
) const
{
    if (isotropic_[i])
    {
        return isotropicInverseInertia_[i]*T;
    }
    const tensor R(q.R());
    return (R & inverseInertiaBody_[i] & R.T()) & T;
}


Foam::boolList Foam::particleContact::pairParticles() const
{
    const label nM = materials_.size();
    boolList pairMaterial(nM, false);
    for (const label b : particleMaterial_)
    {
        for (label a = 0; a < nM; ++a)
        {
            pairMaterial[a] = pairMaterial[a] || law(a, b) >= 0;
        }
    }
    boolList pairParticle(particleMaterial_.size());
    forAll(particleMaterial_, i)
    {
        pairParticle[i] = pairMaterial[particleMaterial_[i]];
    }
    return pairParticle;
}


void Foam::particleContact::findCandidates
(
    const scalar deltaT,
    const vectorField& accel
)
{
    const PtrList<dlmParticle>& particles = cloud_.particles();
    const label n = particles.size();

    pairs_.clear();
    pairLaws_.clear();
    wallCandidates_.clear();
    wallFeatures_.clear();
    involved_.setSize(n);
    involved_ = false;
    if (n == 0)
    {
        return;
    }

    // Particles that may touch another particle (not an obstacle that every
    // particle passes through, such as an immersed wall, which would set
    // the bins' size)
    const boolList pairParticle(pairParticles());
    DynamicList<label> searched(n);
    forAll(particles, i)
    {
        if (pairParticle[i])
        {
            searched.append(i);
        }
    }

    // Skin: twice the largest displacement of the step, and the range of
    // lubrication
    scalar maxSpeed = 0;
    scalar maxRadius = 0;
    scalar minRadius = GREAT;
    forAll(particles, i)
    {
        const dlmParticle& p = particles[i];
        const scalar R = p.shape().boundingRadius();
        maxSpeed = max
        (
            maxSpeed,
            max(mag(p.velocity()), mag(p.velocity0()))
          + mag(accel[i])*deltaT
          + max(mag(p.angularVelocity()), mag(p.angularVelocity0()))*R
        );
        minRadius = min(minRadius, R);
    }
    for (const label i : searched)
    {
        maxRadius = max(maxRadius, particles[i].shape().boundingRadius());
    }
    const scalar skin =
        2*maxSpeed*deltaT + 0.01*minRadius
      + (lubricationViscosity_ > 0 ? lubricationRange_ : 0);

    // A periodic image meets another particle only within reach of the
    // mesh, where the particles' centres are: the images beyond (most of
    // them, in a periodic box) are left out of the search
    const label nSources = cloud_.nParticles();
    if (nSources < n)
    {
        const boundBox& bounds = cloud_.mesh().bounds();
        label nKept = 0;
        for (const label i : searched)
        {
            const scalar reach =
                particles[i].shape().boundingRadius() + maxRadius + skin;
            if
            (
                i < nSources
             || bounds.overlaps
                (
                    boundBox
                    (
                        particles[i].position() - reach*vector::one,
                        particles[i].position() + reach*vector::one
                    )
                )
            )
            {
                searched[nKept++] = i;
            }
        }
        searched.resize(nKept);
    }

    // Uniform bins of the searched particles' bounding box, side at least
    // the largest interaction distance
    boundBox bb;
    for (const label i : searched)
    {
        bb.add(particles[i].position());
    }
    if (searched.empty())
    {
        bb.add(point::zero);
    }
    const scalar binSize = 2*maxRadius + skin;
    Vector<label> nBins;
    for (direction d = 0; d < 3; ++d)
    {
        nBins[d] = max(label(bb.span()[d]/binSize), label(1));
    }
    // At most about 8 bins per particle
    while (scalar(nBins.x())*nBins.y()*nBins.z() > 8.0*n + 27)
    {
        for (direction d = 0; d < 3; ++d)
        {
            nBins[d] = max((nBins[d] + 1)/2, label(1));
        }
    }
    vector binWidth;
    for (direction d = 0; d < 3; ++d)
    {
        binWidth[d] = max(bb.span()[d]/nBins[d], binSize);
    }

    auto binOf = [&](const point& X, const direction d)
    {
        return min
        (
            label((X[d] - bb.min()[d])/binWidth[d]),
            nBins[d] - 1
        );
    };
    const label nTotal = nBins.x()*nBins.y()*nBins.z();
    labelList binStart(nTotal + 1, 0);
    labelList binOfParticle(n, -1);
    for (const label i : searched)
    {
        const point& X = particles[i].position();
        binOfParticle[i] =
            binOf(X, 0) + nBins.x()*(binOf(X, 1) + nBins.y()*binOf(X, 2));
        ++binStart[binOfParticle[i] + 1];
    }
    for (label b = 0; b < nTotal; ++b)
    {
        binStart[b + 1] += binStart[b];
    }
    labelList sorted(searched.size());
    {
        labelList fill(SubList<label>(binStart, nTotal));
        for (const label i : searched)
        {
            sorted[fill[binOfParticle[i]]++] = i;
        }
    }

    // With periodic images a contact is met more than once: across a
    // periodic boundary between a particle and an image of the other and
    // the other way round, and between images of both. The first found
    // (lowest indices: the particles read first) is kept. Its key: the two
    // sources and the second's offset from the first in periods
    HashSet<FixedList<label, 5>, FixedList<label, 5>::Hash<>> periodicPairs;
    auto newContact = [&](const label i, const label j)
    {
        const label a = cloud_.source(i);
        const label b = cloud_.source(j);
        if (a == b)
        {
            return false;
        }
        if (nSources == n)
        {
            return true;
        }
        const periodicImages& images = cloud_.images();
        labelVector offset(images.periods(j) - images.periods(i));
        if (a > b)
        {
            offset = -offset;
        }
        return periodicPairs.insert
        (
            FixedList<label, 5>
            ({min(a, b), max(a, b), offset.x(), offset.y(), offset.z()})
        );
    };

    forAll(particles, i)
    {
        const dlmParticle& pi = particles[i];
        const point& Xi = pi.position();
        const scalar Ri = pi.shape().boundingRadius();

        // Pairs: the searched particles in the 27 bins around it
        if (binOfParticle[i] >= 0)
        {
            const label bx = binOf(Xi, 0);
            const label by = binOf(Xi, 1);
            const label bz = binOf(Xi, 2);
            const label zEnd = min(bz + 1, nBins.z() - 1);
            const label yEnd = min(by + 1, nBins.y() - 1);
            const label xEnd = min(bx + 1, nBins.x() - 1);

            for (label z = max(bz - 1, 0); z <= zEnd; ++z)
            for (label y = max(by - 1, 0); y <= yEnd; ++y)
            for (label x = max(bx - 1, 0); x <= xEnd; ++x)
            {
                const label b = x + nBins.x()*(y + nBins.y()*z);
                for (label k = binStart[b]; k < binStart[b + 1]; ++k)
                {
                    const label j = sorted[k];
                    const dlmParticle& pj = particles[j];
                    const label pairLaw =
                        law(particleMaterial_[i], particleMaterial_[j]);
                    if
                    (
                        j <= i || (!pi.isFree() && !pj.isFree())
                     || pairLaw == noContact
                    )
                    {
                        continue;
                    }
                    const scalar gap =
                        mag(pj.position() - Xi) - Ri
                      - pj.shape().boundingRadius();
                    if (gap < skin && newContact(i, j))
                    {
                        pairs_.append(labelPair(i, j));
                        pairLaws_.append(pairLaw);
                        involved_[i] = true;
                        involved_[j] = true;
                    }
                }
            }
        }

        // A particle's contacts with the walls are its own, not its
        // images' (their centres lie outside the mesh)
        if (!pi.isFree() || i >= nSources)
        {
            continue;
        }
        forAll(walls_, w)
        {
            const label wallLaw =
                law(particleMaterial_[i], wallMaterial_[w]);
            if (wallLaw == noContact)
            {
                continue;
            }
            DynamicList<label> features;
            walls_[w].near(Xi, Ri + skin, features);
            if (features.size())
            {
                wallCandidates_.append(FixedList<label, 3>({i, w, wallLaw}));
                wallFeatures_.append(features);
                involved_[i] = true;
            }
        }
    }

    // A particle moves with its images' contacts
    for (label i = nSources; i < n; ++i)
    {
        if (involved_[i])
        {
            involved_[cloud_.source(i)] = true;
        }
    }

    // The springs of the candidate pairs move from the table to an array
    // for the step
    pairSpring_.setSize(pairs_.size());
    pairActive_.setSize(pairs_.size());
    forAll(pairs_, k)
    {
        const contactKey key({pairs_[k].first(), pairs_[k].second(), 0});
        auto iter = history_.find(key);
        pairActive_[k] = iter.found();
        pairSpring_[k] = iter.found() ? iter().first() : vector(Zero);
        if (iter.found())
        {
            history_.erase(iter);
        }
    }

    overlap_->prepare(pairs_);
}


Foam::scalar Foam::particleContact::impactStep
(
    const scalar deltaT,
    const vectorField& accel
) const
{
    const PtrList<dlmParticle>& particles = cloud_.particles();
    // Below this the collision time is long against any sensible step
    const scalar slowest = 1e-6;

    scalar step = GREAT;
    forAll(pairs_, k)
    {
        const label i = pairs_[k].first();
        const label j = pairs_[k].second();
        const scalar Ri = particles[i].shape().boundingRadius();
        const scalar Rj = particles[j].shape().boundingRadius();
        const scalar speed =
            mag(particles[i].velocity0() - particles[j].velocity0())
          + mag(particles[i].velocity() - particles[j].velocity())
          + (mag(accel[i]) + mag(accel[j]))*deltaT;
        const scalar mass = 1/(inverseMass(i) + inverseMass(j));
        step = min
        (
            step,
            laws_[pairLaws_[k]].contactTime
            (
                Ri*Rj/(Ri + Rj), mass, max(speed, slowest)
            )
        );
        if (!particles[i].shape().round() || !particles[j].shape().round())
        {
            step = min
            (
                step,
                flatContactTime(laws_[pairLaws_[k]], pi*sqr(min(Ri, Rj)), mass)
            );
        }
    }
    forAll(wallCandidates_, k)
    {
        const label i = wallCandidates_[k][0];
        const scalar speed =
            mag(particles[i].velocity0()) + mag(particles[i].velocity())
          + mag(accel[i])*deltaT;
        const scalar Ri = particles[i].shape().boundingRadius();
        step = min
        (
            step,
            laws_[wallCandidates_[k][2]].contactTime
            (
                Ri, 1/inverseMass(i), max(speed, slowest)
            )
        );
        if (!particles[i].shape().round())
        {
            step = min
            (
                step,
                flatContactTime
                (
                    laws_[wallCandidates_[k][2]], pi*sqr(Ri), 1/inverseMass(i)
                )
            );
        }
    }
    return step/stepsPerContact_;
}


Foam::scalar Foam::particleContact::flatContactTime
(
    const contactLaw& law,
    const scalar area,
    const scalar mass
)
{
    // A face meets a face at once over its area: a stiffness that does not
    // grow from zero with the depth, so the contact is as short at any
    // speed, and a body resting down onto a face must not sink into it by
    // a whole sub-step's fall
    const scalar depth = 1e-6*Foam::sqrt(area);
    const scalar V = area*depth;
    scalar stiffness, damping;
    law.normalForce(V, depth, sqr(area)/(4*pi*V), mass, 0, stiffness, damping, 1);
    return pi*Foam::sqrt(mass/max(stiffness, VSMALL));
}


Foam::vector Foam::particleContact::tangentialForce
(
    const contactLaw& law,
    vector* spring,
    const vector& sliding,
    const vector& normal,
    const scalar normalForce,
    const scalar stiffness,
    const scalar damping,
    const scalar h
)
{
    const scalar limit = law.friction()*mag(normalForce);
    const scalar ct = law.tangentialDampingRatio()*damping;

    if (law.tangential() == contactLaw::tangentialType::coulomb)
    {
        vector F(-ct*sliding);
        const scalar magF = mag(F);
        return magF > limit ? F*limit/magF : F;
    }

    // Spring on the sliding displacement, kept in the tangent plane
    vector& xi = *spring;

    const scalar magXi = mag(xi);
    xi -= (xi & normal)*normal;
    const scalar magTangent = mag(xi);
    if (magTangent > VSMALL)
    {
        xi *= magXi/magTangent;
    }
    xi += sliding*h;

    const scalar kt = law.tangentialStiffnessRatio()*stiffness;
    if (law.frictionLimit() == contactLaw::frictionLimitType::spring)
    {
        const scalar magSpring = kt*mag(xi);
        if (magSpring > limit)
        {
            // Sliding: the spring alone, at what friction allows
            xi *= limit/magSpring;
            return -kt*xi;
        }
        return -kt*xi - ct*sliding;
    }

    vector F(-kt*xi - ct*sliding);
    const scalar magF = mag(F);
    if (magF > limit)
    {
        // Sliding: the spring holds what friction allows
        F *= limit/magF;
        xi = kt > 0 ? vector(-(F + ct*sliding)/kt) : vector(Zero);
    }
    return F;
}


Foam::vector& Foam::particleContact::wallSpring(const contactKey& key)
{
    auto iter = history_.find(key);
    if (!iter.found())
    {
        history_.insert(key, Tuple2<vector, label>(Zero, evaluation_));
        iter = history_.find(key);
    }
    iter().second() = evaluation_;
    return iter().first();
}


void Foam::particleContact::applyContact
(
    const label i,
    const label j,
    const contactLaw& law,
    vector* spring,
    const scalar V,
    const scalar depth,
    const point& location,
    const vector& normal,
    const scalar h,
    const scalar curvatureRadius,
    const scalar volumeExponent,
    const scalar sectionArea
)
{
    const scalar Ri = radius_[i];

    const vector ri(location - position_[i]);
    vector relative(-(velocity_[i] + (omega_[i] ^ ri)));
    scalar invMass = inverseMass(i);
    scalar radius = curvatureRadius > 0 ? curvatureRadius : Ri;
    scalar smallerRadius = Ri;
    vector rj(Zero);
    if (j >= 0)
    {
        const scalar Rj = radius_[j];
        rj = location - position_[j];
        relative += velocity_[j] + (omega_[j] ^ rj);
        invMass += inverseMass(j);
        if (curvatureRadius <= 0)
        {
            radius = Ri*Rj/(Ri + Rj);
        }
        smallerRadius = min(Ri, Rj);
    }
    maxOverlapRatio_ = max(maxOverlapRatio_, 0.5*depth/smallerRadius);

    // The mass that the contact moves along its normal: with the turn of
    // a body that it pushes off its centroid (not a sphere's), so that
    // the damping and the sub-step fit the contact's true frequency
    const PtrList<dlmParticle>& particles = cloud_.particles();
    const bool offCentre =
        !particles[i].shape().round()
     || (j >= 0 && !particles[j].shape().round());
    if (offCentre)
    {
        const vector ci(ri ^ normal);
        invMass += ci & angularAcceleration(i, orientation_[i], ci);
        if (j >= 0)
        {
            const vector cj(rj ^ normal);
            invMass += cj & angularAcceleration(j, orientation_[j], cj);
        }
    }
    const scalar mass = 1/invMass;

    // relative: velocity of j (or the wall) seen from i; normal from i to j
    scalar stiffness, damping;
    const scalar Fn = law.normalForce
    (
        V, depth, radius, mass, -(relative & normal), stiffness, damping,
        volumeExponent
    );
    const vector sliding(-(relative - (relative & normal)*normal));
    const vector Ft
    (
        tangentialForce(law, spring, sliding, normal, Fn, stiffness, damping, h)
    );

    const vector F(-Fn*normal + Ft);
    force_[i] += F;
    torque_[i] += ri ^ F;
    if (j >= 0)
    {
        force_[j] -= F;
        torque_[j] -= rj ^ F;
    }
    // Rolling resistance against the whole relative spin; twisting
    // friction against its part along the normal: Coulomb's friction over
    // the patch, taken as a disk of its area
    const vector spin(relativeSpin(i, j));
    vector M(Zero);
    const scalar magSpin = mag(spin);
    if (law.rollingFriction() > 0 && Fn > 0 && magSpin > VSMALL)
    {
        M -= law.rollingFriction()*radius*Fn*spin/magSpin;
    }
    const scalar twist = spin & normal;
    if
    (
        law.twistingFriction() && law.friction() > 0 && Fn > 0
     && sectionArea > 0 && !cloud_.twoD() && mag(twist) > VSMALL
    )
    {
        M -= 2.0/3.0*law.friction()*Fn*sqrt(sectionArea/pi)*sign(twist)*normal;
    }
    if (magSqr(M) > 0)
    {
        spinResistances_.append({i, j, M});
        ++nSpinResistances_[i];
        if (j >= 0)
        {
            ++nSpinResistances_[j];
        }
    }

    // A contact that began within this sub-step, a fraction s of it ago:
    // its damping force (not zero at first touch) acts for s h, not the
    // h/2 of the closing half-kick
    const scalar approach = -(relative & normal);
    // An unclipped contact that will end within the next sub-step, after a
    // fraction s of it: its damping force (pulling, not zero at the end)
    // acts for s h, not the h/2 of the next opening half-kick
    const scalar hc = correctionStep_;
    if (hc > 0 && approach < 0 && depth < -approach*hc && !law.clip())
    {
        const scalar s = depth/(-approach*hc);
        const vector correction(-(2*s - 1)*damping*approach*normal);
        exitForce_[i] += correction;
        if (j >= 0)
        {
            exitForce_[j] -= correction;
        }
        // Along the normal: a torque off a round shape's centre only
        if (offCentre)
        {
            exitTorque_[i] += ri ^ correction;
            if (j >= 0)
            {
                exitTorque_[j] -= rj ^ correction;
            }
        }
    }
    if (hc > 0 && approach > 0 && depth < approach*hc && Fn > 0)
    {
        const scalar s = depth/(approach*hc);
        const vector correction
        (
            -(2*s - 1)*min(damping*approach, Fn)*normal
        );
        onsetForce_[i] += correction;
        if (j >= 0)
        {
            onsetForce_[j] -= correction;
        }
        if (offCentre)
        {
            onsetTorque_[i] += ri ^ correction;
            if (j >= 0)
            {
                onsetTorque_[j] -= rj ^ correction;
            }
        }
    }

    if (stiffness > 0)
    {
        activeStep_ = min
        (
            activeStep_,
            pi*sqrt(mass/stiffness)/stepsPerContact_
        );
    }
    ++nActive_;
}


void Foam::particleContact::applySpinResistances(const scalar h)
{
    // Each torque against its pair's relative spin, at most a share of
    // what stops that spin within the sub-step (the step's first
    // evaluation, h = 0, opens a sub-step like the last): a quarter, or
    // half over the number of such contacts of the busier body. Each
    // contact taking the whole of it reversed the spin of a body between
    // two (a box between the floor and a cylinder on it spun up to
    // 12 rad/s); a quarter from each, rolling and twisting apart, let a
    // body with four or more such contacts in a dry pile spin up from
    // step to step without bound
    const scalar step = h > 0 ? h : correctionStep_;
    for (const spinResistance& r : spinResistances_)
    {
        const label i = r.i;
        const label j = r.j;
        const scalar limit = mag(r.torque);
        const vector axis(r.torque/limit);
        vector M(r.torque);
        if (step > 0)
        {
            const vector spin(relativeSpin(i, j));
            vector response(angularAcceleration(i, orientation_[i], axis));
            if (j >= 0)
            {
                response += angularAcceleration(j, orientation_[j], axis);
            }
            const label busier =
                max(nSpinResistances_[i], j >= 0 ? nSpinResistances_[j] : 0);
            const scalar share = min(0.25, 0.5/busier);
            const scalar stopping =
                share*max(-(spin & axis), scalar(0))
               /(step*max(axis & response, VSMALL));
            M = min(limit, stopping)*axis;
        }
        torque_[i] += M;
        if (j >= 0)
        {
            torque_[j] -= M;
        }
    }
    spinResistances_.clear();
    nSpinResistances_ = 0;
}


template<class SpringOf>
void Foam::particleContact::applyShapeWallContact
(
    const label i,
    const contactLaw& law,
    const SpringOf& spring,
    const wallContact& c,
    const scalar h
)
{
    const dlmParticle& p = cloud_.particles()[i];
    const tensor R(orientation_[i].R());
    // Body frame: the unit normal from the centroid towards the wall
    const vector n(R.T() & -c.normal);
    const scalar depth = p.shape().support(n) - c.distance;
    if (depth <= 0)
    {
        return;
    }
    scalar V, area;
    vector centroid;
    p.shape().planeCut(n, c.distance, V, centroid, area);
    if (V <= 0 || area <= 0)
    {
        return;
    }

    // The force acts at the overlap's centroid; its stiffness is the law's
    // for the section's area (dV/ddelta), as for the round shapes' lens of
    // the equivalent curvature radius, and its damping gives the
    // restitution for the exponent with which the overlap grows (1 on a
    // face, 2 on a smooth point, 3 on a corner)
    applyContact
    (
        i, -1, law, spring(c), V, depth,
        position_[i] + (R & centroid), -c.normal, h,
        overlapGeometry::equivalentRadius(area, V, cloud_.twoD() ? 2 : 3),
        min(max(area*depth/V, scalar(1)), scalar(3)),
        area
    );
}


void Foam::particleContact::applyLubrication
(
    const label i,
    const label j,
    const scalar gap,
    const point& location,
    const vector& normal
)
{
    const scalar Ri = radius_[i];

    vector relative(-velocity_[i]);
    scalar invMass = inverseMass(i);
    scalar radius = Ri;
    if (j >= 0)
    {
        const scalar Rj = radius_[j];
        relative += velocity_[j];
        invMass += inverseMass(j);
        radius = Ri*Rj/(Ri + Rj);
    }
    const scalar h = max(gap, roughness_*radius);
    if (h >= lubricationRange_)
    {
        return;
    }

    // Resistance coefficient of the unresolved part of the film
    const scalar mu = lubricationViscosity_;
    const scalar resistance =
        cloud_.twoD()
      ? 0.75*pi*sqrt(2.0)*mu
       *(pow(radius/h, 1.5) - pow(radius/lubricationRange_, 1.5))
      : 6*pi*mu*sqr(radius)*(1/h - 1/lubricationRange_);

    const vector F((resistance*(relative & normal))*normal);
    force_[i] += F;
    if (j >= 0)
    {
        force_[j] -= F;
    }
    activeStep_ = min(activeStep_, 0.5/(invMass*resistance));
}


void Foam::particleContact::evaluate(const scalar h)
{
    const PtrList<dlmParticle>& particles = cloud_.particles();
    ++evaluation_;
    activeStep_ = GREAT;
    nActive_ = 0;

    // Overlaps by blocks, each used while it is in cache
    const label block = min(overlap_->blockSize(), pairs_.size());
    overlaps_.setSize(block);
    for (label start = 0; start < pairs_.size(); start += block)
    {
        SubList<pairOverlap> overlaps
        (
            overlaps_,
            min(block, pairs_.size() - start)
        );
        overlap_->overlaps(pairs_, start, position_, orientation_, overlaps);
        forAll(overlaps, b)
        {
            const pairOverlap& o = overlaps[b];
            const label k = start + b;
            const label i = pairs_[k].first();
            const label j = pairs_[k].second();
            const contactLaw& law = laws_[pairLaws_[k]];
            pairActive_[k] = o.volume > 0;
            if (pairActive_[k])
            {
                applyContact
                (
                    i, j, law,
                    law.tangential() == contactLaw::tangentialType::spring
                  ? &pairSpring_[k] : nullptr,
                    o.volume, o.depth, o.location, o.normal, h,
                    o.curvatureRadius, o.volumeExponent, o.sectionArea
                );
            }
            else
            {
                pairSpring_[k] = Zero;
            }
            // The lubrication film between round shapes only
            if
            (
                lubricationViscosity_ > 0
             && particles[i].shape().round()
             && particles[j].shape().round()
            )
            {
                applyLubrication(i, j, -o.depth, o.location, o.normal);
            }
        }
    }

    DynamicList<wallContact> found;
    DynamicList<wallContact> shapePlanes;
    forAll(wallCandidates_, k)
    {
        const label i = wallCandidates_[k][0];
        const label w = wallCandidates_[k][1];
        const particleShape& shape = particles[i].shape();
        const scalar R = shape.boundingRadius();
        found.clear();
        walls_[w].contacts
        (
            position_[i],
            R
          + (
                lubricationViscosity_ > 0 && walls_[w].lubricated()
              ? lubricationRange_
              : 0
            ),
            wallFeatures_[k],
            found
        );
        const tensor RT(orientation_[i].R().T());
        const contactLaw& law = laws_[wallCandidates_[k][2]];
        // The tangential spring of a contact that touches (created then)
        auto spring = [&](const wallContact& c)
        {
            return
                law.tangential() == contactLaw::tangentialType::spring
              ? &wallSpring(contactKey({i, -1 - w, c.feature})) : nullptr;
        };
        for (const wallContact& c : found)
        {
            if (!shape.round())
            {
                shapePlanes.clear();
                walls_[w].shapeContacts
                (
                    shape, position_[i], orientation_[i].R(), c, shapePlanes
                );
                for (const wallContact& plane : shapePlanes)
                {
                    applyShapeWallContact(i, law, spring, plane, h);
                }
                continue;
            }
            if (lubricationViscosity_ > 0 && walls_[w].lubricated())
            {
                applyLubrication(i, -1, c.distance - R, c.location, -c.normal);
            }
            if (c.distance >= R)
            {
                continue;
            }
            const scalar V = shape.planeOverlap(RT & -c.normal, c.distance);
            if (V > 0)
            {
                applyContact
                (
                    i, -1, law, spring(c),
                    V, R - c.distance, c.location, -c.normal, h
                );
            }
        }
    }

    applySpinResistances(h);

    // Wall contacts that ended lose their history
    DynamicList<contactKey> ended;
    forAllConstIters(history_, iter)
    {
        if (iter().second() != evaluation_)
        {
            ended.append(iter.key());
        }
    }
    for (const contactKey& key : ended)
    {
        history_.erase(key);
    }

    if (cloud_.twoD())
    {
        for (vector& F : force_)
        {
            F.z() = 0;
        }
        for (vector& T : torque_)
        {
            T = vector(0, 0, T.z());
        }
    }
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::wordList Foam::particleContact::keywords()
{
    return wordList
    ({
        "active", "overlap", "stepsPerContact", "meshWalls", "pairs", "walls",
        "lubrication", "maxStartOverlap"
    });
}


Foam::wordList Foam::particleContact::lubricationKeywords()
{
    return wordList({"active", "range", "roughness"});
}


Foam::wordList Foam::particleContact::noLawKeywords()
{
    return wordList({"materials", "law"});
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleContact::particleContact
(
    dlmParticleCloud& cloud,
    const dictionary& dict,
    const dictionary& state
)
:
    cloud_(cloud),
    dict_(dict),
    stepsPerContact_(dict.getOrDefault<scalar>("stepsPerContact", 50)),
    lubricationViscosity_(0),
    lubricationRange_(cloud.cellSizeMax()),
    roughness_(0.01),
    overlap_(),
    evaluation_(0),
    correctionStep_(0),
    lastSubStep_(0),
    activeStep_(GREAT),
    nActive_(0),
    maxTouching_(0),
    nSubSteps_(0),
    maxOverlapRatio_(0),
    maxStartOverlap_(dict.getOrDefault<scalar>("maxStartOverlap", 0.05))
{
    checkKeywords(dict, wordHashSet(keywords()), "in the contact settings");
    if (maxStartOverlap_ < 0 || maxStartOverlap_ >= 1)
    {
        FatalIOErrorInFunction(dict)
            << "maxStartOverlap " << maxStartOverlap_ << " must be in [0, 1)"
            << " (a fraction of the smaller diameter)" << exit(FatalIOError);
    }
    if (stepsPerContact_ < 4)
    {
        FatalIOErrorInFunction(dict)
            << "stepsPerContact " << stepsPerContact_ << " must be at least 4"
            << exit(FatalIOError);
    }

    const dictionary lubrication(dict.subOrEmptyDict("lubrication"));
    checkKeywords
    (
        lubrication,
        wordHashSet(lubricationKeywords()),
        "in the contact settings' lubrication"
    );
    const bool withFluid = cloud.rhoFluid().value() > 0;
    if (lubrication.getOrDefault<bool>("active", withFluid))
    {
        if (!withFluid)
        {
            FatalIOErrorInFunction(lubrication)
                << "Lubrication needs a fluid (this run has none)"
                << exit(FatalIOError);
        }
        const dictionary& transport =
            cloud.mesh().lookupObject<IOdictionary>("transportProperties");
        lubricationViscosity_ =
            cloud.rhoFluid().value()*transport.get<scalar>("nu");
        lubricationRange_ =
            lubrication.getOrDefault<scalar>("range", lubricationRange_);
        roughness_ = lubrication.getOrDefault<scalar>("roughness", roughness_);
        if (lubricationRange_ <= 0 || roughness_ <= 0)
        {
            FatalIOErrorInFunction(lubrication)
                << "lubrication range and roughness must be positive"
                << exit(FatalIOError);
        }
        Info<< "Lubrication below gaps of " << lubricationRange_
            << " m, smallest gap " << roughness_ << " R*" << endl;
    }

    const PtrList<dlmParticle>& particles = cloud.particles();
    particleMaterial_.setSize(particles.size());
    forAll(particles, i)
    {
        particleMaterial_[i] = materialIndex(particles[i].material());
    }

    // The mesh's walls, where it has any (a periodic box has none, and
    // needs no law for them)
    if
    (
        dict.getOrDefault<bool>("meshWalls", true)
     && cloud.mesh().boundaryMesh().findPatchIDs<wallPolyPatch>().size()
    )
    {
        dictionary meshWalls;
        meshWalls.name() = dict.name() + ".meshWalls";
        meshWalls.add("type", "patches");
        walls_.append(contactWall::New(meshWalls, cloud.mesh()));
    }
    if (dict.found("walls"))
    {
        for (const entry& e : dict.subDict("walls"))
        {
            walls_.append(contactWall::New(e.dict(), cloud.mesh()));
        }
    }
    wallMaterial_.setSize(walls_.size());
    forAll(walls_, w)
    {
        wallMaterial_[w] = materialIndex(walls_[w].material());
    }

    readLaws();
    overlap_ = overlapMethod::New(dict, cloud, pairParticles());

    // A restarted run's last sub-step (the corrections of the first
    // evaluation take it) and tangential history
    state.readIfPresent("lastContactSubStep", lastSubStep_);
    labelList near;
    if (state.readIfPresent("nearContact", near))
    {
        involved_.setSize(particles.size());
        involved_ = false;
        for (const label i : near)
        {
            if (i < 0 || i >= particles.size())
            {
                FatalIOErrorInFunction(state)
                    << "nearContact names particle " << i << " of "
                    << particles.size() << exit(FatalIOError);
            }
            involved_[i] = true;
        }
    }
    if (state.found("contacts"))
    {
        const List<Tuple2<contactKey, vector>> saved
        (
            state.get<List<Tuple2<contactKey, vector>>>("contacts")
        );
        for (const auto& entry : saved)
        {
            history_.set
            (
                entry.first(),
                Tuple2<vector, label>(entry.second(), evaluation_)
            );
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::particleContact::addImageLoads(const labelUList& images)
{
    for (const label i : images)
    {
        const label body = cloud_.source(i);
        for
        (
            vectorField* loads :
            {
                &force_, &torque_, &onsetForce_, &onsetTorque_, &exitForce_,
                &exitTorque_
            }
        )
        {
            vectorField& f = *loads;
            f[body] += f[i];
            f[i] = Zero;
        }
    }
}


void Foam::particleContact::followSources(const labelUList& images)
{
    const PtrList<dlmParticle>& particles = cloud_.particles();
    for (const label i : images)
    {
        const label body = cloud_.source(i);
        position_[i] =
            position_[body] + particles[i].position()
          - particles[body].position();
        velocity_[i] = velocity_[body];
        omega_[i] = omega_[body];
        orientation_[i] = orientation_[body];
    }
}


void Foam::particleContact::evolve
(
    const scalar deltaT,
    const vectorField& accel,
    const vectorField& angularAccel
)
{
    PtrList<dlmParticle>& particles = cloud_.particles();
    const label n = particles.size();

    maxOverlapRatio_ = 0;
    gatherConstants();
    findCandidates(deltaT, accel);

    // Step state of the particles that may touch something, from the
    // start of the step
    position_.setSize(n);
    velocity_.setSize(n);
    omega_.setSize(n);
    orientation_.setSize(n);
    force_.setSize(n);
    torque_.setSize(n);
    onsetForce_.setSize(n);
    onsetTorque_.setSize(n);
    exitForce_.setSize(n);
    exitTorque_.setSize(n);
    nSpinResistances_.setSize(n);
    nSpinResistances_ = 0;
    force_ = Zero;
    torque_ = Zero;
    onsetForce_ = Zero;
    onsetTorque_ = Zero;
    exitForce_ = Zero;
    exitTorque_ = Zero;
    forAll(particles, i)
    {
        const dlmParticle& p = particles[i];
        position_[i] = p.position();
        velocity_[i] = p.velocity0();
        omega_[i] = p.angularVelocity0();
        orientation_[i] = p.orientation();
        if (p.motion() == dlmParticle::motionType::prescribed)
        {
            velocity_[i] = p.velocity();
            omega_[i] = p.angularVelocity();
        }
    }

    vectorField impulse(n, Zero);
    vectorField angularImpulse(n, Zero);
    vectorField halfVelocity(n, Zero);
    vectorField halfOmega(n, Zero);
    // Forces of the opening half-kick of the present sub-step
    vectorField force0(n, Zero);
    vectorField torque0(n, Zero);

    const scalar hImpact = impactStep(deltaT, accel);
    // The first evaluation sees the step of the last sub-step for the
    // corrections of contacts that begin or end; its springs do not advance
    correctionStep_ = lastSubStep_;
    evaluate(0);

    // The images in contact, whose loads go to their particles and which
    // follow them
    DynamicList<label> images;
    for (label i = cloud_.nParticles(); i < n; ++i)
    {
        if (involved_[i])
        {
            images.append(i);
        }
    }
    addImageLoads(images);

    // Sub-step from time t on (0: the step is done)
    auto nextStep = [&](const scalar t)
    {
        return
            t < deltaT*(1 - 1e-12)
          ? min(deltaT - t, min(hImpact, activeStep_))
          : 0;
    };

    scalar t = 0;
    label nSub = 0;
    scalar hMin = deltaT;
    label maxActive = nActive_;
    // Each visit of the particles closes the sub-step that ended (hClose,
    // half-kick with the forces at its end) and opens the next (h,
    // half-kick and drift): the particle arrays are read once per sub-step
    scalar hClose = 0;
    scalar h = nextStep(t);
    while (true)
    {
        if (h > 0)
        {
            correctionStep_ = h;
            lastSubStep_ = h;
            hMin = min(hMin, h);
        }

        const label nSources = cloud_.nParticles();
        for (label i = 0; i < nSources; ++i)
        {
            if (!involved_[i])
            {
                continue;
            }
            if (hClose > 0 && inverseMass_[i] > 0)
            {
                velocity_[i] =
                    halfVelocity[i]
                  + 0.5*hClose
                   *(accel[i] + inverseMass(i)*(force_[i] + onsetForce_[i]));
                omega_[i] =
                    halfOmega[i]
                  + 0.5*hClose
                   *(
                        angularAccel[i]
                      + angularAcceleration
                        (
                            i, orientation_[i], torque_[i] + onsetTorque_[i]
                        )
                    );
                impulse[i] +=
                    0.5*hClose*(force0[i] + force_[i] + onsetForce_[i]);
                angularImpulse[i] +=
                    0.5*hClose*(torque0[i] + torque_[i] + onsetTorque_[i]);
            }
            if (h == 0)
            {
                continue;
            }
            force0[i] = force_[i] + exitForce_[i];
            torque0[i] = torque_[i] + exitTorque_[i];
            if (inverseMass_[i] > 0)
            {
                const vector dv
                (
                    0.5*h*(accel[i] + inverseMass(i)*force0[i])
                );
                const vector domega
                (
                    0.5*h
                   *(
                        angularAccel[i]
                      + angularAcceleration(i, orientation_[i], torque0[i])
                    )
                );
                halfVelocity[i] = velocity_[i] + dv;
                halfOmega[i] = omega_[i] + domega;
                // Forces at the end of the sub-step see the velocities
                // predicted there (second order with damping)
                velocity_[i] = halfVelocity[i] + dv;
                omega_[i] = halfOmega[i] + domega;
            }
            else
            {
                halfVelocity[i] = velocity_[i];
                halfOmega[i] = omega_[i];
            }
            if (moving_[i])
            {
                position_[i] += h*halfVelocity[i];
                // The drift turns free of torque: a body whose inertia is
                // not isotropic changes its angular velocity as it turns
                const dlmParticle& p = particles[i];
                p.rotateFree(orientation_[i], halfOmega[i], h);
                if (!p.steadyFreeSpin() && inverseMass_[i] > 0)
                {
                    omega_[i] =
                        halfOmega[i]
                      + 0.5*h
                       *(
                            angularAccel[i]
                          + angularAcceleration
                            (
                                i,
                                orientation_[i],
                                torque0[i]
                            )
                        );
                }
            }
            // The forces of the next evaluation add up from zero
            force_[i] = Zero;
            torque_[i] = Zero;
            onsetForce_[i] = Zero;
            onsetTorque_[i] = Zero;
            exitForce_[i] = Zero;
            exitTorque_[i] = Zero;
        }
        if (h == 0)
        {
            break;
        }
        followSources(images);

        evaluate(h);
        addImageLoads(images);
        maxActive = max(maxActive, nActive_);

        t += h;
        ++nSub;
        hClose = h;
        h = nextStep(t);
    }

    // The images take their particles' state afterwards
    // (dlmParticleCloud::move)
    for (label i = 0; i < cloud_.nParticles(); ++i)
    {
        dlmParticle& p = particles[i];
        if (!involved_[i])
        {
            p.move(deltaT);
            p.setContactLoads(Zero, Zero);
        }
        else if (p.motion() != dlmParticle::motionType::fixed)
        {
            p.setMotion(position_[i], velocity_[i], omega_[i], orientation_[i]);
            p.setContactLoads(impulse[i]/deltaT, angularImpulse[i]/deltaT);
        }
    }

    forAll(pairs_, k)
    {
        if
        (
            pairActive_[k]
         && laws_[pairLaws_[k]].tangential()
         == contactLaw::tangentialType::spring
        )
        {
            history_.set
            (
                contactKey({pairs_[k].first(), pairs_[k].second(), 0}),
                Tuple2<vector, label>(pairSpring_[k], evaluation_)
            );
        }
    }

    maxTouching_ = maxActive;
    nSubSteps_ = nSub;

    Info<< "Contacts: " << pairs_.size() << " particle pairs and "
        << wallCandidates_.size() << " particle-wall candidates, up to "
        << maxActive << " touching; " << nSub << " sub-steps, smallest "
        << hMin << " s" << endl;
}


Foam::scalarField Foam::particleContact::nearSpeeds
(
    const PtrList<dlmParticle>& particles
) const
{
    scalarField speeds(particles.size(), Zero);
    for (const labelPair& pair : pairs_)
    {
        const scalar s =
            mag
            (
                particles[pair.first()].velocity()
              - particles[pair.second()].velocity()
            );
        speeds[pair.first()] = max(speeds[pair.first()], s);
        speeds[pair.second()] = max(speeds[pair.second()], s);
    }
    for (const FixedList<label, 3>& candidate : wallCandidates_)
    {
        const label i = candidate[0];
        speeds[i] = max(speeds[i], mag(particles[i].velocity()));
    }
    return speeds;
}


void Foam::particleContact::checkWalls() const
{
    DynamicList<label> features;
    DynamicList<wallContact> found;
    for (const dlmParticle& p : cloud_.particles())
    {
        if (!p.isFree())
        {
            continue;
        }
        const point& X = p.position();
        const scalar R = p.shape().boundingRadius();
        for (const contactWall& wall : walls_)
        {
            features.clear();
            found.clear();
            wall.near(X, R, features);
            wall.contacts(X, R, features, found);
            for (const wallContact& c : found)
            {
                // The depth, and the thickness across the wall (the
                // diameter of a round shape)
                const vector n(p.R().T() & -c.normal);
                const scalar depth = p.shape().support(n) - c.distance;
                const scalar thickness = p.shape().thickness(n);
                if (c.distance < 0 || depth > maxStartOverlap_*thickness)
                {
                    FatalIOErrorInFunction(dict_)
                        << "Particle " << p.name() << " at " << X
                        << " (thickness " << thickness << " across the wall) "
                        << (
                               c.distance < 0
                             ? "has its centre beyond wall "
                             : "overlaps wall "
                           )
                        << wall.name() << " by " << depth << " ("
                        << 100*depth/thickness << " % of its thickness) at"
                        << " the start,"
                        << " more than the contact laws resolve"
                        << " (maxStartOverlap " << maxStartOverlap_
                        << " of the thickness). Move the particle clear of"
                        << " the wall" << exit(FatalIOError);
                }
            }
        }
    }
}


void Foam::particleContact::removeParticles(const labelList& oldToNew)
{
    HashTable<Tuple2<vector, label>, contactKey, contactKey::Hash<>> kept
    (
        history_.capacity()
    );
    forAllConstIters(history_, iter)
    {
        // A wall's key is -1 - wall: map particle partners only
        contactKey key(iter.key());
        const bool pair = key[1] >= 0;
        if (oldToNew[key[0]] < 0 || (pair && oldToNew[key[1]] < 0))
        {
            continue;
        }
        key[0] = oldToNew[key[0]];
        if (pair)
        {
            key[1] = oldToNew[key[1]];
        }
        kept.insert(key, iter.val());
    }
    history_.transfer(kept);

    const labelList oldMaterial(particleMaterial_);
    const boolList oldInvolved(involved_);
    particleMaterial_.setSize(max(oldToNew) + 1);
    involved_.setSize(particleMaterial_.size());
    forAll(oldToNew, i)
    {
        const label k = oldToNew[i];
        if (k >= 0)
        {
            particleMaterial_[k] = oldMaterial[i];
            involved_[k] = i < oldInvolved.size() && oldInvolved[i];
        }
    }
}


void Foam::particleContact::write(Ostream& os) const
{
    List<Tuple2<contactKey, vector>> saved(history_.size());
    label k = 0;
    for (const contactKey& key : history_.sortedToc())
    {
        saved[k++] = Tuple2<contactKey, vector>(key, history_[key].first());
    }
    os.writeEntry("contacts", saved);
    os.writeEntry("lastContactSubStep", lastSubStep_);

    // The particles near a contact in the last step: the next step's size
    // counts their surface speed twice (dlmParticleCloud::courantNumber)
    DynamicList<label> near;
    forAll(involved_, i)
    {
        if (involved_[i])
        {
            near.append(i);
        }
    }
    os.writeEntry("nearContact", near);
}


// ************************************************************************* //
