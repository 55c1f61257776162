/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "checkKeywords.H"
#include "FlatOutput.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::checkKeywords
(
    const dictionary& dict,
    const wordHashSet& known,
    const std::string& owner
)
{
    for (const entry& e : dict)
    {
        if (!known.found(e.keyword()))
        {
            FatalIOErrorInFunction(dict)
                << "Unknown keyword '" << e.keyword() << "'"
                << (owner.empty() ? "" : " ") << owner.c_str() << "." << nl
                << "Known keywords: " << flatOutput(known.sortedToc())
                << exit(FatalIOError);
        }
    }
}


// ************************************************************************* //
