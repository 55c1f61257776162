/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "rigidProjection.H"
#include "dlmParticleCloud.H"
#include "uniformDimensionedFields.H"
#include "fvMatrices.H"
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
    { mixedCellsType::volumeWeighted, "volumeWeighted" },
    { mixedCellsType::massWeighted, "massWeighted" },
});


namespace
{
    // Layout of the per-particle sums reduced over processors
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
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

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
    mixedCells_(mixedCellsType::massWeighted)
{
    fieldNames_.setSize(1, "U");
    applied_.setSize(1, false);

    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::fv::rigidProjection::read(const dictionary& dict)
{
    if (option::read(dict))
    {
        mixedCells_ = mixedCellsTypeNames.getOrDefault
        (
            "mixedCells",
            coeffs_,
            mixedCellsType::massWeighted
        );
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
    const dlmParticleCloud& cloud =
        mesh_.lookupObject<dlmParticleCloud>("particles");
    const vector g(gravity());
    const scalar rhoFluid = cloud.rhoFluid().value();

    DimensionedField<vector, volMesh> weight
    (
        IOobject("reducedWeight", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedVector(eqn.dimensions()/dimVolume, Zero)
    );

    forAll(cloud.particles(), i)
    {
        const dlmParticle& p = cloud.particles()[i];
        if (p.isFree())
        {
            const vector density((p.density() - rhoFluid)*g);
            const DynamicList<label>& cells = cloud.cells(i);
            const DynamicList<scalar>& fractions = cloud.fractions(i);
            forAll(cells, k)
            {
                weight[cells[k]] += fractions[k]*density;
            }
        }
    }

    eqn += weight;
}


void Foam::fv::rigidProjection::correct(volVectorField& U)
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
            const scalar b = beta(fractions[k], p.density(), rho[celli]);
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
            FatalErrorInFunction
                << "Particle " << p.name() << " covers no cell volume"
                << exit(FatalError);
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
        const scalar heldDensity = p.isFree() ? p.density() : rhoFluid;
        vector F((P - P0)/deltaT - heldDensity*s[iVolume]*g);
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
                beta(fractions[k], p.density(), rho[celli])*(us - u[celli]);
        }
    }

    U.correctBoundaryConditions();
    cloud.setProjected();
}


// ************************************************************************* //
