/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "massWeighted.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fv
{
    defineTypeNameAndDebug(massWeighted, 0);
    addToRunTimeSelectionTable(mixedCellTreatment, massWeighted, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fv::massWeighted::massWeighted
(
    const word& optionName,
    const dictionary& coeffs,
    const fvMesh& mesh
)
:
    fractionBlended(optionName, mesh)
{}


// ************************************************************************* //
