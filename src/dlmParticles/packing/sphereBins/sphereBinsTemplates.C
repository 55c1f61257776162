/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "sphereBins.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Visitor>
bool Foam::sphereBins::forNeighbours
(
    const point& p,
    const Visitor& visit
) const
{
    for (const label other : neighbours_[binOf(p)])
    {
        for (label j = first_[other]; j != -1; j = next_[j])
        {
            if (!visit(j))
            {
                return false;
            }
        }
    }
    return true;
}


template<class PairVisitor>
void Foam::sphereBins::forAllPairs(const PairVisitor& visit) const
{
    forAll(first_, bin)
    {
        for (label i = first_[bin]; i != -1; i = next_[i])
        {
            for (const label other : neighbours_[bin])
            {
                for (label j = first_[other]; j != -1; j = next_[j])
                {
                    if (j > i)
                    {
                        visit(i, j);
                    }
                }
            }
        }
    }
}


// ************************************************************************* //
