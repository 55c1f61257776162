/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "particleOutlet.H"
#include "checkKeywords.H"

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

    checkKeywords
    (
        dict,
        wordHashSet(outlet->keywords()),
        "for outlet " + dict.dictName() + " (type " + outletType + ")"
    );

    return outlet;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::particleOutlet::typeKeywords()
{
    return wordList({"type"});
}


Foam::wordList Foam::particleOutlet::keywords() const
{
    return typeKeywords();
}


void Foam::particleOutlet::readState(const dictionary& state)
{
    const dictionary* dictPtr = state.findDict(name_);
    if (dictPtr)
    {
        nRemoved_ = dictPtr->get<label>("particles");
        massRemoved_ = dictPtr->get<scalar>("mass");
        removedNames_ =
            dictPtr->getOrDefault<wordList>("removed", wordList());
    }
}


void Foam::particleOutlet::writeState(Ostream& os) const
{
    os.beginBlock(name_);
    os.writeEntry("particles", nRemoved_);
    os.writeEntry("mass", massRemoved_);
    os.writeEntry("removed", removedNames_);
    os.endBlock();
}


// ************************************************************************* //
