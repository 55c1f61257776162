/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "fractionBlended.H"
#include "dlmParticleCloud.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace
{
    // Layout of the per-particle sums of the fractionBlended projection, reduced
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
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fv::fractionBlended::fractionBlended(const word& optionName, const fvMesh& mesh)
:
    mixedCellTreatment(optionName, mesh)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fv::fractionBlended::correct(volVectorField& U)
{
    dlmParticleCloud& cloud =
        mesh_.lookupObjectRef<dlmParticleCloud>("particles");
    PtrList<dlmParticle>& particles = cloud.particles();

    const vectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();
    const scalarField& rho = cloud.rho();
    vectorField& u = U.primitiveFieldRef();

    const vector g(gravity(mesh_));
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
    cloud.images().reduceSums(sums, nSums);


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


void Foam::fv::fractionBlended::holdRigid
(
    volVectorField& U,
    scalarField& held
)
{
    const dlmParticleCloud& cloud =
        mesh_.lookupObject<dlmParticleCloud>("particles");
    const PtrList<dlmParticle>& particles = cloud.particles();
    vectorField& u = U.primitiveFieldRef();

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


// ************************************************************************* //
