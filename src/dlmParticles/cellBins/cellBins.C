/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "cellBins.H"

#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::cellBins::binRange
(
    const boundBox& bb,
    Vector<label>& lo,
    Vector<label>& hi
) const
{
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        const scalar a = (bb.min()[d] - origin_[d])/binSize_;
        const scalar b = (bb.max()[d] - origin_[d])/binSize_;
        lo[d] = max(label(0), min(nBins_[d] - 1, label(std::floor(a))));
        hi[d] = max(label(0), min(nBins_[d] - 1, label(std::floor(b))));
    }
}


template<class BinOp>
void Foam::cellBins::forAllBins(const boundBox& bb, const BinOp& op) const
{
    Vector<label> lo, hi;
    binRange(bb, lo, hi);
    for (label k = lo.z(); k <= hi.z(); ++k)
    {
        for (label j = lo.y(); j <= hi.y(); ++j)
        {
            for (label i = lo.x(); i <= hi.x(); ++i)
            {
                op(i + nBins_.x()*(j + nBins_.y()*k));
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cellBins::cellBins(const List<boundBox>& cellBoxes)
:
    cellBoxes_(cellBoxes),
    origin_(Zero),
    binSize_(1),
    nBins_(1, 1, 1),
    stamp_(cellBoxes.size(), -1),
    query_(0)
{
    const label nCells = cellBoxes_.size();
    binStarts_.setSize(2, 0);
    if (nCells == 0)
    {
        return;
    }

    boundBox bounds;
    for (const boundBox& bb : cellBoxes_)
    {
        bounds.add(bb);
    }
    origin_ = bounds.min();

    // The mean cell size if the cells filled the bounds; a flat mesh (2D,
    // one cell thick) has one bin across its thickness and is measured by
    // its area
    const vector span(bounds.span());
    const scalar extent = cmptMax(span);
    label nDims = 0;
    scalar measure = 1;
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (span[d] > 1e-3*extent)
        {
            ++nDims;
            measure *= span[d];
        }
    }
    binSize_ = Foam::pow(measure/nCells, 1.0/nDims);
    auto countBins = [&]()
    {
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            nBins_[d] = max(label(1), label(std::ceil(span[d]/binSize_)));
        }
        return scalar(nBins_.x())*nBins_.y()*nBins_.z();
    };
    while (countBins() > 4.0*nCells)
    {
        binSize_ *= 1.25;
    }

    // A box is binned shrunk by a small fraction of itself: a cell whose
    // face lies on a bin edge is not listed in the next bin as well
    auto shrunk = [](const boundBox& bb)
    {
        const vector eps(1e-9*bb.span());
        return boundBox(bb.min() + eps, bb.max() - eps);
    };

    const label nAllBins = nBins_.x()*nBins_.y()*nBins_.z();
    labelList counts(nAllBins + 1, 0);
    forAll(cellBoxes_, celli)
    {
        forAllBins(shrunk(cellBoxes_[celli]), [&](const label b)
        {
            ++counts[b + 1];
        });
    }
    for (label b = 0; b < nAllBins; ++b)
    {
        counts[b + 1] += counts[b];
    }
    binStarts_ = counts;
    binCells_.setSize(counts[nAllBins]);
    forAll(cellBoxes_, celli)
    {
        forAllBins(shrunk(cellBoxes_[celli]), [&](const label b)
        {
            binCells_[counts[b]++] = celli;
        });
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::cellBins::findBox
(
    const boundBox& bb,
    DynamicList<label>& found
) const
{
    if (cellBoxes_.empty())
    {
        return;
    }
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if
        (
            bb.max()[d] < origin_[d]
         || bb.min()[d] > origin_[d] + nBins_[d]*binSize_
        )
        {
            return;
        }
    }

    if (query_ == labelMax)
    {
        stamp_ = -1;
        query_ = 0;
    }
    ++query_;

    // Cells are binned shrunk: a cell that touches the query at a bin edge
    // lies in the bin on the other side, so the range is taken widened
    const vector eps(vector::uniform(1e-6*binSize_));
    forAllBins(boundBox(bb.min() - eps, bb.max() + eps), [&](const label b)
    {
        for (label s = binStarts_[b]; s < binStarts_[b + 1]; ++s)
        {
            const label celli = binCells_[s];
            if (stamp_[celli] != query_ && bb.overlaps(cellBoxes_[celli]))
            {
                stamp_[celli] = query_;
                found.append(celli);
            }
        }
    });
}

// ************************************************************************* //
