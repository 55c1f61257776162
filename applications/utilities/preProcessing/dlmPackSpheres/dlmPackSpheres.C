/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
-------------------------------------------------------------------------------
Application
    dlmPackSpheres

Group
    grpPreProcessingUtilities

Description
    Random packing of equal spheres in a box at a requested solid fraction,
    without overlaps and reproducible from a seed, written as a particle file
    (lines "x y z radius", full precision, '#' comments) for particleFile in
    constant/particleProperties.

    The centres start at random positions (OpenFOAM's Random, seeded with
    'seed'). Up to a solid fraction of 0.62 their overlaps are removed by
    minimising the energy of soft spheres marginally larger than the
    requested ones with FIRE (Bitzek et al. 2006, Phys. Rev. Lett. 97,
    170201). Denser packings are relaxed so at 0.5 and then compressed by
    hard-sphere Monte Carlo: sweeps of random displacements, rejected on
    overlap, each followed by growing the diameter by 5 % of the smallest
    gap, as in the compression of Lubachevsky and Stillinger (1990) without
    its event-driven dynamics. Neighbours are found in bins one diameter
    wide. Periodic directions use the minimum-image convention (the box must
    be at least two diameters long in them) and wrap the centres into the
    box; in the other directions walls keep the centres at least one radius
    from the faces. At the end the packing is checked without margin: no
    two centres closer than a diameter.

    Random packings of equal spheres jam near a solid fraction of 0.64 (random
    close packing), and walls lower that. In a periodic box a thousand
    spheres reach 0.62 in seconds; about 100 spheres reach 0.64 in a second
    (20000 sweeps) and jam near 0.643, but the compression slows with the
    number of spheres (the smallest gap limits each sweep's growth): 1200
    spheres get from 0.5 only to 0.60 in 100000 sweeps (90 s). A run
    that reaches maxIterations (relaxation iterations, then compression
    sweeps) stops with an error and writes nothing.

Usage
    \b dlmPackSpheres [OPTIONS]

    system/packSpheresDict:
    \verbatim
    box             (0 0 0) (0.01 0.01 0.01);   // min and max corners
    periodic        (yes yes no);   // per direction x y z; no: walls
    radius          0.001;

    // Either the solid fraction, which gives
    // N = round(solidFraction*boxVolume/sphereVolume) spheres ...
    solidFraction   0.6;
    // ... or the number of spheres
    // nParticles   200;

    seed            1;                          // optional, default 1
    output          "constant/packing.dat";     // optional, default
    maxIterations   100000;                     // optional, default
    \endverbatim

    constant/particleProperties then reads the file with, for instance:
    \verbatim
    particleFile        "constant/packing.dat";
    particleFileDefaults
    {
        shape       sphere;
        density     2500;
        motion      fixed;
    }
    \endverbatim

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "Random.H"
#include "HashSet.H"
#include "labelVector.H"
#include "Pair.H"
#include "pointField.H"
#include "mathematicalConstants.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- The soft spheres of the relaxation are larger than the requested ones by
//  this relative margin, and the relaxation stops once no two centres are
//  closer than (1 + gapMargin) diameters: the written packing then has no
//  overlap despite rounding
const scalar contactMargin = 1e-6;
const scalar gapMargin = 1e-9;

//- Relaxing random centres at the final fraction works up to about 0.62;
//  denser packings are relaxed at compressionStart and then compressed
const scalar relaxedMax = 0.62;
const scalar compressionStart = 0.5;

//- Densest packing of equal spheres (face-centred cubic)
const scalar densestFraction = constant::mathematical::pi/std::sqrt(18.0);

//- Iterations between progress reports
const label reportInterval = 10000;


//- Cuboid box, periodic or bounded by walls in each direction
struct packingBox
{
    point lowerCorner;
    point upperCorner;
    vector length;
    FixedList<bool, 3> periodic;

    //- Separation a - b, minimum image in the periodic directions
    vector separation(const point& a, const point& b) const
    {
        vector d(a - b);
        for (direction i = 0; i < vector::nComponents; ++i)
        {
            if (periodic[i])
            {
                d[i] -= length[i]*std::round(d[i]/length[i]);
            }
        }
        return d;
    }

    //- Whether p is in the box, at least radius from the walls
    bool holds(const point& p, const scalar radius) const
    {
        for (direction i = 0; i < vector::nComponents; ++i)
        {
            const bool outside =
                periodic[i]
              ? (p[i] < lowerCorner[i] || p[i] >= upperCorner[i])
              : (
                    p[i] - lowerCorner[i] < radius
                 || upperCorner[i] - p[i] < radius
                );
            if (outside)
            {
                return false;
            }
        }
        return true;
    }

    //- Move p into [lowerCorner, upperCorner) in the periodic directions
    void wrap(point& p) const
    {
        for (direction i = 0; i < vector::nComponents; ++i)
        {
            if (periodic[i])
            {
                p[i] -=
                    length[i]*std::floor((p[i] - lowerCorner[i])/length[i]);

                // Rounding of values just off the box
                if (p[i] < lowerCorner[i] || p[i] >= upperCorner[i])
                {
                    p[i] = lowerCorner[i];
                }
            }
        }
    }
};


//- Spheres sorted into a grid of bins no narrower than a given width, so
//  that any two centres closer than that width are in neighbouring bins
class sphereBins
{
    const packingBox& box_;

    //- Number and width of the bins in each direction
    labelVector nBins_;
    vector binWidth_;

    //- Neighbour bins of each bin
    labelListList neighbours_;

    //- First sphere of each bin (-1: empty) and next sphere in its bin
    labelList first_;
    labelList next_;

    label binIndex(const labelVector& ijk) const
    {
        return ijk.x() + nBins_.x()*(ijk.y() + nBins_.y()*ijk.z());
    }

    label binOf(const point& p) const
    {
        labelVector ijk;
        for (direction i = 0; i < vector::nComponents; ++i)
        {
            const label index
            (
                std::floor((p[i] - box_.lowerCorner[i])/binWidth_[i])
            );
            ijk[i] = Foam::min(nBins_[i] - 1, Foam::max(label(0), index));
        }
        return binIndex(ijk);
    }

    //- The bins around bin ijk, itself included, each listed once (with
    //  fewer than three bins across a periodic direction the bins on either
    //  side are the same)
    labelList neighbourBins(const labelVector& ijk) const
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
                        if (box_.periodic[i])
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

public:

    sphereBins(const packingBox& box, const scalar minWidth, const label n)
    :
        box_(box),
        next_(n)
    {
        // Not much more than one bin per sphere in dilute packings
        const scalar width =
            Foam::max(minWidth, std::cbrt(cmptProduct(box.length)/n));
        for (direction i = 0; i < vector::nComponents; ++i)
        {
            nBins_[i] = Foam::max(label(1), label(box.length[i]/width));
            binWidth_[i] = box.length[i]/nBins_[i];
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

    //- Width of the narrowest bins: all pairs closer than it are visited
    scalar minWidth() const
    {
        return cmptMin(binWidth_);
    }

    //- Sort the centres into the bins
    void fill(const pointField& centres)
    {
        first_ = -1;
        forAll(centres, i)
        {
            const label bin = binOf(centres[i]);
            next_[i] = first_[bin];
            first_[bin] = i;
        }
    }

    //- Move sphere i, at from, to its new centre to
    void move(const label i, const point& from, const point& to)
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

    //- Call visit(j) for each sphere j in the bins around point p; stops
    //  and returns false as soon as visit does
    template<class Visitor>
    bool forNeighbours(const point& p, const Visitor& visit) const
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

    //- Call visit(i, j) once for each pair i < j in neighbouring bins
    template<class PairVisitor>
    void forAllPairs(const PairVisitor& visit) const
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
};


//- Move the centres until no two are closer than minDistance, minimising
//  with FIRE the energy of soft spheres of diameter contactDiameter >
//  minDistance (harmonic repulsion, unit stiffness and mass) and keeping the
//  centres within [lowestCentre, highestCentre] in the wall directions.
//  Returns the number of iterations, -1 if maxIterations is reached first.
label removeOverlaps
(
    pointField& centres,
    const packingBox& box,
    const point& lowestCentre,
    const point& highestCentre,
    const scalar contactDiameter,
    const scalar minDistance,
    const label maxIterations
)
{
    // FIRE parameters of Bitzek et al.; times in units of the inverse
    // frequency of one contact
    const scalar dtStart = 0.1;
    const scalar dtMax = 1.0;
    const scalar dtGrowth = 1.1;
    const scalar dtCut = 0.5;
    const scalar mixingStart = 0.1;
    const scalar mixingDecay = 0.99;
    const label nDelay = 5;

    sphereBins bins(box, contactDiameter, centres.size());
    vectorField velocity(centres.size(), Zero);
    vectorField force(centres.size());
    scalar dt = dtStart;
    scalar mixing = mixingStart;
    label nDownhill = 0;

    for (label iteration = 0; iteration < maxIterations; ++iteration)
    {
        bins.fill(centres);
        force = Zero;
        scalar closest = GREAT;
        bins.forAllPairs
        (
            [&](const label i, const label j)
            {
                const vector d(box.separation(centres[i], centres[j]));
                const scalar distanceSqr = magSqr(d);
                if (distanceSqr < sqr(contactDiameter))
                {
                    const scalar distance = std::sqrt(distanceSqr);
                    closest = Foam::min(closest, distance);

                    // Coincident centres: any direction separates them
                    const vector normal
                    (
                        distance > 0 ? d/distance : vector(1, 0, 0)
                    );
                    const vector push((contactDiameter - distance)*normal);
                    force[i] += push;
                    force[j] -= push;
                }
            }
        );

        if (closest >= minDistance)
        {
            return iteration;
        }
        if (iteration && iteration % reportInterval == 0)
        {
            Info<< "Iteration " << iteration
                << ": smallest distance / contact diameter "
                << closest/contactDiameter << endl;
        }

        if (sum(force & velocity) > 0)
        {
            // Going downhill: turn the velocity toward the force, and speed
            // up once it has lasted
            const scalar speed = std::sqrt(sum(magSqr(velocity)));
            const scalar forceNorm = std::sqrt(sum(magSqr(force)));
            velocity =
                (1 - mixing)*velocity + (mixing*speed/forceNorm)*force;
            if (nDownhill > nDelay)
            {
                dt = Foam::min(dt*dtGrowth, dtMax);
                mixing *= mixingDecay;
            }
            ++nDownhill;
        }
        else
        {
            // Uphill: stop and restart cautiously
            velocity = Zero;
            dt *= dtCut;
            mixing = mixingStart;
            nDownhill = 0;
        }

        velocity += dt*force;
        forAll(centres, i)
        {
            point& p = centres[i];
            p += dt*velocity[i];
            box.wrap(p);
            for (direction d = 0; d < vector::nComponents; ++d)
            {
                if
                (
                    !box.periodic[d]
                 && (p[d] < lowestCentre[d] || p[d] > highestCentre[d])
                )
                {
                    p[d] = Foam::min
                    (
                        highestCentre[d],
                        Foam::max(lowestCentre[d], p[d])
                    );
                    velocity[i][d] = 0;
                }
            }
        }
    }

    return -1;
}


//- Hard-sphere Monte Carlo compression from non-overlapping spheres of
//  diameter startDiameter to finalDiameter: sweeps of random displacements
//  (rejected on overlap, step adapted to about a third accepted), each
//  followed by growing the diameter by 5 % of its gap to the smallest
//  separation (centre distance, or twice the wall distance): slow enough
//  growth to reach random close packing, as in Lubachevsky and
//  Stillinger's compression without its event-driven dynamics.
//  Returns the number of sweeps, -1 if maxSweeps is reached first, with
//  diameter the last one reached.
label compress
(
    pointField& centres,
    const packingBox& box,
    const scalar startDiameter,
    const scalar finalDiameter,
    const label maxSweeps,
    Random& rng,
    scalar& diameter
)
{
    const scalar growth = 0.05;
    sphereBins bins(box, (1 + contactMargin)*finalDiameter, centres.size());
    bins.fill(centres);
    diameter = startDiameter;
    scalar step = 0.1*startDiameter;

    auto wallDistance = [&](const point& p)
    {
        scalar distance = GREAT;
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (!box.periodic[d])
            {
                distance = Foam::min
                (
                    distance,
                    Foam::min
                    (
                        p[d] - box.lowerCorner[d],
                        box.upperCorner[d] - p[d]
                    )
                );
            }
        }
        return distance;
    };

    for (label sweep = 0; sweep < maxSweeps; ++sweep)
    {
        const scalar minDistance = (1 + gapMargin)*diameter;
        label nAccepted = 0;
        forAll(centres, i)
        {
            point trial(centres[i]);
            for (direction d = 0; d < vector::nComponents; ++d)
            {
                trial[d] += step*(2*rng.sample01<scalar>() - 1);
            }
            box.wrap(trial);
            if (wallDistance(trial) < 0.5*minDistance)
            {
                continue;
            }
            const bool free = bins.forNeighbours
            (
                trial,
                [&](const label j)
                {
                    return
                        j == i
                     || magSqr(box.separation(trial, centres[j]))
                     >= sqr(minDistance);
                }
            );
            if (free)
            {
                bins.move(i, centres[i], trial);
                centres[i] = trial;
                ++nAccepted;
            }
        }
        const scalar accepted = scalar(nAccepted)/centres.size();
        step *= accepted < 0.25 ? 0.8 : (accepted > 0.4 ? 1.2 : 1);
        step = Foam::min(step, 0.1*finalDiameter);

        scalar smallest = GREAT;
        for (const point& p : centres)
        {
            smallest = Foam::min(smallest, 2*wallDistance(p));
        }
        bins.forAllPairs
        (
            [&](const label i, const label j)
            {
                smallest = Foam::min
                (
                    smallest,
                    mag(box.separation(centres[i], centres[j]))
                );
            }
        );
        diameter = Foam::min
        (
            finalDiameter,
            diameter + growth*(smallest/(1 + gapMargin) - diameter)
        );
        if (diameter >= finalDiameter)
        {
            return sweep + 1;
        }
        if ((sweep + 1) % reportInterval == 0)
        {
            Info<< "Sweep " << sweep + 1 << ": diameter / final "
                << diameter/finalDiameter << endl;
        }
    }
    return -1;
}


//- Smallest minimum-image distance between two centres (GREAT for a single
//  centre), searched in bins from binWidth wide up to the whole box
scalar smallestDistance
(
    const pointField& centres,
    const packingBox& box,
    const scalar binWidth
)
{
    for (scalar width = binWidth; ; width *= 2)
    {
        sphereBins bins(box, width, centres.size());
        bins.fill(centres);
        scalar smallest = GREAT;
        bins.forAllPairs
        (
            [&](const label i, const label j)
            {
                smallest = Foam::min
                (
                    smallest,
                    mag(box.separation(centres[i], centres[j]))
                );
            }
        );

        // Exact once below the bin width, or with all pairs visited
        if (smallest < bins.minWidth() || width >= cmptMax(box.length))
        {
            return smallest;
        }
    }
}


//- Box and periodicity from the dictionary, checked for spheres of radius
packingBox readBox(const dictionary& dict, const scalar radius)
{
    packingBox box;
    ITstream& is = dict.lookup("box");
    is >> box.lowerCorner >> box.upperCorner;
    dict.checkITstream(is, "box");
    box.length = box.upperCorner - box.lowerCorner;
    box.periodic = dict.get<FixedList<bool, 3>>("periodic");

    for (direction i = 0; i < vector::nComponents; ++i)
    {
        if (box.length[i] <= 0)
        {
            FatalIOErrorInFunction(dict)
                << "box " << box.lowerCorner << ' ' << box.upperCorner
                << ": the min corner must be below the max corner in every"
                << " direction" << exit(FatalIOError);
        }
        if (!box.periodic[i] && box.length[i] < 2*radius)
        {
            FatalIOErrorInFunction(dict)
                << "box " << box.lowerCorner << ' ' << box.upperCorner
                << " is narrower than a sphere of radius " << radius
                << " in the " << vector::componentNames[i]
                << " direction (walls, periodic no)" << exit(FatalIOError);
        }
        // Minimum image finds every overlap only if a sphere cannot touch
        // two images of another
        if (box.periodic[i] && box.length[i] < 4*radius)
        {
            FatalIOErrorInFunction(dict)
                << "box " << box.lowerCorner << ' ' << box.upperCorner
                << " is shorter than two diameters (4 radius = " << 4*radius
                << ") in the periodic " << vector::componentNames[i]
                << " direction" << exit(FatalIOError);
        }
    }
    return box;
}


//- Number of spheres from solidFraction or nParticles
label readNSpheres
(
    const dictionary& dict,
    const scalar boxVolume,
    const scalar sphereVolume
)
{
    const bool byFraction = dict.found("solidFraction");
    if (byFraction == dict.found("nParticles"))
    {
        FatalIOErrorInFunction(dict)
            << "Give exactly one of solidFraction and nParticles"
            << exit(FatalIOError);
    }

    label nSpheres;
    if (byFraction)
    {
        const scalar requested = dict.get<scalar>("solidFraction");
        if (requested <= 0 || requested > densestFraction)
        {
            FatalIOErrorInFunction(dict)
                << "solidFraction " << requested << " must be in (0, "
                << densestFraction << "], the densest packing of equal"
                << " spheres (pi/sqrt(18))" << exit(FatalIOError);
        }
        nSpheres = label(std::round(requested*boxVolume/sphereVolume));
        if (nSpheres < 1)
        {
            FatalIOErrorInFunction(dict)
                << "solidFraction " << requested << " gives no sphere: the"
                << " box holds " << boxVolume/sphereVolume << " sphere"
                << " volumes" << exit(FatalIOError);
        }
    }
    else
    {
        nSpheres = dict.get<label>("nParticles");
        if (nSpheres < 1)
        {
            FatalIOErrorInFunction(dict)
                << "nParticles " << nSpheres << " must be positive"
                << exit(FatalIOError);
        }
        const scalar fraction = nSpheres*sphereVolume/boxVolume;
        if (fraction > densestFraction)
        {
            FatalIOErrorInFunction(dict)
                << "nParticles " << nSpheres << " gives solid fraction "
                << fraction << ", above the densest packing of equal"
                << " spheres (pi/sqrt(18) = " << densestFraction << ")"
                << exit(FatalIOError);
        }
    }
    return nSpheres;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Random packing of equal spheres without overlaps at a requested"
        " solid fraction, from system/packSpheresDict, written as a particle"
        " file (lines 'x y z radius') for particleFile"
    );
    argList::noParallel();

    #include "setRootCase.H"
    #include "createTime.H"

    const IOdictionary dict
    (
        IOobject
        (
            "packSpheresDict",
            runTime.system(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    );

    const wordHashSet known
    ({
        "box", "periodic", "radius", "solidFraction", "nParticles", "seed",
        "output", "maxIterations", "FoamFile"
    });
    for (const entry& e : dict)
    {
        if (!known.found(e.keyword()))
        {
            FatalIOErrorInFunction(dict)
                << "Unknown keyword '" << e.keyword() << "'. Known keywords: "
                << flatOutput(known.sortedToc()) << exit(FatalIOError);
        }
    }

    const scalar radius = dict.get<scalar>("radius");
    if (radius <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "radius " << radius << " must be positive"
            << exit(FatalIOError);
    }
    const packingBox box(readBox(dict, radius));

    const scalar boxVolume = cmptProduct(box.length);
    const scalar sphereVolume =
        4.0/3.0*constant::mathematical::pi*pow3(radius);
    const label nSpheres = readNSpheres(dict, boxVolume, sphereVolume);
    const scalar fraction = nSpheres*sphereVolume/boxVolume;

    const label seed = dict.getOrDefault<label>("seed", 1);
    const label maxIterations =
        dict.getOrDefault<label>("maxIterations", 100000);
    if (maxIterations < 1)
    {
        FatalIOErrorInFunction(dict)
            << "maxIterations " << maxIterations << " must be positive"
            << exit(FatalIOError);
    }
    fileName output
    (
        dict.getOrDefault<fileName>("output", "constant/packing.dat")
    );
    output.expand();
    if (!output.isAbsolute())
    {
        output = runTime.globalPath()/output;
    }

    // Centres range over the whole of a periodic direction and stay one
    // (contact) radius from the walls, unless the sphere just fits
    const scalar diameter = 2*radius;
    auto centreRange = [&](const scalar contactDiameter)
    {
        Pair<point> range(box.lowerCorner, box.upperCorner);
        for (direction i = 0; i < vector::nComponents; ++i)
        {
            if (!box.periodic[i])
            {
                const scalar wallDistance =
                    Foam::min(contactDiameter/2, box.length[i]/2);
                range.first()[i] += wallDistance;
                range.second()[i] -= wallDistance;
            }
        }
        return range;
    };

    Info<< "Packing " << nSpheres << " spheres of radius " << radius
        << " at solid fraction " << fraction << ", seed " << seed << nl
        << endl;

    Random rng(seed);
    pointField centres(nSpheres);
    {
        const Pair<point> range(centreRange((1 + contactMargin)*diameter));
        for (point& p : centres)
        {
            for (direction i = 0; i < vector::nComponents; ++i)
            {
                p[i] =
                    range.first()[i]
                  + rng.sample01<scalar>()*(range.second()[i] - range.first()[i]);
            }
            box.wrap(p);
        }
    }

    // Random centres relax to no overlap at the final fraction up to
    // relaxedMax; denser packings relax at compressionStart and are then
    // compressed by Monte Carlo, which (as Lubachevsky-Stillinger) reaches
    // near random close packing (0.64), where relaxing random centres at the
    // final fraction jams near 0.62
    const scalar relaxDiameter =
        fraction <= relaxedMax
      ? diameter
      : diameter*Foam::cbrt(compressionStart/fraction);
    const Pair<point> range(centreRange((1 + contactMargin)*relaxDiameter));
    const label nIterations = removeOverlaps
    (
        centres,
        box,
        range.first(),
        range.second(),
        (1 + contactMargin)*relaxDiameter,
        (1 + gapMargin)*relaxDiameter,
        maxIterations
    );
    if (nIterations < 0)
    {
        FatalErrorInFunction
            << "Could not reach solid fraction " << fraction << " ("
            << nSpheres << " spheres): the overlaps of random centres at "
            << fraction*pow3(relaxDiameter/diameter) << " remain after"
            << " maxIterations " << maxIterations << " iterations" << nl
            << "    Lower solidFraction (or nParticles), or raise"
            << " maxIterations."
            << exit(FatalError);
    }
    label nSweeps = 0;
    if (relaxDiameter < diameter)
    {
        scalar reached = relaxDiameter;
        nSweeps = compress
        (
            centres, box, relaxDiameter, diameter, maxIterations, rng, reached
        );
        if (nSweeps < 0)
        {
            FatalErrorInFunction
                << "Could not reach solid fraction " << fraction << " ("
                << nSpheres << " spheres) in maxIterations " << maxIterations
                << " compression sweeps: reached "
                << fraction*pow3(reached/diameter) << nl
                << "    Lower solidFraction (or nParticles): random packings"
                << " of equal spheres jam near 0.64, less with walls; or"
                << " raise maxIterations."
                << exit(FatalError);
        }
    }

    // Check the final packing without margin
    const scalar smallest = smallestDistance(centres, box, diameter);
    if (smallest < diameter)
    {
        FatalErrorInFunction
            << "Packing check failed: two centres " << smallest
            << " apart, closer than a diameter " << diameter
            << exit(FatalError);
    }
    for (const point& p : centres)
    {
        if (!box.holds(p, radius))
        {
            FatalErrorInFunction
                << "Packing check failed: centre " << p << " outside the box"
                << " or closer than a radius to a wall" << exit(FatalError);
        }
    }

    const string gap
    (
        nSpheres > 1 ? Foam::name(smallest/diameter - 1) : "none"
    );
    Info<< "Removed the overlaps in " << nIterations << " iterations,"
        << " compressed in " << nSweeps << " sweeps;"
        << " smallest gap / diameter " << gap.c_str() << nl << endl;

    const auto yesNo = [](const bool b) { return b ? "yes" : "no"; };
    mkDir(output.path());
    OFstream os(output);
    if (!os.good())
    {
        FatalErrorInFunction
            << "Cannot write " << output << exit(FatalError);
    }
    os  << "# dlmPackSpheres: random packing of equal spheres, lines"
        << " \"x y z radius\"" << nl
        << "# box " << box.lowerCorner << ' ' << box.upperCorner << nl
        << "# periodic (" << yesNo(box.periodic[0]) << ' '
        << yesNo(box.periodic[1]) << ' ' << yesNo(box.periodic[2]) << ')'
        << nl
        << "# radius " << radius << nl
        << "# nParticles " << nSpheres << nl
        << "# solidFraction " << fraction << nl
        << "# seed " << seed << nl
        << "# smallest gap / diameter " << gap.c_str() << nl;
    os.precision(17);
    for (const point& p : centres)
    {
        os  << p.x() << ' ' << p.y() << ' ' << p.z() << ' ' << radius << nl;
    }

    Info<< "Wrote " << nSpheres << " spheres to " << output << nl << endl;
    runTime.printExecutionTime(Info);

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
