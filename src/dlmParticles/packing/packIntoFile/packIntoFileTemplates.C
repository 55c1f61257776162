/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "packIntoFile.H"
#include "IOdictionary.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "checkKeywords.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

template<class Packing>
Foam::wordList Foam::packIntoFileKeywords()
{
    wordList words(Packing::keywords);
    words.append("output");
    return words;
}


template<class Packing>
void Foam::packIntoFile
(
    const Time& runTime,
    const word& dictName,
    const fileName& defaultOutput,
    const word& executable
)
{
    const IOdictionary dict
    (
        IOobject
        (
            dictName,
            runTime.system(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    );

    wordHashSet known(packIntoFileKeywords<Packing>());
    known.insert("FoamFile");
    checkKeywords(dict, known);

    Packing packing(dict);

    fileName output(dict.getOrDefault<fileName>("output", defaultOutput));
    output.expand();
    if (!output.isAbsolute())
    {
        output = runTime.globalPath()/output;
    }

    packing.pack();

    mkDir(output.path());
    OFstream os(output);
    if (!os.good())
    {
        FatalErrorInFunction
            << "Cannot write " << output << exit(FatalError);
    }
    packing.write(os, executable);

    Info<< "Wrote " << packing.size() << " particles to " << output << nl
        << endl;
}


// ************************************************************************* //
