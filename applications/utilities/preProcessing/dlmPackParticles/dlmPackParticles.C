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
#include "randomShapeInsertion.H"
#include "packIntoFile.H"

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

    packIntoFile<randomShapeInsertion>
    (
        runTime,
        "packParticlesDict",
        "constant/packedParticles",
        args.executable()
    );

    runTime.printExecutionTime(Info);

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
