/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
-------------------------------------------------------------------------------
Application
    dlmDEMFoam

Description
    Dry particles: the particles of constant/particleProperties under gravity
    (constant/g) and their contacts, with no fluid (a discrete element
    method run, for contact checks and granular scenes). The mesh gives the
    domain and, unless the contact settings say 'meshWalls false', the
    walls; no field is solved and, with the exact overlap, no volume
    fraction is computed.

    Each step the free particles take gravity's impulse, then the contact
    sub-steps move them (particleContact). A particle whose centre leaves
    the mesh, which bounds the scene, stops the run after its state is
    written, unless an outlet removed it; so do two particles meeting in a
    case without contacts. The output is pimpleDLMFoam's:
    postProcessing/particles, VTK/particles and <time>/uniform/particles for
    restart. At the end the run prints its particle-steps per second.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "dlmParticleCloud.H"
#include "uniformDimensionedFields.H"
#include "runProgress.H"
#include "cpuTime.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Dry particles under gravity with contacts (no fluid)."
    );

    #include "setRootCaseLists.H"
    #include "createTime.H"
    runProgress progress(runTime);
    #include "checkDeltaT.H"
    #include "createMesh.H"
    #include "readGravitationalAcceleration.H"

    Info<< "Reading particles\n" << endl;
    dlmParticleCloud particles
    (
        mesh,
        dimensionedScalar(dimDensity, Zero),
        true
    );

    const vector gravity(g.value());
    label particleSteps = 0;
    const cpuTime timer;

    if (runTime.timeIndex() == runTime.startTimeIndex())
    {
        particles.writeVTK();
    }

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        ++runTime;
        progress.update();
        // Also after a change of system/controlDict while running
        #include "checkDeltaT.H"

        Info<< "Time = " << runTime.timeName() << nl << endl;

        const scalar deltaT = runTime.deltaTValue();
        for (dlmParticle& p : particles.particles())
        {
            if (p.isFree())
            {
                p.setVelocities
                (
                    p.velocity0() + gravity*deltaT,
                    p.angularVelocity0()
                );
            }
        }
        particles.setProjected();
        particles.move();
        particles.removeLeaving();
        particles.checkInMesh();
        particles.checkApart();
        particles.printSummary();

        // The last step and a stop (a particle out of the mesh, or without
        // contacts two overlapping) write their state, whatever the write
        // interval
        const bool stopping = particles.mustStop();
        const bool lastStep = progress.lastStep();
        particles.writeStep(stopping || lastStep);
        particleSteps += particles.particles().size();

        if (stopping || lastStep)
        {
            runTime.writeNow();
        }
        else
        {
            runTime.write();
        }
        if (stopping)
        {
            particles.failStop();
        }
        runTime.printExecutionTime(Info);
    }

    Info<< "Particle-steps per CPU second: "
        << particleSteps/max(timer.elapsedCpuTime(), SMALL) << nl << endl;

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
