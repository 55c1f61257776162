/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
-------------------------------------------------------------------------------
Description
    Tests of cellOperators: in a set of cells, the Gauss linear gradient is
    the whole-mesh one to the last bit, and the momentum matrix applied to
    a field is OpenFOAM's M & psi to round-off, on the 3D and the 2D mesh.

\*---------------------------------------------------------------------------*/

#include <catch2/catch.hpp>

#include "testCase.H"
#include "cellOperators.H"
#include "gaussGrad.H"
#include "fvm.H"
#include "gaussConvectionScheme.H"
#include "upwind.H"
#include "fixedValueFvPatchFields.H"

using namespace Foam;

namespace
{

// A smooth, non-polynomial field, zero on the walls' faces as a no-slip
// velocity's error is
tmp<volVectorField> testField(const fvMesh& mesh)
{
    tmp<volVectorField> tU
    (
        tmp<volVectorField>::New
        (
            IOobject("U", mesh.time().timeName(), mesh),
            mesh,
            dimensionedVector(dimVelocity, Zero),
            fixedValueFvPatchVectorField::typeName
        )
    );
    volVectorField& U = tU.ref();
    forAll(U, celli)
    {
        const point& x = mesh.C()[celli];
        U[celli] = vector
        (
            Foam::sin(3*x.x() + x.y()),
            Foam::cos(2*x.y())*x.z(),
            Foam::exp(x.x() - x.z())
        );
    }
    U.correctBoundaryConditions();
    return tU;
}


// Every third cell, and every cell next to a boundary
labelList someCells(const fvMesh& mesh)
{
    boolList chosen(mesh.nCells(), false);
    for (label celli = 0; celli < mesh.nCells(); celli += 3)
    {
        chosen[celli] = true;
    }
    for (const fvPatch& patch : mesh.boundary())
    {
        for (const label celli : patch.faceCells())
        {
            chosen[celli] = true;
        }
    }
    return findIndices(chosen, true);
}


void runGradient()
{
    const fvMesh& mesh = testCase::mesh();
    const tmp<volVectorField> tU(testField(mesh));
    const volTensorField whole
    (
        fv::gaussGrad<vector>(mesh).calcGrad(tU(), "grad(U)")
    );

    cellOperators ops(mesh);
    ops.setCells(someCells(mesh));
    const tensorField local(ops.grad(tU()));
    label differing = 0;
    forAll(ops.cells(), c)
    {
        differing += local[c] != whole[ops.cells()[c]];
    }
    CHECK(ops.cells().size() > mesh.nCells()/3);
    CHECK(differing == 0);
}


void runProduct()
{
    const fvMesh& mesh = testCase::mesh();
    const tmp<volVectorField> tU(testField(mesh));
    const volVectorField& U = tU();
    const dimensionedScalar nu("nu", dimViscosity, 0.3);
    // Upwind convection: lower and upper coefficients differ
    const surfaceScalarField phi("phi", linearInterpolate(U) & mesh.Sf());
    fvVectorMatrix M
    (
        fvm::ddt(U)
      + fv::gaussConvectionScheme<vector>
        (
            mesh,
            phi,
            tmp<surfaceInterpolationScheme<vector>>
            (
                new upwind<vector>(mesh, phi)
            )
        ).fvmDiv(phi, U)
      - fvm::laplacian(nu, U)
    );
    M.source() = Zero;
    const scalarField rate(mesh.nCells(), 7.5);

    // OpenFOAM's operator: (A psi - H(psi) - source)/V, the walls' values
    // zero
    const vectorField whole
    (
        (M & U)().primitiveField() + rate*U.primitiveField()
    );

    cellOperators ops(mesh);
    ops.setCells(someCells(mesh));
    const vectorField local(ops.product(M, rate, U));
    scalar largest = 0;
    scalar scale = 0;
    forAll(ops.cells(), c)
    {
        largest = max(largest, mag(local[c] - whole[ops.cells()[c]]));
        scale = max(scale, mag(local[c]));
    }
    CHECK(scale > 1);
    CHECK(largest < 1e-12*scale);
}

} // End anonymous namespace


TEST_CASE("3D: gradient in chosen cells is the whole-mesh one", "[3D]")
{
    REQUIRE(testCase::available());
    runGradient();
}


TEST_CASE("3D: matrix product in chosen cells is M & psi", "[3D]")
{
    REQUIRE(testCase::available());
    runProduct();
}


TEST_CASE("2D: gradient in chosen cells is the whole-mesh one", "[2D]")
{
    REQUIRE(testCase::available());
    runGradient();
}


TEST_CASE("2D: matrix product in chosen cells is M & psi", "[2D]")
{
    REQUIRE(testCase::available());
    runProduct();
}


// ************************************************************************* //
