/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "runProgress.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::runProgress::runProgress(const Time& runTime)
:
    runTime_(runTime),
    startTime_(runTime.value()),
    clock_(),
    lastReport_(0)
{
    Sout.precision(logPrecision);
    static_cast<OSstream&>(FatalError).precision(logPrecision);
    static_cast<OSstream&>(FatalIOError).precision(logPrecision);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::runProgress::update()
{
    // Reading a modified controlDict resets it to writePrecision
    Sout.precision(logPrecision);

    const scalar interval =
        runTime_.controlDict().getOrDefault<scalar>("progressInterval", 10);
    const scalar wall = clock_.elapsedTime();
    if (interval <= 0 || wall - lastReport_ < interval)
    {
        return;
    }
    lastReport_ = wall;

    const scalar endTime = runTime_.endTime().value();
    const scalar done = runTime_.value() - startTime_;
    const scalar total = endTime - startTime_;
    Info<< "Progress: t = " << runTime_.value() << " of " << endTime
        << " (" << label(100*runTime_.value()/max(endTime, VSMALL))
        << " %), wall time " << label(wall) << " s";
    if (done > 0 && total > done)
    {
        Info<< ", about " << label(wall*(total - done)/done) << " s left";
    }
    Info<< endl;
}


// ************************************************************************* //
