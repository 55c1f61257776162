/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "mixedCellTreatment.H"
#include "dlmParticleCloud.H"
#include "uniformDimensionedFields.H"
#include "OStringStream.H"
#include "IOmanip.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fv
{
    defineTypeNameAndDebug(mixedCellTreatment, 0);
    defineRunTimeSelectionTable(mixedCellTreatment, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fv::mixedCellTreatment::mixedCellTreatment
(
    const word& optionName,
    const fvMesh& mesh
)
:
    optionName_(optionName),
    mesh_(mesh)
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::fv::mixedCellTreatment::failUncovered
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


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::fv::mixedCellTreatment::gravity(const fvMesh& mesh)
{
    const word name("g");
    if (mesh.time().foundObject<uniformDimensionedVectorField>(name))
    {
        return
            mesh.time().lookupObject<uniformDimensionedVectorField>(name)
           .value();
    }
    return Zero;
}


void Foam::fv::mixedCellTreatment::read(const dictionary& coeffs)
{}


void Foam::fv::mixedCellTreatment::addForce
(
    DimensionedField<vector, volMesh>& source
)
{}


bool Foam::fv::mixedCellTreatment::predictsContacts() const
{
    return false;
}


void Foam::fv::mixedCellTreatment::constrain(fvMatrix<vector>& eqn)
{}


bool Foam::fv::mixedCellTreatment::followContacts(vectorField& change) const
{
    return false;
}


void Foam::fv::mixedCellTreatment::markRigidExcess(boolList& rigid) const
{}


void Foam::fv::mixedCellTreatment::updateMesh()
{}


// ************************************************************************* //
