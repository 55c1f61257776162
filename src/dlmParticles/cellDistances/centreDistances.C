/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "centreDistances.H"
#include "surfaceFields.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::scalarField> Foam::centreDistances(const fvMesh& mesh)
{
    const tmp<surfaceVectorField> tdelta(mesh.delta());
    const surfaceVectorField& delta = tdelta();

    label n = delta.size();
    forAll(mesh.boundary(), patchi)
    {
        if (mesh.boundary()[patchi].coupled())
        {
            n += mesh.boundary()[patchi].size();
        }
    }

    auto tdistances = tmp<scalarField>::New(n);
    scalarField& distances = tdistances.ref();
    SubField<scalar>(distances, delta.size()) = mag(delta.primitiveField());
    label start = delta.size();
    forAll(mesh.boundary(), patchi)
    {
        if (mesh.boundary()[patchi].coupled())
        {
            const fvsPatchVectorField& d = delta.boundaryField()[patchi];
            SubField<scalar>(distances, d.size(), start) = mag(d);
            start += d.size();
        }
    }

    return tdistances;
}


// ************************************************************************* //
