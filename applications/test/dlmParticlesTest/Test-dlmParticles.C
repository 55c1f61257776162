/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
-------------------------------------------------------------------------------
Application
    Test-dlmParticles

Description
    Unit tests of the dlmParticles library (Catch2).

    Usage: Test-dlmParticles <caseDir> [Catch2 options, e.g. "[3D]"]

    Geometry tests need no case; tests tagged [3D], [2D] or [gap] use the
    mesh of <caseDir> (a 3D box, a one-cell-thick 2D box, or the 3D box
    with fixed spheres across narrow gaps, each with its own
    constant/particleProperties).

\*---------------------------------------------------------------------------*/

#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "testCase.H"
#include "argList.H"
#include "OSspecific.H"

using namespace Foam;

namespace
{
    autoPtr<Time> timePtr;
    autoPtr<fvMesh> meshPtr;
}


Time& testCase::time()
{
    return *timePtr;
}


fvMesh& testCase::mesh()
{
    return *meshPtr;
}


bool testCase::available()
{
    return meshPtr.valid();
}


int main(int argc, char* argv[])
{
    if (argc < 2)
    {
        std::cerr << "Usage: " << argv[0] << " <caseDir> [Catch2 options]\n";
        return 2;
    }

    argList::noBanner();
    fileName caseDir(argv[1]);
    if (!caseDir.isAbsolute())
    {
        caseDir = cwd()/caseDir;
    }

    if (isDir(caseDir/"constant"/"polyMesh"))
    {
        timePtr.reset
        (
            new Time
            (
                Time::controlDictName,
                fileName(caseDir.path()),
                fileName(caseDir.name())
            )
        );
        meshPtr.reset
        (
            new fvMesh
            (
                IOobject
                (
                    fvMesh::defaultRegion,
                    timePtr->timeName(),
                    *timePtr,
                    IOobject::MUST_READ
                )
            )
        );
    }

    // Catch2 sees the program name and the options after the case
    argv[1] = argv[0];
    const int result = Catch::Session().run(argc - 1, argv + 1);

    meshPtr.clear();
    timePtr.clear();

    return result;
}
