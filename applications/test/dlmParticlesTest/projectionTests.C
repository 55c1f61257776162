/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
-------------------------------------------------------------------------------
Description
    Tests on a mesh: the solid fraction field of the cloud and the rigid
    projection (conservation, rigid fields unchanged), in 3D and 2D.

\*---------------------------------------------------------------------------*/

#include <catch2/catch.hpp>

#include "testCase.H"
#include "dlmParticleCloud.H"
#include "rigidProjection.H"
#include "Random.H"
#include "fvm.H"
#include "fixedValueFvPatchFields.H"

using namespace Foam;

namespace
{

const wordList mixedCellsTypes
({
    "interpolated",
    "massWeighted",
    "volumeWeighted"
});


struct Moments
{
    vector momentum;
    vector angularMomentum;
    scalar scale;
};


// Momentum and angular momentum (about the origin) of rho U
Moments moments(const volScalarField& rho, const volVectorField& U)
{
    const fvMesh& mesh = U.mesh();
    Moments m{Zero, Zero, 0};
    forAll(U, celli)
    {
        const scalar mass = rho[celli]*mesh.V()[celli];
        m.momentum += mass*U[celli];
        m.angularMomentum += mass*(mesh.C()[celli] ^ U[celli]);
        m.scale += mass*mag(U[celli]);
    }
    return m;
}


tmp<volVectorField> zeroVelocity(const fvMesh& mesh)
{
    return tmp<volVectorField>::New
    (
        IOobject("U", mesh.time().timeName(), mesh),
        mesh,
        dimensionedVector(dimVelocity, Zero),
        fixedValueFvPatchVectorField::typeName
    );
}


autoPtr<fv::option> projection(const fvMesh& mesh, const word& mixedCells)
{
    dictionary dict;
    dict.add("type", "rigidProjection");
    dict.add("mixedCells", mixedCells);
    return autoPtr<fv::option>
    (
        new fv::rigidProjection("projection", "rigidProjection", dict, mesh)
    );
}


// Project U as the solver does, after a momentum equation (here a time
// derivative and diffusion) was constrained
void project(fv::option& projection, volVectorField& U)
{
    fvVectorMatrix momentum
    (
        fvm::ddt(U)
      - fvm::laplacian(dimensionedScalar("nu", dimViscosity, 1), U)
    );
    projection.constrain(momentum, 0);
    projection.correct(U);
}


bool twoD(const fvMesh& mesh)
{
    return mesh.nSolutionD() == 2;
}


void runConservation()
{
    const fvMesh& mesh = testCase::mesh();

    // The case's particle has density 3: ratios 3 and 0.5
    for (const scalar rhoFluid : {1.0, 6.0})
    {
        for (const word& mixedCells : mixedCellsTypes)
        {
            dlmParticleCloud cloud(mesh, dimensionedScalar("rho", dimDensity, rhoFluid));
            tmp<volVectorField> tU(zeroVelocity(mesh));
            volVectorField& U = tU.ref();

            Random rnd(3);
            forAll(U, celli)
            {
                U[celli] = rnd.sample01<vector>() - 0.5*vector::one;
                if (twoD(mesh))
                {
                    U[celli].z() = 0;
                }
            }

            const Moments before(moments(cloud.rho(), U));
            autoPtr<fv::option> rigidProjection(projection(mesh, mixedCells));
            project(rigidProjection(), U);
            const Moments after(moments(cloud.rho(), U));

            INFO(mixedCells << ", density ratio " << 3/rhoFluid);
            CHECK(mag(after.momentum - before.momentum) < 1e-13*before.scale);
            CHECK
            (
                mag(after.angularMomentum - before.angularMomentum)
              < 1e-13*before.scale
            );

            // The force that keeps the particle rigid is internal to the
            // mixture: no net force or torque
            if (mixedCells == "interpolated")
            {
                const volVectorField& f =
                    mesh.lookupObject<volVectorField>("rigidForce");
                vector netForce(Zero);
                vector netTorque(Zero);
                scalar scale = 0;
                forAll(f, celli)
                {
                    const scalar V = mesh.V()[celli];
                    netForce += V*f[celli];
                    netTorque += V*(mesh.C()[celli] ^ f[celli]);
                    scale += V*mag(f[celli]);
                }
                CHECK(scale > 0);
                CHECK(mag(netForce) < 1e-13*scale);
                CHECK(mag(netTorque) < 1e-13*scale);
            }

            // Cells fully inside move rigidly with the particle: velocity
            // differences are omega x separations
            const dlmParticle& p = cloud.particles()[0];
            const vector omega(p.angularVelocity());
            const DynamicList<label>& cells = cloud.cells(0);
            const DynamicList<scalar>& fractions = cloud.fractions(0);
            label reference = -1;
            label nSolid = 0;
            forAll(cells, k)
            {
                if (fractions[k] < 1)
                {
                    continue;
                }
                const label celli = cells[k];
                if (reference < 0)
                {
                    reference = celli;
                }
                const vector relative(U[celli] - U[reference]);
                const vector rigid
                (
                    omega ^ (mesh.C()[celli] - mesh.C()[reference])
                );
                CHECK(mag(relative - rigid) < 1e-12);
                ++nSolid;
            }
            CHECK(nSolid > 0);
            CHECK(mag(p.velocity()) > 0);
        }
    }
}


void runRigidUnchanged()
{
    const fvMesh& mesh = testCase::mesh();
    dlmParticleCloud cloud(mesh, dimensionedScalar("rho", dimDensity, 1.0));
    const point X(cloud.particles()[0].position());

    const vector U0 = twoD(mesh) ? vector(0.3, -0.2, 0) : vector(0.3, -0.2, 0.1);
    const vector omega0 = twoD(mesh) ? vector(0, 0, 2) : vector(1, -2, 0.5);

    for (const word& mixedCells : mixedCellsTypes)
    {
        tmp<volVectorField> tU(zeroVelocity(mesh));
        volVectorField& U = tU.ref();
        forAll(U, celli)
        {
            U[celli] = U0 + (omega0 ^ (mesh.C()[celli] - X));
        }
        const vectorField before(U.primitiveField());

        project(projection(mesh, mixedCells)(), U);

        INFO(mixedCells);
        CHECK(max(mag(U.primitiveField() - before)) < 1e-12);
        CHECK(mag(cloud.particles()[0].velocity() - U0) < 1e-12);
        CHECK(mag(cloud.particles()[0].angularVelocity() - omega0) < 1e-11);
    }
}


void runFractionIntegral()
{
    const fvMesh& mesh = testCase::mesh();
    dlmParticleCloud cloud(mesh, dimensionedScalar("rho", dimDensity, 1.0));
    const dlmParticle& p = cloud.particles()[0];

    scalar exact = p.shape().volume();
    if (twoD(mesh))
    {
        exact *= mesh.bounds().span().z();
    }
    const scalar sum = gSum(cloud.alpha().primitiveField()*mesh.V());
    CHECK(sum/exact == Approx(1).epsilon(1e-3));

    // rho = rhoFluid + (rho_s - rhoFluid) alpha
    const scalar expectedMass = gSum(mesh.V()) + (p.density() - 1)*sum;
    CHECK(gSum(cloud.rho().primitiveField()*mesh.V()) == Approx(expectedMass));
}


// The cell whose centre is x
label cellAt(const fvMesh& mesh, const point& x)
{
    const label celli = mesh.findCell(x);
    REQUIRE(celli >= 0);
    REQUIRE(mag(mesh.C()[celli] - x) < 1e-12);
    return celli;
}


// The internal face between two cells
label faceBetween(const fvMesh& mesh, const label celli, const label cellj)
{
    for (const label facei : mesh.cells()[celli])
    {
        if
        (
            mesh.isInternalFace(facei)
         && (mesh.owner()[facei] == cellj || mesh.neighbour()[facei] == cellj)
        )
        {
            return facei;
        }
    }
    FAIL("cells " << celli << " and " << cellj << " share no face");
    return -1;
}


void runGapBlending()
{
    const fvMesh& mesh = testCase::mesh();
    dlmParticleCloud cloud(mesh, dimensionedScalar("rho", dimDensity, 1.0));
    dictionary dict;
    dict.add("type", "rigidProjection");
    dict.add("gapBlending", 0.25);
    fv::rigidProjection projection("projection", "rigidProjection", dict, mesh);
    tmp<volVectorField> tU(zeroVelocity(mesh));
    project(projection, tU.ref());

    const surfaceScalarField& factor =
        mesh.lookupObject<surfaceScalarField>("UBlendingFactor");
    auto factorBetween = [&](const point& a, const point& b)
    {
        return
            factor[faceBetween(mesh, cellAt(mesh, a), cellAt(mesh, b))];
    };

    // Two cells between the surfaces at x = 0.3 and 0.43, and the cells
    // next to the surfaces in a gap of three: left to the flow
    const scalar y2 = 0.28125;
    const scalar y3 = 0.71875;
    const scalar z = 0.46875;
    CHECK(factorBetween(point(0.34375, y2, z), point(0.40625, y2, z)) == 0.25);
    CHECK(factorBetween(point(0.34375, y3, z), point(0.40625, y3, z)) == 0.25);
    CHECK(factorBetween(point(0.40625, y3, z), point(0.46875, y3, z)) == 0.25);

    // The three-cell gap's middle cell is next to no surface: its faces to
    // the side keep 1
    CHECK(factorBetween(point(0.40625, y3, z), point(0.40625, y3 + 0.0625, z)) == 1);

    // An interface cell with a profile (beyond the first sphere, towards
    // the wall x = 0) and the open flow keep 1
    CHECK(factorBetween(point(0.03125, y2, z), point(0.09375, y2, z)) == 1);
    CHECK(factorBetween(point(0.84375, y2, z), point(0.90625, y2, z)) == 1);
}

} // End anonymous namespace


TEST_CASE("3D: solid fraction integrates to the sphere's volume", "[3D]")
{
    REQUIRE(testCase::available());
    REQUIRE_FALSE(twoD(testCase::mesh()));
    runFractionIntegral();
}


TEST_CASE("3D: projection conserves momentum and angular momentum", "[3D]")
{
    REQUIRE(testCase::available());
    runConservation();
}


TEST_CASE("3D: a rigid velocity field is left unchanged", "[3D]")
{
    REQUIRE(testCase::available());
    runRigidUnchanged();
}


TEST_CASE("2D: solid fraction integrates to the disk's area", "[2D]")
{
    REQUIRE(testCase::available());
    REQUIRE(twoD(testCase::mesh()));
    runFractionIntegral();
}


TEST_CASE("2D: projection conserves momentum and angular momentum", "[2D]")
{
    REQUIRE(testCase::available());
    runConservation();
}


TEST_CASE("2D: a rigid velocity field is left unchanged", "[2D]")
{
    REQUIRE(testCase::available());
    runRigidUnchanged();
}


TEST_CASE
(
    "3D: the faces of gaps left to the flow carry gapBlending",
    "[gap]"
)
{
    REQUIRE(testCase::available());
    runGapBlending();
}


// ************************************************************************* //
