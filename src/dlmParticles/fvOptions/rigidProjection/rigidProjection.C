/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "rigidProjection.H"
#include "dlmParticleCloud.H"
#include "uniformDimensionedFields.H"
#include "fvMatrices.H"
#include "fvmDdt.H"
#include "scalarMatrices.H"
#include "cpuTime.H"
#include "fvcFlux.H"
#include "HashSet.H"
#include "OStringStream.H"
#include "IOmanip.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fv
{
    defineTypeNameAndDebug(rigidProjection, 0);
    addToRunTimeSelectionTable(option, rigidProjection, dictionary);
}
}

const Foam::Enum<Foam::fv::rigidProjection::mixedCellsType>
Foam::fv::rigidProjection::mixedCellsTypeNames
({
    { mixedCellsType::interpolated, "interpolated" },
    { mixedCellsType::massWeighted, "massWeighted" },
    { mixedCellsType::volumeWeighted, "volumeWeighted" },
});


namespace
{
    // Layout of the per-particle sums of the blended projection, reduced
    // over processors
    enum sumIndex
    {
        iMass = 0,          // sum w
        iFirst = 1,         // sum w r (3)
        iMomentum = 4,      // sum w u (3)
        iAngular = 7,       // sum w r x u (3)
        iSecond = 10,       // sum w r r (6, symmetric)
        iVolume = 16,       // sum f V
        nSums = 17
    };

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

    // and sums of the velocity and the held force, at each correction
    enum velocitySumIndex
    {
        vB1 = 0,            // sum m (u - u_samples) (3)
        vB2 = 3,            // sum m r x (u - u_samples) (3)
        vForce = 6,         // sum V f (3)
        vTorque = 9,        // sum V r x f (3)
        nVelocitySums = 12
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


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fv::rigidProjection::checkKeywords(const dictionary& dict) const
{
    const auto check = [this](const dictionary& d, const wordHashSet& known)
    {
        for (const entry& e : d)
        {
            if (!known.found(e.keyword()))
            {
                FatalIOErrorInFunction(d)
                    << "Unknown keyword '" << e.keyword() << "' for fvOption "
                    << name_ << " (type " << modelType_ << ")." << nl
                    << "Known keywords: " << flatOutput(known.sortedToc())
                    << exit(FatalIOError);
            }
        }
    };

    // fv::option reads type, libs, active, log and the optional
    // <type>Coeffs sub-dictionary, which then holds the projection's own
    const wordHashSet own
    ({
        "mixedCells", "forceRelaxation", "implicitHold", "gapBlending"
    });
    const word coeffsName(modelType_ + "Coeffs");
    wordHashSet known({"type", "libs", "active", "log", coeffsName});

    const dictionary* coeffsPtr = dict.findDict(coeffsName);
    if (coeffsPtr)
    {
        check(*coeffsPtr, own);
    }
    else
    {
        known += own;
    }
    check(dict, known);
}


void Foam::fv::rigidProjection::failUncovered
(
    const dlmParticle& p,
    const word& what
) const
{
    const dlmParticleCloud& cloud =
        mesh_.lookupObject<dlmParticleCloud>("particles");
    const point& X = p.position();

    // The size of the cell that holds the centre, on the processor that has
    // it; -1 if none does
    scalar h = -1;
    const label celli = mesh_.findCell(X);
    if (celli >= 0)
    {
        const vector span(cloud.cellBoxes()[celli].span());
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (mesh_.solutionD()[d] == 1)
            {
                h = max(h, span[d]);
            }
        }
    }
    reduce(h, maxOp<scalar>());
    const bool outside = h < 0;
    if (outside)
    {
        h = cloud.cellSizeMax();
    }

    const scalar D = 2*p.shape().boundingRadius();
    const scalar speed = mag(p.velocity());
    const scalar minCells = Foam::sqrt(scalar(p.shape().nDimensions()));

    OStringStream cause;
    cause.precision(4);
    if (outside)
    {
        cause
            << "Its centre is outside the mesh " << mesh_.bounds()
            << ": it left the mesh. A particle leaves the mesh when an"
            << " overlap throws it out, at an absurd velocity, or where no"
            << " wall holds it (meshWalls false): check the particles'"
            << " overlaps, velocities and walls (constant/particleProperties)"
            << " and gravity (constant/g).";
    }
    else
    {
        cause
            << "It is under-resolved: below " << minCells << " cells per"
            << " diameter a particle may hold no cell centre, and the method"
            << " needs several. Refine the mesh or enlarge the particle"
            << " (constant/particleProperties).";
    }

    FatalErrorInFunction
        << setprecision(4)
        << "Particle " << p.name() << " covers no " << what.c_str()
        << ": centre " << X << ", diameter " << D << " = " << D/h
        << " cells of " << h << ", speed " << speed << " ("
        << speed*mesh_.time().deltaTValue()/h << " cells per step)." << nl
        << cause.str().c_str() << exit(FatalError);
}


Foam::vector Foam::fv::rigidProjection::gravity() const
{
    const word name("g");
    if (mesh_.time().foundObject<uniformDimensionedVectorField>(name))
    {
        return
            mesh_.time().lookupObject<uniformDimensionedVectorField>(name)
           .value();
    }
    return Zero;
}


void Foam::fv::rigidProjection::updateRegions()
{
    const dlmParticleCloud& cloud =
        mesh_.lookupObject<dlmParticleCloud>("particles");
    if
    (
        mixedCells_ != mixedCellsType::interpolated
     || regionMoves_ == cloud.nMoves()
    )
    {
        return;
    }

    // Fixed particles alone (a fixed bed) keep their cells and sums: found
    // at the first step only
    bool allFixed = true;
    for (const dlmParticle& p : cloud.particles())
    {
        allFixed = allFixed && p.motion() == dlmParticle::motionType::fixed;
    }
    if (regionMoves_ >= 0 && allFixed)
    {
        regionMoves_ = cloud.nMoves();
        return;
    }

    const label nSearches = regions_.update();
    regions_.setBlendingFactor(blendingFactor_, gapBlending_);

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

    restrictForce();
    heldForce_ = force_.primitiveField();
    sumRegionGeometry();
    regionMoves_ = cloud.nMoves();
}


void Foam::fv::rigidProjection::sumRegionGeometry()
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
    Pstream::listCombineGather(geometricSums_, plusEqOp<scalar>());
    Pstream::listCombineScatter(geometricSums_);
}


void Foam::fv::rigidProjection::restrictForce()
{
    const dlmParticleCloud& cloud =
        mesh_.lookupObject<dlmParticleCloud>("particles");
    const PtrList<dlmParticle>& particles = cloud.particles();
    const vectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();
    const scalarField& rho = cloud.rho();
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
    Pstream::listCombineGather(sums, plusEqOp<scalar>());
    Pstream::listCombineScatter(sums);

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

Foam::fv::rigidProjection::rigidProjection
(
    const word& name,
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    option(name, modelType, dict, mesh),
    mixedCells_(mixedCellsType::interpolated),
    forceRelaxation_(1),
    implicitHold_(10),
    gapBlending_(0),
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
    ddtRate_(0),
    ddtRateTimeIndex_(-1)
{
    fieldNames_.setSize(1, "U");
    applied_.setSize(1, false);

    if (mesh.foundObject<dlmParticleCloud>("particles"))
    {
        recordFractions(mesh.lookupObject<dlmParticleCloud>("particles"));
    }

    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::fv::rigidProjection::read(const dictionary& dict)
{
    if (option::read(dict))
    {
        checkKeywords(dict);
        mixedCells_ = mixedCellsTypeNames.getOrDefault
        (
            "mixedCells",
            coeffs_,
            mixedCellsType::interpolated
        );
        forceRelaxation_ = coeffs_.getOrDefault<scalar>("forceRelaxation", 1);
        implicitHold_ = coeffs_.getOrDefault<scalar>("implicitHold", 10);
        gapBlending_ = coeffs_.getOrDefault<scalar>("gapBlending", 0);
        if (forceRelaxation_ < 0 || forceRelaxation_ > 1)
        {
            FatalIOErrorInFunction(coeffs_)
                << "forceRelaxation " << forceRelaxation_ << " of fvOption "
                << name_ << " is outside [0, 1]" << exit(FatalIOError);
        }
        if (implicitHold_ < 0)
        {
            FatalIOErrorInFunction(coeffs_)
                << "implicitHold " << implicitHold_ << " of fvOption "
                << name_ << " is negative" << exit(FatalIOError);
        }
        if (gapBlending_ < 0 || gapBlending_ > 1)
        {
            FatalIOErrorInFunction(coeffs_)
                << "gapBlending " << gapBlending_ << " of fvOption "
                << name_ << " is outside [0, 1]" << exit(FatalIOError);
        }
        force_.writeOpt() =
            mixedCells_ == mixedCellsType::interpolated
          ? IOobject::AUTO_WRITE
          : IOobject::NO_WRITE;
        return true;
    }

    return false;
}


void Foam::fv::rigidProjection::addSup
(
    const volScalarField& rho,
    fvMatrix<vector>& eqn,
    const label fieldi
)
{
    const cpuTime timer;
    dlmParticleCloud& cloud =
        mesh_.lookupObjectRef<dlmParticleCloud>("particles");
    const vector g(gravity());
    const scalar rhoFluid = cloud.rhoFluid().value();

    updateRegions();
    heldForce_ = force_.primitiveField();

    DimensionedField<vector, volMesh> source
    (
        IOobject("rigidSource", mesh_.time().timeName(), mesh_),
        force_()
    );

    forAll(cloud.particles(), i)
    {
        const dlmParticle& p = cloud.particles()[i];
        if (p.isFree())
        {
            // Reduced weight, and the mean contact force and torque of the
            // last step as the prediction of this step's (the particle's
            // motion discounts it, see dlmParticleCloud::move)
            const vector density
            (
                (p.density() - rhoFluid)*g + p.contactForce()/p.shape().volume()
            );
            const vector spin(p.spinPerUnitDensity(p.contactTorque()));
            const vectorField& C = mesh_.C();
            const DynamicList<label>& cells = cloud.cells(i);
            const DynamicList<scalar>& fractions = cloud.fractions(i);
            forAll(cells, k)
            {
                source[cells[k]] +=
                    fractions[k]
                   *(density + (spin ^ (C[cells[k]] - p.position())));
            }
        }
    }

    eqn += source;
    if (mixedCells_ == mixedCellsType::interpolated)
    {
        // The follow step gives the forced cells the contacts' change
        cloud.setContactPredicted();
    }
    cloud.addWorkTime(timer.elapsedCpuTime());
}


void Foam::fv::rigidProjection::constrain
(
    fvMatrix<vector>& eqn,
    const label fieldi
)
{
    if (implicitHold_ <= 0 || mixedCells_ != mixedCellsType::interpolated)
    {
        return;
    }

    // The held term c (u* - u), with u* the projected velocity, vanishes
    // at convergence; c scales with the cell's coupling to its neighbours,
    // not with 1/deltaT, so that the steady state does not depend on the
    // time step
    const dlmParticleCloud& cloud =
        mesh_.lookupObject<dlmParticleCloud>("particles");
    holdRate_ = 0;
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
            }
        }
    }
}


Foam::scalar Foam::fv::rigidProjection::ddtRate(const volVectorField& U)
{
    const label timeIndex = mesh_.time().timeIndex();
    if (ddtRateTimeIndex_ != timeIndex)
    {
        // Every processor takes the same value, also one without cells
        ddtRate_ = 0;
        if (mesh_.nCells() > 0)
        {
            tmp<fvVectorMatrix> ddtU(fvm::ddt(U));
            ddtRate_ = ddtU().diag()[0]/mesh_.V()[0];
        }
        reduce(ddtRate_, maxOp<scalar>());
        ddtRateTimeIndex_ = timeIndex;
    }
    return ddtRate_;
}


void Foam::fv::rigidProjection::correct(volVectorField& U)
{
    const cpuTime timer;
    dlmParticleCloud& cloud =
        mesh_.lookupObjectRef<dlmParticleCloud>("particles");
    if (mixedCells_ == mixedCellsType::interpolated)
    {
        updateRegions();
        correctInterpolated(U);
    }
    else
    {
        correctBlended(U);
    }

    U.correctBoundaryConditions();
    cloud.setProjected();
    cloud.addWorkTime(timer.elapsedCpuTime());
}


void Foam::fv::rigidProjection::recordFractions
(
    const dlmParticleCloud& cloud
)
{
    followedCells_.setSize(cloud.nParticles());
    followedFractions_.setSize(cloud.nParticles());
    forAll(followedCells_, body)
    {
        followedCells_[body].clear();
        followedFractions_[body].clear();
    }
    forAll(cloud.particles(), i)
    {
        const label body = cloud.source(i);
        followedCells_[body].append(cloud.cells(i));
        followedFractions_[body].append(cloud.fractions(i));
    }
}


void Foam::fv::rigidProjection::followParticles
(
    volVectorField& U,
    surfaceScalarField& phi
)
{
    const cpuTime timer;
    dlmParticleCloud& cloud =
        mesh_.lookupObjectRef<dlmParticleCloud>("particles");
    const PtrList<dlmParticle>& particles = cloud.particles();
    const scalarField& rho = cloud.rho();
    const scalar rhoFluid = cloud.rhoFluid().value();
    const vectorField& C = mesh_.C();
    const vectorField& u = U.primitiveField();

    volVectorField change
    (
        IOobject("rigidChange", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedVector(dimVelocity, Zero)
    );
    bool changed = false;

    // The contact sub-steps' change of each free particle's velocity since
    // the projection, in its forced cells (found before the move)
    if (mixedCells_ == mixedCellsType::interpolated)
    {
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
                change[cells[k]] +=
                    regions_.weights()[i][k]*dU + (dOmega ^ regions_.arms()[i][k]);
            }
        }
    }

    // The excess mass each particle moved into a cell brings its velocity
    const vectorField followed(u + change.primitiveField());
    scalarField fraction0(mesh_.nCells(), Zero);
    forAll(particles, i)
    {
        const dlmParticle& p = particles[i];
        const scalar excess = p.mixtureDensity(rhoFluid) - rhoFluid;
        const label body = cloud.source(i);
        if (excess <= 0 || body >= followedCells_.size())
        {
            continue;
        }

        // The body's fractions at the last follow step (its images' too)
        forAll(followedCells_[body], k)
        {
            fraction0[followedCells_[body][k]] = followedFractions_[body][k];
        }

        const DynamicList<label>& cells = cloud.cells(i);
        const DynamicList<scalar>& fractions = cloud.fractions(i);
        forAll(cells, k)
        {
            const label celli = cells[k];
            const scalar gained = excess*(fractions[k] - fraction0[celli]);
            if (gained > 0)
            {
                const vector us
                (
                    p.velocity()
                  + (p.angularVelocity() ^ (C[celli] - p.position()))
                );
                change[celli] += gained/rho[celli]*(us - followed[celli]);
                changed = true;
            }
        }

        for (const label celli : followedCells_[body])
        {
            fraction0[celli] = 0;
        }
    }
    recordFractions(cloud);

    if (returnReduce(changed, orOp<bool>()))
    {
        change.correctBoundaryConditions();
        U.primitiveFieldRef() += change.primitiveField();
        U.correctBoundaryConditions();
        phi += fvc::flux(change);
    }
    cloud.addWorkTime(timer.elapsedCpuTime());
}


Foam::fv::rigidProjection* Foam::fv::rigidProjection::find
(
    optionList& options
)
{
    PtrList<option>& list = options;
    for (option& entry : list)
    {
        if (isA<rigidProjection>(entry))
        {
            return &refCast<rigidProjection>(entry);
        }
    }
    return nullptr;
}


void Foam::fv::rigidProjection::holdRigid
(
    volVectorField& U,
    scalarField& held
)
{
    const dlmParticleCloud& cloud =
        mesh_.lookupObject<dlmParticleCloud>("particles");
    const PtrList<dlmParticle>& particles = cloud.particles();
    vectorField& u = U.primitiveFieldRef();
    held = 0;

    if (mixedCells_ == mixedCellsType::interpolated)
    {
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
    else
    {
        const vectorField& C = mesh_.C();
        forAll(particles, i)
        {
            const dlmParticle& p = particles[i];
            const DynamicList<label>& cells = cloud.cells(i);
            const DynamicList<scalar>& fractions = cloud.fractions(i);
            forAll(cells, k)
            {
                const label celli = cells[k];
                const vector us
                (
                    p.velocity()
                  + (p.angularVelocity() ^ (C[celli] - p.position()))
                );
                u[celli] += fractions[k]*(us - u[celli]);
                held[celli] = max(held[celli], fractions[k]);
            }
        }
    }
    U.correctBoundaryConditions();
}


void Foam::fv::rigidProjection::correctInterpolated(volVectorField& U)
{
    dlmParticleCloud& cloud =
        mesh_.lookupObjectRef<dlmParticleCloud>("particles");
    PtrList<dlmParticle>& particles = cloud.particles();

    const vectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();
    const scalarField& rho = cloud.rho();
    vectorField& u = U.primitiveFieldRef();
    vectorField& f = force_.primitiveFieldRef();

    const vector gravity(this->gravity());
    const scalar rhoFluid = cloud.rhoFluid().value();
    const scalar deltaT = mesh_.time().deltaTValue();
    const scalar ddtRate = this->ddtRate(U);
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
        return
            regions_.weights()[i][k]*Up
          + (omega ^ regions_.arms()[i][k])
          + sampled[i][k];
    };

    scalarList sums(nVelocitySums*particles.size(), Zero);
    forAll(particles, i)
    {
        const point& X = particles[i].position();
        scalar* s = &sums[nVelocitySums*i];

        const DynamicList<label>& cells = regions_.cells()[i];
        forAll(cells, k)
        {
            const label celli = cells[k];
            const scalar m = rho[celli]*V[celli];
            const vector r(C[celli] - X);
            const vector d(u[celli] - sampled[i][k]);
            const vector& f = heldForce_[celli];

            addVector(s + vB1, m*d);
            addVector(s + vB2, m*(r ^ d));
            addVector(s + vForce, V[celli]*f);
            addVector(s + vTorque, V[celli]*(r ^ f));

            // The implicitly held cells' part of this correction's change
            // (a held particle's velocity, and so its target, is known)
            if (holdRate_[celli] > 0)
            {
                const dlmParticle& p = particles[i];
                const vector df
                (
                    forceRelaxation_*holdRate_[celli]
                   *(target(i, k, p.velocity(), p.angularVelocity()) - u[celli])
                );
                addVector(s + vForce, V[celli]*df);
                addVector(s + vTorque, V[celli]*(r ^ df));
            }
        }
    }
    Pstream::listCombineGather(sums, plusEqOp<scalar>());
    Pstream::listCombineScatter(sums);

    // Targets from the provisional velocity first: samples may be forced
    // cells of another particle
    List<vectorField> targets(particles.size());
    projectedVelocity_.setSize(particles.size());
    projectedOmega_.setSize(particles.size());
    forAll(particles, i)
    {
        dlmParticle& p = particles[i];
        const scalar* g = &geometricSums_[nGeometricSums*i];
        const scalar* s = &sums[nVelocitySums*i];

        // A held particle (a periodic image reaching just into the mesh,
        // say) may force no cell; a free one could not move
        if (g[gA11] <= 0 && p.isFree())
        {
            failUncovered(p, "cell centre");
        }

        const tensor A11(g[gA11]*tensor::I);
        const tensor A12(-crossMatrix(sumVector(g + gMq)));
        const tensor A21(crossMatrix(sumVector(g + gMar)));
        const tensor A22(sumTensor(g + gA22));
        const vector b1(sumVector(s + vB1));
        const vector b2(sumVector(s + vB2));

        if (p.isFree())
        {
            vector Up, omega;
            solveRigid(A11, A12, A21, A22, b1, b2, twoD, Up, omega);
            p.setVelocities(Up, omega);
        }
        projectedVelocity_[i] = p.velocity();
        projectedOmega_[i] = p.angularVelocity();

        const vector& Up = p.velocity();
        const vector& omega = p.angularVelocity();
        const scalar M = g[gMass];
        symmTensor I;
        for (direction d = 0; d < 6; ++d)
        {
            I[d] = g[gInertia + d];
        }

        vector F, T;
        if (p.isFree())
        {
            F = M*(Up - p.velocity0())/deltaT - p.density()*g[gVolume]*gravity;
            T = (I & (omega - p.angularVelocity0()))/deltaT;
        }
        else
        {
            // Force holding the particle: the carried force and this
            // correction's change, (A x - b) ddtRate and the held cells'
            // part
            const vector holdForce
            (
                sumVector(s + vForce)
              + forceRelaxation_*ddtRate*((A11 & Up) + (A12 & omega) - b1)
            );
            const vector holdTorque
            (
                sumVector(s + vTorque)
              + forceRelaxation_*ddtRate*((A21 & Up) + (A22 & omega) - b2)
            );
            F =
                g[gA11]*(Up - p.velocity0())/deltaT
              - holdForce
              - rhoFluid*g[gVolume]*gravity;
            T = (I & (omega - p.angularVelocity0()))/deltaT - holdTorque;
        }
        if (twoD)
        {
            F.z() = 0;
            T = vector(0, 0, T.z());
        }
        p.setLoads(F, T);

        const DynamicList<label>& cells = regions_.cells()[i];
        targets[i].setSize(cells.size());
        forAll(cells, k)
        {
            targets[i][k] = target(i, k, Up, omega);
        }
    }

    forAll(particles, i)
    {
        const DynamicList<label>& cells = regions_.cells()[i];
        forAll(cells, k)
        {
            const label celli = cells[k];
            f[celli] =
                heldForce_[celli]
              + forceRelaxation_*(rho[celli]*ddtRate + holdRate_[celli])
               *(targets[i][k] - u[celli]);
            u[celli] = targets[i][k];
        }
    }
}


void Foam::fv::rigidProjection::correctBlended(volVectorField& U)
{
    dlmParticleCloud& cloud =
        mesh_.lookupObjectRef<dlmParticleCloud>("particles");
    PtrList<dlmParticle>& particles = cloud.particles();

    const vectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();
    const scalarField& rho = cloud.rho();
    vectorField& u = U.primitiveFieldRef();

    const vector g(gravity());
    const scalar rhoFluid = cloud.rhoFluid().value();
    const scalar deltaT = mesh_.time().deltaTValue();
    const bool twoD = cloud.twoD();

    // Local sums, relative to each particle's own centre
    scalarList sums(nSums*particles.size(), Zero);
    forAll(particles, i)
    {
        const dlmParticle& p = particles[i];
        const DynamicList<label>& cells = cloud.cells(i);
        const DynamicList<scalar>& fractions = cloud.fractions(i);
        scalar* s = &sums[nSums*i];

        forAll(cells, k)
        {
            const label celli = cells[k];
            const scalar b = beta(fractions[k], p.mixtureDensity(rhoFluid), rho[celli]);
            const scalar w = rho[celli]*b*V[celli];
            const vector r(C[celli] - p.position());
            const vector& uc = u[celli];
            const vector rxu(r ^ uc);

            s[iMass] += w;
            for (direction d = 0; d < 3; ++d)
            {
                s[iFirst + d] += w*r[d];
                s[iMomentum + d] += w*uc[d];
                s[iAngular + d] += w*rxu[d];
            }
            s[iSecond + 0] += w*r.x()*r.x();
            s[iSecond + 1] += w*r.x()*r.y();
            s[iSecond + 2] += w*r.x()*r.z();
            s[iSecond + 3] += w*r.y()*r.y();
            s[iSecond + 4] += w*r.y()*r.z();
            s[iSecond + 5] += w*r.z()*r.z();
            s[iVolume] += fractions[k]*V[celli];
        }
    }
    Pstream::listCombineGather(sums, plusEqOp<scalar>());
    Pstream::listCombineScatter(sums);


    forAll(particles, i)
    {
        dlmParticle& p = particles[i];
        const scalar* s = &sums[nSums*i];
        const scalar M = s[iMass];

        if (M <= 0)
        {
            failUncovered(p, "cell volume");
        }

        // Discrete centroid, momentum, and moments about the centroid
        const vector delta
        (
            vector(s[iFirst], s[iFirst + 1], s[iFirst + 2])/M
        );
        const vector P(s[iMomentum], s[iMomentum + 1], s[iMomentum + 2]);
        const vector L
        (
            vector(s[iAngular], s[iAngular + 1], s[iAngular + 2])
          - (delta ^ P)
        );
        const symmTensor J
        (
            symmTensor
            (
                s[iSecond], s[iSecond + 1], s[iSecond + 2],
                s[iSecond + 3], s[iSecond + 4], s[iSecond + 5]
            )
          - M*sqr(delta)
        );
        const symmTensor I(tr(J)*symmTensor::I - J);

        if (p.isFree())
        {
            const vector omega
            (
                twoD ? vector(0, 0, L.z()/I.zz()) : (inv(I) & L)
            );
            // P/M is the velocity of the discrete centroid; the particle
            // moves with the velocity of its own centre
            p.setVelocities(P/M - (omega ^ delta), omega);
        }

        // Fluid force, with the hydrostatic buoyancy: the momentum change
        // less the weight, where the momentum equation holds it
        const vector P0
        (
            M*(p.velocity0() + (p.angularVelocity0() ^ delta))
        );
        vector F((P - P0)/deltaT - p.mixtureDensity(rhoFluid)*s[iVolume]*g);
        vector T((L - (I & p.angularVelocity0()))/deltaT);
        if (twoD)
        {
            F.z() = 0;
            T = vector(0, 0, T.z());
        }
        p.setLoads(F, T);

        const vector& Up = p.velocity();
        const vector& omega = p.angularVelocity();
        const point& X = p.position();
        const DynamicList<label>& cells = cloud.cells(i);
        const DynamicList<scalar>& fractions = cloud.fractions(i);
        forAll(cells, k)
        {
            const label celli = cells[k];
            const vector us(Up + (omega ^ (C[celli] - X)));
            u[celli] +=
                beta(fractions[k], p.mixtureDensity(rhoFluid), rho[celli])*(us - u[celli]);
        }
    }
}


// ************************************************************************* //
