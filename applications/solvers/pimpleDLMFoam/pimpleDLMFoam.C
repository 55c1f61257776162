/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
-------------------------------------------------------------------------------
Application
    pimpleDLMFoam

Description
    Transient solver for incompressible laminar flow with freely moving,
    fixed or prescribed rigid particles resolved on a fixed mesh by the
    distributed Lagrange multiplier (DLM) method of Kanarska, Lomov and
    Antoun (2011, Computational Particle Mechanics).

    Each time step:
    0. with constant/dynamicMeshDict (dlmRefineFvMesh), refinement at the
       particles' places (a fresh start is refined before its first step);
       the particles' fractions, the projection's cells and force, the
       flux and the step limits follow each change (updateMesh.H);
    1. PIMPLE solution of the momentum and pressure equations on the whole
       mesh with the mixture density rho = rhoFluid + sum_p (rho_p -
       rhoFluid) alpha_p:

           rho (ddt(U) + div(phi, U)) - laplacian(mu, U) = - grad(p_rgh)

       p_rgh = p - rhoFluid (g & x) is the pressure less the fluid's
       hydrostatic part, so a fluid at rest stays at rest exactly;
    2. rigid-body projection in the particles (the rigidProjection fvOption,
       applied after each pressure correction), which also gives each free
       particle the impulse of its weight less its buoyancy;
    3. contacts, particle motion and new volume fractions
       (dlmParticleCloud);
    4. the follow step (rigidProjection::followParticles): the forced
       cells take the contacts' change of the particles' velocities, and
       the excess mass (rho_s - rho_f) phi a particle heavier than the fluid
       moved into or out of a cell carries the particle's momentum, not the
       fluid's (at both time levels of a backward time derivative);
    5. free particles whose centroid entered an outlet (particleProperties
       'outlets') leave the simulation, counted and recorded.

    The convection term takes the fluid's density: the solid is carried by
    the particles' motion (step 4), not by the flux (measurements:
    validation/cases/heavyParticles.md).

    In the first outer corrector the convection takes the flux of the last
    two steps extrapolated to the new time (PIMPLE extrapolateFlux, default
    yes): with the last step's alone, the flow a moving particle carries
    lagged a step.

    The time step also keeps the viscous number nu deltaT/h^2 within
    maxViscousNumber (system/controlDict; default 50 with three or more
    pressure correctors, 1 with fewer), where the projection is stable.

    A fresh start with moving particles (an initial velocity or angular
    velocity) starts the fluid with them: rigid inside each particle and
    the flow of an impulsive start around it, so that the particles keep
    their velocity. The last step's state is always written, and a run
    stopped by a free particle reaching a wall, or two particles meeting,
    without contacts writes its state and ends with an error. The log has
    a line per step on the particles and, every progressInterval seconds of
    wall time (system/controlDict, default 10), the run's progress (see
    runProgress).

    Inputs: constant/transportProperties (rho, nu of the fluid), constant/g,
    constant/particleProperties, system/fvOptions (rigidProjection), fields
    U and p_rgh; optional constant/dynamicMeshDict (refinement).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "dlmRefineFvMesh.H"
#include "pimpleControl.H"
#include "fvOptions.H"
#include "dlmParticleCloud.H"
#include "runProgress.H"
#include "rigidProjection.H"
#include "cpuTime.H"
#include "cellAspectRatio.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Transient solver for incompressible laminar flow with rigid"
        " particles resolved by the distributed Lagrange multiplier method."
    );

    #include "postProcess.H"

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"
    #include "createTime.H"
    runProgress progress(runTime);
    #include "createDynamicMesh.H"
    #include "createPimpleControl.H"
    #include "createTimeControls.H"
    #include "checkDeltaT.H"
    #include "checkTimeControls.H"

    #include "createFields.H"
    #include "initContinuityErrs.H"

    // Smallest squared distance between neighbouring cell centres
    scalar minDeltaSqr = sqr(particles.cellSizeMin());
    scalar aspectRatio = cellAspectRatioMax(mesh);

    #include "createFaceVelocity.H"
    // Time spent changing the mesh, and following the change (fields,
    // particles, projection and flux), reported at the end
    label nMeshChanges = 0;
    scalar meshChangeCpu = 0;
    scalar meshFollowCpu = 0;
    #include "refineAtStart.H"
    #include "initialParticleVelocity.H"
    #include "CourantNo.H"
    #include "setInitialDeltaT.H"

    Info<< "Largest cell aspect ratio: " << aspectRatio << endl;
    #include "viscousNumber.H"

    // * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

    if (runTime.timeIndex() == runTime.startTimeIndex())
    {
        particles.writeVTK();
    }

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        #include "readTimeControls.H"
        #include "checkTimeControls.H"
        #include "updateMesh.H"
        #include "CourantNo.H"
        #include "particleCourantNo.H"
        #include "setDeltaT.H"
        #include "viscousNumber.H"

        ++runTime;
        // Also after a change of system/controlDict while running
        #include "checkDeltaT.H"
        progress.update();

        Info<< "Time = " << runTime.timeName() << nl << endl;

        while (pimple.loop())
        {
            #include "UEqn.H"

            while (pimple.correct())
            {
                #include "pEqn.H"
            }
        }

        // Contacts, motion and new fractions; then the flow takes the
        // contacts' change and the solid mass moved into new cells
        particles.move();
        if (projection)
        {
            projection->followParticles(U, phi);
        }
        if (particles.removeLeaving() && projection)
        {
            projection->recordFractions(particles);
        }
        particles.checkInMesh();
        particles.checkApart();
        particles.printSummary();

        // The last step and a stop (without contacts a particle at a wall
        // or two overlapping; a particle out of the mesh) write their
        // state, whatever the write interval
        const bool stopping = particles.mustStop();
        const bool lastStep = progress.lastStep();

        const cpuTime outputTimer;
        particles.writeStep(stopping || lastStep);
        particles.addWorkTime
        (
            dlmParticleCloud::workPart::output,
            outputTimer.elapsedCpuTime()
        );

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

    particles.printWorkTime(runTime.elapsedCpuTime());
    if (mesh.dynamic())
    {
        Info<< "Mesh changes: " << nMeshChanges << ", refining "
            << meshChangeCpu << " s and following the change "
            << meshFollowCpu << " s, "
            << 100*(meshChangeCpu + meshFollowCpu)/runTime.elapsedCpuTime()
            << " % of the execution time" << endl;
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
