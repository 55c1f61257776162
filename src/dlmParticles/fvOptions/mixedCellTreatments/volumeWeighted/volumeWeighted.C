/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "volumeWeighted.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fv
{
    defineTypeNameAndDebug(volumeWeighted, 0);
    addToRunTimeSelectionTable(mixedCellTreatment, volumeWeighted, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fv::volumeWeighted::volumeWeighted
(
    const word& optionName,
    const dictionary& coeffs,
    const fvMesh& mesh
)
:
    fractionBlended(optionName, mesh)
{}


// ************************************************************************* //
