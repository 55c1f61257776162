/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "sphereBins.H"
#include "DynamicList.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelList Foam::sphereBins::neighbourBins(const labelVector& ijk) const
{
    DynamicList<label> neighbours(27);
    labelVector offset;
    for (offset.z() = -1; offset.z() <= 1; ++offset.z())
    {
        for (offset.y() = -1; offset.y() <= 1; ++offset.y())
        {
            for (offset.x() = -1; offset.x() <= 1; ++offset.x())
            {
                labelVector other(ijk + offset);
                bool inside = true;
                for (direction i = 0; i < vector::nComponents; ++i)
                {
                    if (box_.periodic(i))
                    {
                        other[i] = (other[i] + nBins_[i]) % nBins_[i];
                    }
                    else if (other[i] < 0 || other[i] >= nBins_[i])
                    {
                        inside = false;
                    }
                }
                if (inside && !neighbours.found(binIndex(other)))
                {
                    neighbours.append(binIndex(other));
                }
            }
        }
    }
    return labelList(std::move(neighbours));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::sphereBins::sphereBins
(
    const packingBox& box,
    const scalar minWidth,
    const label n
)
:
    box_(box),
    next_(n)
{
    // Not much more than one bin per sphere in dilute packings
    const scalar width =
        Foam::max(minWidth, std::cbrt(cmptProduct(box.length())/n));
    for (direction i = 0; i < vector::nComponents; ++i)
    {
        nBins_[i] = Foam::max(label(1), label(box.length()[i]/width));
        binWidth_[i] = box.length()[i]/nBins_[i];
    }

    first_.setSize(cmptProduct(nBins_));
    neighbours_.setSize(first_.size());

    labelVector ijk;
    for (ijk.z() = 0; ijk.z() < nBins_.z(); ++ijk.z())
    {
        for (ijk.y() = 0; ijk.y() < nBins_.y(); ++ijk.y())
        {
            for (ijk.x() = 0; ijk.x() < nBins_.x(); ++ijk.x())
            {
                neighbours_[binIndex(ijk)] = neighbourBins(ijk);
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::sphereBins::fill(const pointField& centres)
{
    first_ = -1;
    forAll(centres, i)
    {
        const label bin = binOf(centres[i]);
        next_[i] = first_[bin];
        first_[bin] = i;
    }
}


void Foam::sphereBins::move(const label i, const point& from, const point& to)
{
    const label oldBin = binOf(from);
    const label newBin = binOf(to);
    if (oldBin == newBin)
    {
        return;
    }
    if (first_[oldBin] == i)
    {
        first_[oldBin] = next_[i];
    }
    else
    {
        label k = first_[oldBin];
        while (next_[k] != i)
        {
            k = next_[k];
        }
        next_[k] = next_[i];
    }
    next_[i] = first_[newBin];
    first_[newBin] = i;
}


// ************************************************************************* //
