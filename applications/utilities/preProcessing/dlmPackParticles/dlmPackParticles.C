/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
-------------------------------------------------------------------------------
Application
    dlmPackParticles

Group
    grpPreProcessingUtilities

Description
    Places particles of any convex shapes (a mix of spheres, ellipsoids,
    cylinders, boxes, ...) at random positions and orientations in a box
    without overlap, reproducible from a seed, and writes them as entries of
    'particles' for constant/particleProperties. The placement is
    Foam::randomShapeInsertion's (random sequential insertion, each
    candidate tested against the walls by its support function and against
    the particles placed by the contact's separating-plane search); a
    particle that finds no free place stops the run with an error and
    nothing is written. Random insertion is loose: dense piles come from
    letting the particles settle.

Usage
    \b dlmPackParticles [OPTIONS]

    system/packParticlesDict holds the box, the groups of particles and how
    to place them, as in the Usage of Foam::randomShapeInsertion
    (src/dlmParticles/packing/randomShapeInsertion/randomShapeInsertion.H),
    and the file to write:
    \verbatim
    output          "constant/packedParticles";     // optional, default
    \endverbatim

    constant/particleProperties then includes the file among its particles
    (a path relative to constant/):
    \verbatim
    particles
    {
        #include "packedParticles"
    }
    \endverbatim

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "HashSet.H"
#include "randomShapeInsertion.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Random placement of particles of any convex shapes without overlap,"
        " from system/packParticlesDict, written as entries of 'particles'"
        " for constant/particleProperties"
    );
    argList::noParallel();

    #include "setRootCase.H"
    #include "createTime.H"

    const IOdictionary dict
    (
        IOobject
        (
            "packParticlesDict",
            runTime.system(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    );

    // A misspelt optional keyword would otherwise be ignored silently
    wordHashSet known(randomShapeInsertion::keywords);
    known.insert({"output", "FoamFile"});
    for (const entry& e : dict)
    {
        if (!known.found(e.keyword()))
        {
            FatalIOErrorInFunction(dict)
                << "Unknown keyword '" << e.keyword() << "'. Known keywords: "
                << flatOutput(known.sortedToc()) << exit(FatalIOError);
        }
    }

    randomShapeInsertion packing(dict);

    fileName output
    (
        dict.getOrDefault<fileName>("output", "constant/packedParticles")
    );
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
    packing.write(os, args.executable());

    Info<< "Wrote " << packing.positions().size() << " particles to "
        << output << nl << endl;
    runTime.printExecutionTime(Info);

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
