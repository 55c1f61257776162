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
    scalar volume = 0;
    for (const boundBox& bb : cellBoxes_)
    {
        bounds.add(bb);
        volume += cmptProduct(bb.span());
    }
    origin_ = bounds.min();

    // A flat mesh (2D, one cell thick) has one bin across its thickness:
    // count its cells by their area
    const vector span(bounds.span());
    scalar extent = 0;
    label nDims = 0;
    scalar cellMeasure = 0;
    {
        scalar product = 1;
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            extent = max(extent, span[d]);
        }
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (span[d] > 1e-3*extent)
            {
                ++nDims;
                product *= span[d];
            }
        }
        cellMeasure = product/nCells;
    }
    binSize_ = Foam::pow(cellMeasure, 1.0/nDims);
    if (nDims == 3)
    {
        binSize_ = max(binSize_, Foam::cbrt(volume/nCells));
    }
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        nBins_[d] = max(label(1), label(std::ceil(span[d]/binSize_)));
    }
    while (scalar(nBins_.x())*nBins_.y()*nBins_.z() > 4.0*nCells)
    {
        binSize_ *= 1.25;
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            nBins_[d] = max(label(1), label(std::ceil(span[d]/binSize_)));
        }
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
    Vector<label> lo, hi;
    for (label pass = 0; pass < 2; ++pass)
    {
        forAll(cellBoxes_, celli)
        {
            binRange(shrunk(cellBoxes_[celli]), lo, hi);
            for (label k = lo.z(); k <= hi.z(); ++k)
            {
                for (label j = lo.y(); j <= hi.y(); ++j)
                {
                    for (label i = lo.x(); i <= hi.x(); ++i)
                    {
                        const label b = i + nBins_.x()*(j + nBins_.y()*k);
                        if (pass == 0)
                        {
                            ++counts[b + 1];
                        }
                        else
                        {
                            binCells_[counts[b]++] = celli;
                        }
                    }
                }
            }
        }
        if (pass == 0)
        {
            for (label b = 0; b < nAllBins; ++b)
            {
                counts[b + 1] += counts[b];
            }
            binStarts_ = counts;
            binCells_.setSize(counts[nAllBins]);
        }
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
    Vector<label> lo, hi;
    binRange(boundBox(bb.min() - eps, bb.max() + eps), lo, hi);
    for (label k = lo.z(); k <= hi.z(); ++k)
    {
        for (label j = lo.y(); j <= hi.y(); ++j)
        {
            for (label i = lo.x(); i <= hi.x(); ++i)
            {
                const label b = i + nBins_.x()*(j + nBins_.y()*k);
                for (label s = binStarts_[b]; s < binStarts_[b + 1]; ++s)
                {
                    const label celli = binCells_[s];
                    if (stamp_[celli] != query_ && bb.overlaps(cellBoxes_[celli]))
                    {
                        stamp_[celli] = query_;
                        found.append(celli);
                    }
                }
            }
        }
    }
}


// ************************************************************************* //
