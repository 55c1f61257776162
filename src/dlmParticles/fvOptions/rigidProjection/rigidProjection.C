/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "rigidProjection.H"
#include "dlmParticleCloud.H"
#include "fvMatrices.H"
#include "cpuTime.H"
#include "fvcFlux.H"
#include "checkKeywords.H"
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


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fv::rigidProjection::checkKeywords(const dictionary& dict) const
{
    const std::string owner
    (
        "for fvOption " + name_ + " (type " + modelType_ + ")"
    );

    // fv::option reads type, libs, active, log and the optional
    // <type>Coeffs sub-dictionary, which then holds the projection's own
    const wordHashSet own
    ({
        "mixedCells", "forceRelaxation", "implicitHold", "gapBlending",
        "boundaryLayerSlip", "forceFollowsParticles"
    });
    const word coeffsName(modelType_ + "Coeffs");
    wordHashSet known({"type", "libs", "active", "log", coeffsName});

    const dictionary* coeffsPtr = dict.findDict(coeffsName);
    if (coeffsPtr)
    {
        Foam::checkKeywords(*coeffsPtr, own, owner);
    }
    else
    {
        known += own;
    }
    Foam::checkKeywords(dict, known, owner);
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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fv::rigidProjection::rigidProjection
(
    const word& name,
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    option(name, modelType, dict, mesh)
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
        const word mixedCells
        (
            coeffs_.getOrDefault<word>("mixedCells", "interpolated")
        );
        if (!treatment_.valid() || treatment_->type() != mixedCells)
        {
            treatment_ = mixedCellTreatment::New(name_, coeffs_, mesh_);
        }
        treatment_->read(coeffs_);
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
    const vector g(mixedCellTreatment::gravity(mesh_));
    const scalar rhoFluid = cloud.rhoFluid().value();

    DimensionedField<vector, volMesh> source
    (
        IOobject("rigidSource", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedVector(dimDensity*dimAcceleration, Zero)
    );
    treatment_->addForce(source);

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
    if (treatment_->predictsContacts())
    {
        cloud.setContactPredicted();
    }
    cloud.addWorkTime
    (
        dlmParticleCloud::workPart::projection,
        timer.elapsedCpuTime()
    );
}


void Foam::fv::rigidProjection::constrain
(
    fvMatrix<vector>& eqn,
    const label fieldi
)
{
    // The search for the forced cells after a move runs here
    const cpuTime timer;
    treatment_->constrain(eqn);
    mesh_.lookupObjectRef<dlmParticleCloud>("particles").addWorkTime
    (
        dlmParticleCloud::workPart::projection,
        timer.elapsedCpuTime()
    );
}


void Foam::fv::rigidProjection::correct(volVectorField& U)
{
    const cpuTime timer;
    dlmParticleCloud& cloud =
        mesh_.lookupObjectRef<dlmParticleCloud>("particles");
    treatment_->correct(U);

    U.correctBoundaryConditions();
    cloud.setProjected();
    cloud.addWorkTime
    (
        dlmParticleCloud::workPart::projection,
        timer.elapsedCpuTime()
    );
}


void Foam::fv::rigidProjection::holdRigid
(
    volVectorField& U,
    scalarField& held
)
{
    held = 0;
    treatment_->holdRigid(U, held);
    U.correctBoundaryConditions();
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

    // A fixed bed neither moves nor has contacts
    if (cloud.allFixed())
    {
        return;
    }

    volVectorField change
    (
        IOobject("rigidChange", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedVector(dimVelocity, Zero)
    );
    // The contact sub-steps' change of each free particle's velocities
    // since the projection, in its cells
    bool changed = treatment_->followContacts(change.primitiveFieldRef());

    // The excess mass each particle moved into a cell brings the
    // particle's velocity, and the excess mass it moved out of a cell takes
    // it away: the mixture's momentum only moves with the mass
    // (validation/cases/freeSphere.md)
    const vectorField followed(u + change.primitiveField());

    // With a second-order time derivative (backward) the momentum equation
    // also takes the last step's velocity with the new densities: the mass
    // moved carries its momentum there too
    // (a restart that read U_0 holds an older level whatever the scheme)
    const ITstream& ddtScheme = mesh_.ddtScheme("ddt(" + U.name() + ')');
    const bool olderLevel =
        U.nOldTimes() > 1
     && ddtScheme.size() && ddtScheme[0].isWord()
     && ddtScheme[0].wordToken() == "backward";
    vectorField changeOld(olderLevel ? mesh_.nCells() : 0, Zero);
    const vectorField& u0 =
        olderLevel ? U.oldTime().primitiveField() : U.primitiveField();
    // The excess mass leaving a cell moved rigidly only where the
    // projection held it so; elsewhere it moved with the cell's velocity
    boolList rigid(mesh_.nCells(), false);
    treatment_->markRigidExcess(rigid);

    labelListList images(followedCells_.size());
    forAll(particles, i)
    {
        const label body = cloud.source(i);
        if (body < images.size())
        {
            images[body].append(i);
        }
    }
    scalarField fraction0(mesh_.nCells(), Zero);
    forAll(images, body)
    {
        if (images[body].empty())
        {
            continue;
        }
        const dlmParticle& p0 = particles[images[body].first()];
        const scalar excess = p0.mixtureDensity(rhoFluid) - rhoFluid;
        if (excess <= 0)
        {
            continue;
        }

        // The body's fractions at the last follow step (its images' too)
        forAll(followedCells_[body], k)
        {
            fraction0[followedCells_[body][k]] = followedFractions_[body][k];
        }

        auto moveExcess = [&]
        (
            const dlmParticle& p,
            const label celli,
            const scalar gained
        )
        {
            const vector us
            (
                p.velocity()
              + (p.angularVelocity() ^ (C[celli] - p.position()))
            );
            change[celli] += gained/rho[celli]*(us - followed[celli]);
            if (olderLevel)
            {
                changeOld[celli] += gained/rho[celli]*(us - u0[celli]);
            }
            changed = true;
        };

        // Cells the body covers now: gained or lost some of its mass
        for (const label i : images[body])
        {
            const DynamicList<label>& cells = cloud.cells(i);
            const DynamicList<scalar>& fractions = cloud.fractions(i);
            forAll(cells, k)
            {
                const label celli = cells[k];
                const scalar gained = excess*(fractions[k] - fraction0[celli]);
                if (gained > 0 || (gained < 0 && rigid[celli]))
                {
                    moveExcess(particles[i], celli, gained);
                }
                fraction0[celli] = 0;
            }
        }

        // Cells the body left: all of its mass there went with the image
        // nearest to the cell
        for (const label celli : followedCells_[body])
        {
            if (fraction0[celli] > 0 && rigid[celli])
            {
                label nearest = images[body].first();
                for (const label i : images[body])
                {
                    if
                    (
                        magSqr(C[celli] - particles[i].position())
                      < magSqr(C[celli] - particles[nearest].position())
                    )
                    {
                        nearest = i;
                    }
                }
                moveExcess
                (
                    particles[nearest],
                    celli,
                    -excess*fraction0[celli]
                );
            }
            fraction0[celli] = 0;
        }
    }
    recordFractions(cloud);

    if (returnReduce(changed, orOp<bool>()))
    {
        change.correctBoundaryConditions();
        U.primitiveFieldRef() += change.primitiveField();
        if (olderLevel)
        {
            U.oldTime().primitiveFieldRef() += changeOld;
            U.oldTime().correctBoundaryConditions();
        }
        U.correctBoundaryConditions();
        phi += fvc::flux(change);
    }
    cloud.addWorkTime
    (
        dlmParticleCloud::workPart::projection,
        timer.elapsedCpuTime()
    );
}


void Foam::fv::rigidProjection::updateMesh(const dlmParticleCloud& cloud)
{
    treatment_->updateMesh();
    recordFractions(cloud);
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


// ************************************************************************* //
