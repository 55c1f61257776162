/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "particleSurface.H"
#include "dlmParticleCloud.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace refinementTargets
{
    defineTypeNameAndDebug(particleSurface, 0);
    addToRunTimeSelectionTable(refinementTarget, particleSurface, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::refinementTargets::particleSurface::particleSurface
(
    const dictionary& dict
)
:
    refinementTarget(dict),
    cellsOutside_(dict.getCheckOrDefault<scalar>("cells", 3, scalarMinMax::ge(0))),
    cellsInside_
    (
        dict.getCheckOrDefault<scalar>("cellsInside", 1, scalarMinMax::ge(0))
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::refinementTargets::particleSurface::typeKeywords()
{
    wordList known(refinementTarget::typeKeywords());
    known.append(wordList({"cells", "cellsInside"}));
    return known;
}


Foam::wordList Foam::refinementTargets::particleSurface::keywords() const
{
    return typeKeywords();
}


void Foam::refinementTargets::particleSurface::mark
(
    const dlmParticleCloud& cloud,
    const labelList& cellLevel,
    const scalar lookAhead,
    const bool keep,
    labelList& targetLevel
) const
{
    const vectorField& C = cloud.mesh().C();

    const scalar widestBand =
        searchMargin(cloud, cellLevel, max(cellsOutside_, cellsInside_), keep);

    DynamicList<label> nearCells;
    for (const dlmParticle& p : cloud.particles())
    {
        const scalar motion = p.surfaceSpeed()*lookAhead;
        const scalar margin =
            p.shape().boundingRadius() + widestBand + motion;
        findCellsNear(cloud, p.position(), margin, nearCells);
        for (const label celli : nearCells)
        {
            if (targetLevel[celli] >= level())
            {
                continue;
            }
            const scalar cellReach = reach(cloud, celli, keep);
            const scalar d = surfaceDistance(p, C[celli]);
            if
            (
                d - cellReach
             <= bandWidth(cloud, cellLevel, cellsOutside_, celli) + motion
             && d + cellReach
             >= -(bandWidth(cloud, cellLevel, cellsInside_, celli) + motion)
            )
            {
                targetLevel[celli] = level();
            }
        }
    }
}


// ************************************************************************* //
