/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "interpolated.H"
#include "dlmParticleCloud.H"
#include "fvmDdt.H"
#include "scalarMatrices.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fv
{
    defineTypeNameAndDebug(interpolated, 0);
    addToRunTimeSelectionTable(mixedCellTreatment, interpolated, dictionary);
}
}


namespace
{
    // Layout of the per-particle sums of the interpolated projection: the
    // momentum balance a11 U - [q]x Omega = b1, [ar]x U + A22 Omega = b2,
    // and the particle's own mass and inertia. Geometric sums, fixed over a
    // time step:
    enum geometricSumIndex
    {
        gA11 = 0,           // sum m a
        gMq = 1,            // sum m q (3)
        gMar = 4,           // sum m a r (3)
        gA22 = 7,           // sum m ((r.q) 1 - q r) (9)
        gMass = 16,         // sum rho_s phi V
        gVolume = 17,       // sum phi V
        gInertia = 18,      // sum rho_s phi V (|r|^2 1 - r r) (6)
        nGeometricSums = 24
    };

    // and sums of the velocity, at each correction
    enum velocitySumIndex
    {
        vB1 = 0,            // sum m (u - u_samples) (3)
        vB2 = 3,            // sum m r x (u - u_samples) (3)
        nVelocitySums = 6
    };

    // and, with boundary-layer slip (per cell the rigid part A and the
    // sampled part s' of the target a A U + A (Omega x q) + s'), the
    // blocks of the balance, at each correction (the velocity sums then
    // are sum m (u - s') and its moment)
    enum slipSumIndex
    {
        sA11 = 6,           // sum m a A (9)
        sA12 = 15,          // -sum m A [q]x (9)
        sA21 = 24,          // sum m a [r]x A (9)
        sA22 = 33,          // -sum m [r]x A [q]x (9)
        nSlipSums = 36
    };

    // Layout of the sums that remove the net force of the carried force
    enum restrictSumIndex
    {
        kMass = 0,          // sum m
        kFirst = 1,         // sum m r (3)
        kSecond = 4,        // sum m (|r|^2 1 - r r) (9)
        kForce = 13,        // sum V f (3)
        kTorque = 16,       // sum V r x f (3)
        nRestrictSums = 19
    };

    inline Foam::vector sumVector(const Foam::scalar* s)
    {
        return Foam::vector(s[0], s[1], s[2]);
    }

    inline void addVector(Foam::scalar* s, const Foam::vector& v)
    {
        for (Foam::direction d = 0; d < 3; ++d)
        {
            s[d] += v[d];
        }
    }

    inline void addTensor(Foam::scalar* s, const Foam::tensor& t)
    {
        for (Foam::direction d = 0; d < 9; ++d)
        {
            s[d] += t[d];
        }
    }

    inline Foam::tensor sumTensor(const Foam::scalar* s)
    {
        Foam::tensor t;
        for (Foam::direction d = 0; d < 9; ++d)
        {
            t[d] = s[d];
        }
        return t;
    }

    // Matrix [v]x with [v]x w = v x w
    inline Foam::tensor crossMatrix(const Foam::vector& v)
    {
        return Foam::tensor
        (
            0, -v.z(), v.y(),
            v.z(), 0, -v.x(),
            -v.y(), v.x(), 0
        );
    }

    // Solve [A11 A12; A21 A22] (U, Omega) = (b1, b2) for the rigid
    // velocities; in 2D only U.x, U.y and Omega.z
    void solveRigid
    (
        const Foam::tensor& A11,
        const Foam::tensor& A12,
        const Foam::tensor& A21,
        const Foam::tensor& A22,
        const Foam::vector& b1,
        const Foam::vector& b2,
        const bool twoD,
        Foam::vector& U,
        Foam::vector& omega
    )
    {
        using namespace Foam;

        const labelList unknowns
        (
            twoD ? labelList({0, 1, 5}) : labelList({0, 1, 2, 3, 4, 5})
        );
        const label n = unknowns.size();

        scalarSquareMatrix A(n);
        scalarField x(n);
        for (label row = 0; row < n; ++row)
        {
            const label i = unknowns[row];
            for (label col = 0; col < n; ++col)
            {
                const label j = unknowns[col];
                const tensor& block =
                    i < 3
                  ? (j < 3 ? A11 : A12)
                  : (j < 3 ? A21 : A22);
                A(row, col) = block(i % 3, j % 3);
            }
            x[row] = i < 3 ? b1[i] : b2[i - 3];
        }

        LUsolve(A, x);

        U = Zero;
        omega = Zero;
        for (label row = 0; row < n; ++row)
        {
            const label i = unknowns[row];
            if (i < 3)
            {
                U[i] = x[row];
            }
            else
            {
                omega[i - 3] = x[row];
            }
        }
    }
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fv::interpolated::updateRegions()
{
    const dlmParticleCloud& cloud =
        mesh_.lookupObject<dlmParticleCloud>("particles");
    if (regionMoves_ == cloud.nMoves())
    {
        return;
    }

    // Fixed particles alone (a fixed bed) keep their cells and sums: found
    // at the first step only
    if (regionMoves_ >= 0 && cloud.allFixed())
    {
        regionMoves_ = cloud.nMoves();
        return;
    }

    const label nSearches = regions_.update();
    regions_.setBlendingFactor(blendingFactor_, gapBlending_);
    forcedCellOperators_.setCells(forcedCells());

    if (debug)
    {
        label nForced = 0;
        for (const DynamicList<label>& cells : regions_.cells())
        {
            nForced += cells.size();
        }
        Info<< type() << ": " << returnReduce(nForced, sumOp<label>())
            << " forced cells, "
            << returnReduce(sum(regions_.leftToFlow()), sumOp<label>())
            << " left to the flow, found in " << nSearches << " searches"
            << endl;
    }

    if (forceFollowsParticles_)
    {
        moveForceWithParticles();
    }
    restrictForce();
    heldForce_ = force_.primitiveField();
    sumRegionGeometry();
    regionMoves_ = cloud.nMoves();
}


void Foam::fv::interpolated::sumRegionGeometry()
{
    const dlmParticleCloud& cloud =
        mesh_.lookupObject<dlmParticleCloud>("particles");
    const PtrList<dlmParticle>& particles = cloud.particles();
    const vectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();
    const scalarField& rho = cloud.rho();

    geometricSums_.setSize(nGeometricSums*particles.size());
    geometricSums_ = Zero;
    forAll(particles, i)
    {
        const dlmParticle& p = particles[i];
        const point& X = p.position();
        scalar* s = &geometricSums_[nGeometricSums*i];

        const DynamicList<label>& cells = regions_.cells()[i];
        forAll(cells, k)
        {
            const label celli = cells[k];
            const scalar m = rho[celli]*V[celli];
            const scalar a = regions_.weights()[i][k];
            const vector& q = regions_.arms()[i][k];
            const vector r(C[celli] - X);
            s[gA11] += m*a;
            addVector(s + gMq, m*q);
            addVector(s + gMar, m*a*r);
            addTensor(s + gA22, m*((r & q)*tensor::I - q*r));
        }

        const DynamicList<label>& covered = cloud.cells(i);
        const DynamicList<scalar>& fractions = cloud.fractions(i);
        forAll(covered, k)
        {
            const label celli = covered[k];
            const scalar m = p.density()*fractions[k]*V[celli];
            const vector r(C[celli] - X);
            s[gMass] += m;
            s[gVolume] += fractions[k]*V[celli];
            const symmTensor J(m*(magSqr(r)*symmTensor::I - sqr(r)));
            for (direction d = 0; d < 6; ++d)
            {
                s[gInertia + d] += J[d];
            }
        }
    }
    cloud.images().reduceSums(geometricSums_, nGeometricSums);
}


void Foam::fv::interpolated::moveForceWithParticles()
{
    const PtrList<dlmParticle>& particles =
        mesh_.lookupObject<dlmParticleCloud>("particles").particles();

    // The particles are the same on every rank, and so is this choice
    bool moved = false;
    for (const dlmParticle& p : particles)
    {
        moved = moved
         || (
                p.isFree()
             && (
                    magSqr(p.stepDisplacement()) > 0
                 || magSqr(p.stepRotation().v()) > 0
                )
            );
    }
    if (!moved)
    {
        return;
    }

    // Held particles keep their force on the cells: their inside cells
    // are held implicitly in every solution, and a prescribed sphere's
    // force moved with it took its flow 0.3 % off the held sphere's
    force_.correctBoundaryConditions();
    const tensorField gradForce(forcedCellOperators_.grad(force_));
    const vectorField carried
    (
        UIndirectList<vector>(force_, forcedCellOperators_.cells())()
    );
    vectorField& f = force_.primitiveFieldRef();
    const vectorField& C = mesh_.C();

    label k = 0;
    forAll(particles, i)
    {
        const dlmParticle& p = particles[i];
        if (!p.isFree())
        {
            k += regions_.cells()[i].size();
            continue;
        }
        const tensor turn(p.stepRotation().R());
        for (const label celli : regions_.cells()[i])
        {
            // From the cell centre to where the particle's material point
            // now there was a step ago; the force there, turned with the
            // particle
            const vector arm(C[celli] - p.position());
            const vector back((arm & turn) - arm - p.stepDisplacement());
            f[celli] = turn & (carried[k] + (back & gradForce[k]));
            ++k;
        }
    }
}


Foam::labelList Foam::fv::interpolated::forcedCells() const
{
    label n = 0;
    for (const DynamicList<label>& cells : regions_.cells())
    {
        n += cells.size();
    }
    labelList forced(n);
    n = 0;
    for (const DynamicList<label>& cells : regions_.cells())
    {
        for (const label celli : cells)
        {
            forced[n++] = celli;
        }
    }
    return forced;
}


void Foam::fv::interpolated::restrictForce()
{
    const PtrList<dlmParticle>& particles =
        mesh_.lookupObject<dlmParticleCloud>("particles").particles();
    vectorField& f = force_.primitiveFieldRef();

    boolList forced(mesh_.nCells(), false);
    forAll(particles, i)
    {
        for (const label celli : regions_.cells()[i])
        {
            forced[celli] = true;
        }
    }
    forAll(f, celli)
    {
        if (!forced[celli])
        {
            f[celli] = Zero;
        }
    }

    removeNetForce();
}


void Foam::fv::interpolated::removeNetForce()
{
    const dlmParticleCloud& cloud =
        mesh_.lookupObject<dlmParticleCloud>("particles");
    const PtrList<dlmParticle>& particles = cloud.particles();
    const vectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();
    const scalarField& rho = cloud.rho();
    vectorField& f = force_.primitiveFieldRef();

    scalarList sums(nRestrictSums*particles.size(), Zero);
    forAll(particles, i)
    {
        scalar* s = &sums[nRestrictSums*i];
        const point& X = particles[i].position();
        for (const label celli : regions_.cells()[i])
        {
            const scalar m = rho[celli]*V[celli];
            const vector r(C[celli] - X);
            s[kMass] += m;
            addVector(s + kFirst, m*r);
            addTensor(s + kSecond, m*(magSqr(r)*tensor::I - r*r));
            addVector(s + kForce, V[celli]*f[celli]);
            addVector(s + kTorque, V[celli]*(r ^ f[celli]));
        }
    }
    cloud.images().reduceSums(sums, nRestrictSums);

    forAll(particles, i)
    {
        const scalar* s = &sums[nRestrictSums*i];
        if (!particles[i].isFree() || s[kMass] <= 0)
        {
            continue;
        }

        vector a, beta;
        solveRigid
        (
            s[kMass]*tensor::I,
            -crossMatrix(sumVector(s + kFirst)),
            crossMatrix(sumVector(s + kFirst)),
            sumTensor(s + kSecond),
            sumVector(s + kForce),
            sumVector(s + kTorque),
            cloud.twoD(),
            a,
            beta
        );

        const point& X = particles[i].position();
        for (const label celli : regions_.cells()[i])
        {
            f[celli] -= rho[celli]*(a + (beta ^ (C[celli] - X)));
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fv::interpolated::interpolated
(
    const word& optionName,
    const dictionary& coeffs,
    const fvMesh& mesh
)
:
    mixedCellTreatment(optionName, mesh),
    forceRelaxation_(1),
    implicitHold_(10),
    gapBlending_(0),
    boundaryLayerSlip_(false),
    forceFollowsParticles_(true),
    viscosity_(0),
    force_
    (
        IOobject
        (
            "rigidForce",
            mesh.time().timeName(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedVector(dimDensity*dimAcceleration, Zero)
    ),
    heldForce_(force_.primitiveField()),
    holdRate_(mesh.nCells(), Zero),
    holdTarget_(mesh.nCells(), Zero),
    appliedForce_(mesh.nCells(), Zero),
    blendingFactor_
    (
        IOobject
        (
            "UBlendingFactor",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh,
        dimensionedScalar("one", dimless, 1)
    ),
    regions_(mesh),
    regionMoves_(-1),
    forcedCellOperators_(mesh)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fv::interpolated::read(const dictionary& coeffs)
{
    forceRelaxation_ = coeffs.getOrDefault<scalar>("forceRelaxation", 1);
    implicitHold_ = coeffs.getOrDefault<scalar>("implicitHold", 10);
    gapBlending_ = coeffs.getOrDefault<scalar>("gapBlending", 0);
    boundaryLayerSlip_ = coeffs.getOrDefault<bool>("boundaryLayerSlip", false);
    forceFollowsParticles_ =
        coeffs.getOrDefault<bool>("forceFollowsParticles", true);
    if (boundaryLayerSlip_)
    {
        const IOdictionary& transport =
            mesh_.lookupObject<IOdictionary>("transportProperties");
        viscosity_ = dimensionedScalar("nu", dimViscosity, transport).value();
    }
    if (forceRelaxation_ < 0 || forceRelaxation_ > 1)
    {
        FatalIOErrorInFunction(coeffs)
            << "forceRelaxation " << forceRelaxation_ << " of fvOption "
            << optionName_ << " is outside [0, 1]" << exit(FatalIOError);
    }
    if (implicitHold_ < 0)
    {
        FatalIOErrorInFunction(coeffs)
            << "implicitHold " << implicitHold_ << " of fvOption "
            << optionName_ << " is negative" << exit(FatalIOError);
    }
    if (gapBlending_ < 0 || gapBlending_ > 1)
    {
        FatalIOErrorInFunction(coeffs)
            << "gapBlending " << gapBlending_ << " of fvOption "
            << optionName_ << " is outside [0, 1]" << exit(FatalIOError);
    }
}


void Foam::fv::interpolated::addForce(DimensionedField<vector, volMesh>& source)
{
    updateRegions();
    heldForce_ = force_.primitiveField();
    source += force_();
}


bool Foam::fv::interpolated::predictsContacts() const
{
    return true;
}


void Foam::fv::interpolated::constrain(fvMatrix<vector>& eqn)
{
    updateRegions();
    momentum_.reset(new fvMatrix<vector>(eqn));

    holdRate_ = 0;
    if (implicitHold_ <= 0)
    {
        return;
    }

    // The held term c (u* - u), with u* the projected velocity, vanishes
    // at convergence; c scales with the cell's coupling to its neighbours,
    // not with 1/deltaT, so that the steady state does not depend on the
    // time step
    const dlmParticleCloud& cloud =
        mesh_.lookupObject<dlmParticleCloud>("particles");
    scalarField offDiagonal(mesh_.nCells(), Zero);
    eqn.sumMagOffDiag(offDiagonal);
    forAll(eqn.psi().boundaryField(), patchi)
    {
        // Neighbours across processor and periodic faces count as well
        if (eqn.psi().boundaryField()[patchi].coupled())
        {
            const labelUList& faceCells = mesh_.boundary()[patchi].faceCells();
            const vectorField& coeffs = eqn.boundaryCoeffs()[patchi];
            forAll(faceCells, facei)
            {
                offDiagonal[faceCells[facei]] += mag(cmptAv(coeffs[facei]));
            }
        }
    }
    const vectorField& u = eqn.psi().primitiveField();
    forAll(cloud.particles(), i)
    {
        if (cloud.particles()[i].isFree())
        {
            continue;
        }
        for (const label celli : regions_.cells()[i])
        {
            if (regions_.insideOf()[celli] >= 0)
            {
                const scalar c = implicitHold_*offDiagonal[celli];
                eqn.diag()[celli] += c;
                eqn.source()[celli] += c*u[celli];
                holdRate_[celli] = c/mesh_.V()[celli];
                holdTarget_[celli] = u[celli];
            }
        }
    }
}


void Foam::fv::interpolated::correct(volVectorField& U)
{
    updateRegions();

    if (!momentum_.valid())
    {
        FatalErrorInFunction
            << "fvOption " << optionName_ << ": the velocity is projected"
            << " before the momentum equation was constrained" << nl
            << "    (the solver must call fvOptions.constrain(UEqn) before"
            << " fvOptions.correct(U))" << exit(FatalError);
    }

    dlmParticleCloud& cloud =
        mesh_.lookupObjectRef<dlmParticleCloud>("particles");
    PtrList<dlmParticle>& particles = cloud.particles();

    const vectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();
    const scalarField& rho = cloud.rho();
    vectorField& u = U.primitiveFieldRef();
    vectorField& f = force_.primitiveFieldRef();

    const vector gravity(mixedCellTreatment::gravity(mesh_));
    const scalar rhoFluid = cloud.rhoFluid().value();
    const scalar deltaT = mesh_.time().deltaTValue();
    const bool twoD = cloud.twoD();

    // Velocity of the samples of each forced cell
    const List<vectorField> sampled(regions_.sampledVelocities(U));

    // Target velocity of forced cell k of particle i for rigid motion
    // (Up, omega)
    auto target = [&]
    (
        const label i,
        const label k,
        const vector& Up,
        const vector& omega
    ) -> vector
    {
        const vector rigid
        (
            regions_.weights()[i][k]*Up + (omega ^ regions_.arms()[i][k])
        );
        if (boundaryLayerSlip_)
        {
            return (rigidParts_[i][k] & rigid) + slipSampled_[i][k];
        }
        return rigid + sampled[i][k];
    };

    // With boundary-layer slip, the tangential target of a profile cell
    // takes less of the rigid motion (rigid part A) and more of the flow
    // beyond it, so the balance's blocks carry A and are summed at each
    // correction
    if (boundaryLayerSlip_)
    {
        setSlipParts(sampled);
    }
    const label nSums = nVelocitySums + (boundaryLayerSlip_ ? nSlipSums : 0);

    scalarList sums(nSums*particles.size(), Zero);
    forAll(particles, i)
    {
        const point& X = particles[i].position();
        scalar* s = &sums[nSums*i];

        const DynamicList<label>& cells = regions_.cells()[i];
        forAll(cells, k)
        {
            const label celli = cells[k];
            const scalar m = rho[celli]*V[celli];
            const vector r(C[celli] - X);

            if (boundaryLayerSlip_)
            {
                const tensor A(rigidParts_[i][k]);
                const tensor qCross(crossMatrix(regions_.arms()[i][k]));
                const scalar a = regions_.weights()[i][k];
                const vector d(u[celli] - slipSampled_[i][k]);
                addVector(s + vB1, m*d);
                addTensor(s + sA11, m*a*A);
                addTensor(s + sA12, -m*(A & qCross));

                // The rotation from the normal parts of the profile cells
                // (and the inside cells): their tangential parts follow
                // the flow, and their angular momentum charged to the
                // particle, with only its own interior's inertia left,
                // spun a rising pebble up to 300 rad/s
                const tensor Q(rotationParts_[i][k]);
                const vector dRotation(Q & (u[celli] - sampled[i][k]));
                addVector(s + vB2, m*(r ^ dRotation));
                addTensor(s + sA21, m*a*(crossMatrix(r) & Q));
                addTensor(s + sA22, -m*(crossMatrix(r) & Q & qCross));
            }
            else
            {
                const vector d(u[celli] - sampled[i][k]);
                addVector(s + vB1, m*d);
                addVector(s + vB2, m*(r ^ d));
            }
        }
    }
    cloud.images().reduceSums(sums, nSums);

    // The free particles' velocities from the momentum balance, and the
    // error of each forced cell against its target (zero elsewhere).
    // Targets from the provisional velocity first: samples may be forced
    // cells of another particle
    volVectorField error
    (
        IOobject
        (
            "rigidError",
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        U
    );
    error.primitiveFieldRef() = Zero;
    projectedVelocity_.setSize(particles.size());
    projectedOmega_.setSize(particles.size());
    forAll(particles, i)
    {
        dlmParticle& p = particles[i];
        const scalar* g = &geometricSums_[nGeometricSums*i];
        const scalar* s = &sums[nSums*i];

        // A held particle (a periodic image reaching just into the mesh,
        // say) may force no cell; a free one could not move
        if (g[gA11] <= 0 && p.isFree())
        {
            failUncovered(p, "cell centre");
        }

        if (p.isFree())
        {
            // The balance's blocks: geometric, or with boundary-layer
            // slip summed at this correction
            scalar massRatio;
            tensor A11, A12, A21, A22;
            if (boundaryLayerSlip_)
            {
                A11 = sumTensor(s + sA11);
                A12 = sumTensor(s + sA12);
                A21 = sumTensor(s + sA21);
                A22 = sumTensor(s + sA22);
                massRatio = tr(A11)/(3*g[gMass]);
            }
            else
            {
                A11 = g[gA11]*tensor::I;
                A12 = -crossMatrix(sumVector(g + gMq));
                A21 = crossMatrix(sumVector(g + gMar));
                A22 = sumTensor(g + gA22);
                massRatio = g[gA11]/g[gMass];
            }
            vector Up, omega;
            solveRigid
            (
                A11,
                A12,
                A21,
                A22,
                sumVector(s + vB1),
                sumVector(s + vB2),
                twoD,
                Up,
                omega
            );
            p.setVelocities(Up, omega);

            // The mass and inertia the forced cells move with the particle
            const scalar ownInertia =
                g[gInertia] + g[gInertia + 3] + g[gInertia + 5];
            p.setCoupledInertia
            (
                massRatio,
                twoD ? A22.zz()/g[gInertia + 5] : tr(A22)/ownInertia
            );
        }
        projectedVelocity_[i] = p.velocity();
        projectedOmega_[i] = p.angularVelocity();

        const DynamicList<label>& cells = regions_.cells()[i];
        forAll(cells, k)
        {
            error[cells[k]] =
                target(i, k, p.velocity(), p.angularVelocity()) - u[cells[k]];
        }
    }
    error.correctBoundaryConditions();

    // The force that would have made this solution the targets: the
    // momentum equation's operator applied to the error (extended by zero),
    // and the implicit hold's force, which acted in this solution
    const vectorField change
    (
        forcedCellOperators_.product(momentum_(), holdRate_, error)
    );
    label k = 0;
    forAll(particles, i)
    {
        const bool held = !particles[i].isFree();
        for (const label celli : regions_.cells()[i])
        {
            f[celli] = heldForce_[celli] + forceRelaxation_*change[k++];
            if (held)
            {
                appliedForce_[celli] =
                    heldForce_[celli]
                  + holdRate_[celli]*(holdTarget_[celli] - u[celli])
                  + rho[celli]*error[celli]/deltaT;
            }
            u[celli] += error[celli];
        }
    }

    // The force is internal to a free particle's mixture (it changed in
    // the forced cells only)
    removeNetForce();

    setLoads(gravity, rhoFluid, deltaT, twoD);
}


void Foam::fv::interpolated::setSlipParts(const List<vectorField>& sampled)
{
    const dlmParticleCloud& cloud =
        mesh_.lookupObject<dlmParticleCloud>("particles");
    const PtrList<dlmParticle>& particles = cloud.particles();
    const vectorField& C = mesh_.C();
    const List<boundBox>& cellBoxes = cloud.cellBoxes();
    const scalar age = max(mesh_.time().value(), 0);

    // A particle lighter than its added mass (a sphere's: half the
    // displaced fluid's; a cylinder's in 2D: all of it) keeps no-slip
    // profiles: slipping, the fluid next to it is coupled to it only
    // through the flow, a step late, and a sphere of a tenth of water's
    // density rising with slip started to oscillate and blew up
    const scalar addedMassRatio = cloud.twoD() ? 1 : 0.5;
    const scalar rhoFluid = cloud.rhoFluid().value();

    rigidParts_.setSize(particles.size());
    rotationParts_.setSize(particles.size());
    slipSampled_.setSize(particles.size());
    forAll(particles, i)
    {
        const dlmParticle& p = particles[i];
        const scalar length = 2*p.shape().boundingRadius();
        const DynamicList<label>& cells = regions_.cells()[i];
        symmTensorField& rigidPart = rigidParts_[i];
        symmTensorField& rotationPart = rotationParts_[i];
        vectorField& slipSampled = slipSampled_[i];
        rigidPart.setSize(cells.size());
        rotationPart.setSize(cells.size());
        slipSampled = sampled[i];
        if (p.mixtureDensity(rhoFluid) < addedMassRatio*rhoFluid)
        {
            rigidPart = symmTensor::I;
            rotationPart = symmTensor::I;
            if (!keptNoSlip_.found(p.name()))
            {
                keptNoSlip_.insert(p.name());
                WarningInFunction
                    << "boundaryLayerSlip of fvOption " << optionName_
                    << ": particle " << p.name() << " (density "
                    << p.mixtureDensity(rhoFluid) << ") is lighter than "
                    << addedMassRatio << " times the fluid (its added mass):"
                    << " it keeps no-slip profiles" << endl;
            }
            continue;
        }
        forAll(cells, k)
        {
            const scalar a = regions_.weights()[i][k];
            if (a >= 1 || a <= 0)
            {
                rigidPart[k] = symmTensor::I;
                rotationPart[k] = symmTensor::I;
                continue;
            }
            const label celli = cells[k];
            const symmTensor normalPart(sqr(regions_.normals()[i][k]));
            const symmTensor tangentialPart(symmTensor::I - normalPart);

            // The flow beyond the cell, extrapolated to it along the
            // profile (whose samples' coefficients sum to 1 - a), slips
            // along the surface at this speed
            const vector outer(sampled[i][k]/(1 - a));
            const scalar slipSpeed = mag
            (
                tangentialPart
              & (
                    outer - p.velocity()
                  - (p.angularVelocity() ^ (C[celli] - p.position()))
                )
            );

            // The no-slip share: 1 where the layer is a cell or thicker
            // (the cell's own size: on a refined mesh the cells at the
            // surface are the smallest). The layer grows as sqrt(nu t)
            // from the flow's start until the flow has passed the
            // particle's length
            scalar h = 0;
            for (direction d = 0; d < vector::nComponents; ++d)
            {
                if (mesh_.solutionD()[d] == 1)
                {
                    h = max(h, cellBoxes[celli].span()[d]);
                }
            }
            const scalar layerTime =
                slipSpeed*age > length ? length/slipSpeed : age;
            const scalar noSlip =
                viscosity_*layerTime >= sqr(h)
              ? 1
              : sqrt(viscosity_*layerTime)/h;

            // The tangential target blends the no-slip profile's, by
            // noSlip, with the slip's: the solid share b rigid, the rest
            // the flow beyond, extrapolated to the cell
            const scalar b = regions_.rigidShares()[i][k];
            const scalar aTangential = b + noSlip*(a - b);
            rigidPart[k] = normalPart + (aTangential/a)*tangentialPart;
            rotationPart[k] =
                normalPart + (b + (1 - b)*noSlip)*tangentialPart;
            slipSampled[k] =
                (normalPart & sampled[i][k])
              + (1 - aTangential)*(tangentialPart & outer);
        }
    }
}


void Foam::fv::interpolated::setLoads
(
    const vector& gravity,
    const scalar rhoFluid,
    const scalar deltaT,
    const bool twoD
)
{
    dlmParticleCloud& cloud =
        mesh_.lookupObjectRef<dlmParticleCloud>("particles");
    PtrList<dlmParticle>& particles = cloud.particles();
    const vectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();
    const vectorField& f = appliedForce_;

    // The force holding each held particle
    scalarList holdSums(6*particles.size(), Zero);
    forAll(particles, i)
    {
        if (particles[i].isFree())
        {
            continue;
        }
        const point& X = particles[i].position();
        scalar* s = &holdSums[6*i];
        for (const label celli : regions_.cells()[i])
        {
            addVector(s, V[celli]*f[celli]);
            addVector(s + 3, V[celli]*((C[celli] - X) ^ f[celli]));
        }
    }
    cloud.images().reduceSums(holdSums, 6);

    forAll(particles, i)
    {
        dlmParticle& p = particles[i];
        const scalar* g = &geometricSums_[nGeometricSums*i];
        const scalar M = g[gMass];
        symmTensor I;
        for (direction d = 0; d < 6; ++d)
        {
            I[d] = g[gInertia + d];
        }
        const vector dOmega(p.angularVelocity() - p.angularVelocity0());

        vector F, T;
        if (p.isFree())
        {
            F =
                M*(p.velocity() - p.velocity0())/deltaT
              - p.density()*g[gVolume]*gravity;
            T = (I & dOmega)/deltaT;
        }
        else
        {
            F =
                g[gA11]*(p.velocity() - p.velocity0())/deltaT
              - sumVector(&holdSums[6*i])
              - rhoFluid*g[gVolume]*gravity;
            T = (I & dOmega)/deltaT - sumVector(&holdSums[6*i + 3]);
        }
        if (twoD)
        {
            F.z() = 0;
            T = vector(0, 0, T.z());
        }
        p.setLoads(F, T);
    }
}


void Foam::fv::interpolated::holdRigid
(
    volVectorField& U,
    scalarField& held
)
{
    const dlmParticleCloud& cloud =
        mesh_.lookupObject<dlmParticleCloud>("particles");
    const PtrList<dlmParticle>& particles = cloud.particles();
    vectorField& u = U.primitiveFieldRef();

    updateRegions();
    const List<vectorField> sampled(regions_.sampledVelocities(U));
    forAll(particles, i)
    {
        const dlmParticle& p = particles[i];
        const DynamicList<label>& cells = regions_.cells()[i];
        forAll(cells, k)
        {
            u[cells[k]] =
                regions_.weights()[i][k]*p.velocity()
              + (p.angularVelocity() ^ regions_.arms()[i][k])
              + sampled[i][k];
            held[cells[k]] = 1;
        }
    }
}


bool Foam::fv::interpolated::followContacts(vectorField& change) const
{
    const dlmParticleCloud& cloud =
        mesh_.lookupObject<dlmParticleCloud>("particles");
    const PtrList<dlmParticle>& particles = cloud.particles();

    bool changed = false;
    forAll(projectedVelocity_, i)
    {
        const dlmParticle& p = particles[i];
        const vector dU(p.velocity() - projectedVelocity_[i]);
        const vector dOmega(p.angularVelocity() - projectedOmega_[i]);
        if (!p.isFree() || (dU == vector::zero && dOmega == vector::zero))
        {
            continue;
        }
        changed = true;
        const DynamicList<label>& cells = regions_.cells()[i];
        forAll(cells, k)
        {
            const vector rigidChange
            (
                regions_.weights()[i][k]*dU + (dOmega ^ regions_.arms()[i][k])
            );
            change[cells[k]] +=
                boundaryLayerSlip_
              ? (rigidParts_[i][k] & rigidChange)
              : rigidChange;
        }
    }
    return changed;
}


void Foam::fv::interpolated::markRigidExcess(boolList& rigid) const
{
    for (const DynamicList<label>& cells : regions_.cells())
    {
        for (const label celli : cells)
        {
            rigid[celli] = true;
        }
    }
}


void Foam::fv::interpolated::updateMesh()
{
    const label nCells = mesh_.nCells();
    heldForce_ = force_.primitiveField();
    holdRate_.setSize(nCells);
    holdRate_ = 0;
    holdTarget_.setSize(nCells);
    holdTarget_ = Zero;
    appliedForce_.setSize(nCells);
    appliedForce_ = Zero;
    momentum_.clear();
    regions_.updateMesh();
    regionMoves_ = -1;
    updateRegions();
}


// ************************************************************************* //
