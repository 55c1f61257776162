/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "mixedCellTreatment.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::fv::mixedCellTreatment> Foam::fv::mixedCellTreatment::New
(
    const word& optionName,
    const dictionary& coeffs,
    const fvMesh& mesh
)
{
    const word treatmentType
    (
        coeffs.getOrDefault<word>("mixedCells", "interpolated")
    );

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(treatmentType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(coeffs)
            << "Unknown mixedCells " << treatmentType << " for fvOption "
            << optionName << nl << nl
            << "Valid mixedCells: "
            << flatOutput(dictionaryConstructorTablePtr_->sortedToc())
            << exit(FatalIOError);
    }

    return autoPtr<mixedCellTreatment>(cstrIter()(optionName, coeffs, mesh));
}


// ************************************************************************* //
