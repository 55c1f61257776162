/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
-------------------------------------------------------------------------------
Application
    dlmPackSpheres

Group
    grpPreProcessingUtilities

Description
    Random packing of equal spheres in a box at a requested solid fraction,
    without overlaps and reproducible from a seed, written as a particle file
    (lines "x y z radius", full precision, '#' comments) for particleFile in
    constant/particleProperties. The packing is Foam::randomSpherePacking's
    (FIRE relaxation of random centres, then hard-sphere Monte Carlo
    compression above a solid fraction of 0.62); a run that reaches
    maxIterations stops with an error and writes nothing.

Usage
    \b dlmPackSpheres [OPTIONS]

    system/packSpheresDict holds the box, the spheres and how to pack them,
    as in the Usage of Foam::randomSpherePacking
    (src/dlmParticles/packing/randomSpherePacking/randomSpherePacking.H),
    and the file to write:
    \verbatim
    output          "constant/packing.dat";     // optional, default
    \endverbatim

    constant/particleProperties then reads the file with, for instance:
    \verbatim
    particleFile        "constant/packing.dat";
    particleFileDefaults
    {
        shape       sphere;
        density     2500;
        motion      fixed;
    }
    \endverbatim

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "randomSpherePacking.H"
#include "packIntoFile.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Random packing of equal spheres without overlaps at a requested"
        " solid fraction, from system/packSpheresDict, written as a particle"
        " file (lines 'x y z radius') for particleFile"
    );
    argList::noParallel();

    #include "setRootCase.H"
    #include "createTime.H"

    packIntoFile<randomSpherePacking>
    (
        runTime,
        "packSpheresDict",
        "constant/packing.dat",
        args.executable()
    );

    runTime.printExecutionTime(Info);

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
