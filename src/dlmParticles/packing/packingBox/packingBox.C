/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "packingBox.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::packingBox::packingBox(const dictionary& dict, const scalar radius)
{
    ITstream& is = dict.lookup("box");
    is >> lowerCorner_ >> upperCorner_;
    dict.checkITstream(is, "box");
    length_ = upperCorner_ - lowerCorner_;
    periodic_ = dict.get<FixedList<bool, 3>>("periodic");

    for (direction i = 0; i < vector::nComponents; ++i)
    {
        if (length_[i] <= 0)
        {
            FatalIOErrorInFunction(dict)
                << "box " << lowerCorner_ << ' ' << upperCorner_
                << ": the min corner must be below the max corner in every"
                << " direction" << exit(FatalIOError);
        }
        if (!periodic_[i] && length_[i] < 2*radius)
        {
            FatalIOErrorInFunction(dict)
                << "box " << lowerCorner_ << ' ' << upperCorner_
                << " is narrower than a sphere of radius " << radius
                << " in the " << vector::componentNames[i]
                << " direction (walls, periodic no)" << exit(FatalIOError);
        }
        // Minimum image finds every overlap only if a sphere cannot touch
        // two images of another
        if (periodic_[i] && length_[i] < 4*radius)
        {
            FatalIOErrorInFunction(dict)
                << "box " << lowerCorner_ << ' ' << upperCorner_
                << " is shorter than two diameters (4 radius = " << 4*radius
                << ") in the periodic " << vector::componentNames[i]
                << " direction" << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::Pair<Foam::point> Foam::packingBox::centreRange
(
    const scalar diameter
) const
{
    Pair<point> range(lowerCorner_, upperCorner_);
    for (direction i = 0; i < vector::nComponents; ++i)
    {
        if (!periodic_[i])
        {
            const scalar clearance = Foam::min(diameter/2, length_[i]/2);
            range.first()[i] += clearance;
            range.second()[i] -= clearance;
        }
    }
    return range;
}


// ************************************************************************* //
