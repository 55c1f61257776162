/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "particleOutlet.H"
#include "HashSet.H"
#include "FlatOutput.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(particleOutlet, 0);
    defineRunTimeSelectionTable(particleOutlet, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleOutlet::particleOutlet(const dictionary& dict)
:
    name_(dict.dictName()),
    nRemoved_(0),
    massRemoved_(0)
{}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::particleOutlet> Foam::particleOutlet::New
(
    const dictionary& dict
)
{
    const word outletType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(outletType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "type",
            outletType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    autoPtr<particleOutlet> outlet(cstrIter()(dict));

    const wordHashSet known(outlet->keywords());
    for (const entry& e : dict)
    {
        if (!known.found(e.keyword()))
        {
            FatalIOErrorInFunction(dict)
                << "Unknown keyword '" << e.keyword() << "' for outlet "
                << dict.dictName() << " (type " << outletType << "). Known"
                << " keywords: " << flatOutput(known.sortedToc())
                << exit(FatalIOError);
        }
    }

    return outlet;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::particleOutlet::keywords() const
{
    return wordList({"type"});
}


void Foam::particleOutlet::readState(const dictionary& state)
{
    const dictionary* dictPtr = state.findDict(name_);
    if (dictPtr)
    {
        nRemoved_ = dictPtr->get<label>("particles");
        massRemoved_ = dictPtr->get<scalar>("mass");
    }
}


void Foam::particleOutlet::writeState(Ostream& os) const
{
    os.beginBlock(name_);
    os.writeEntry("particles", nRemoved_);
    os.writeEntry("mass", massRemoved_);
    os.endBlock();
}


// ************************************************************************* //
