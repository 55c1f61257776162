/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "randomSpherePacking.H"
#include "sphereBins.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

const Foam::wordList Foam::randomSpherePacking::keywords
({
    "box", "periodic", "radius", "solidFraction", "nParticles", "seed",
    "maxIterations"
});

const Foam::scalar Foam::randomSpherePacking::contactMargin = 1e-6;
const Foam::scalar Foam::randomSpherePacking::gapMargin = 1e-9;

const Foam::scalar Foam::randomSpherePacking::relaxedMax = 0.62;
const Foam::scalar Foam::randomSpherePacking::compressionStart = 0.5;

const Foam::scalar Foam::randomSpherePacking::densestFraction =
    Foam::constant::mathematical::pi/std::sqrt(18.0);

const Foam::label Foam::randomSpherePacking::reportInterval = 10000;


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::randomSpherePacking::readRadius(const dictionary& dict)
{
    const scalar radius = dict.get<scalar>("radius");
    if (radius <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "radius " << radius << " must be positive"
            << exit(FatalIOError);
    }
    return radius;
}


Foam::label Foam::randomSpherePacking::readNSpheres
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


Foam::label Foam::randomSpherePacking::readMaxIterations
(
    const dictionary& dict
)
{
    const label maxIterations =
        dict.getOrDefault<label>("maxIterations", 100000);
    if (maxIterations < 1)
    {
        FatalIOErrorInFunction(dict)
            << "maxIterations " << maxIterations << " must be positive"
            << exit(FatalIOError);
    }
    return maxIterations;
}


Foam::scalar Foam::randomSpherePacking::sphereVolume() const
{
    return 4.0/3.0*constant::mathematical::pi*pow3(radius_);
}


void Foam::randomSpherePacking::placeRandomly(Random& rng)
{
    const Pair<point> range
    (
        box_.centreRange((1 + contactMargin)*diameter_)
    );
    centres_.setSize(nSpheres_);
    for (point& p : centres_)
    {
        for (direction i = 0; i < vector::nComponents; ++i)
        {
            p[i] =
                range.first()[i]
              + rng.sample01<scalar>()*(range.second()[i] - range.first()[i]);
        }
        box_.wrap(p);
    }
}


Foam::label Foam::randomSpherePacking::removeOverlaps
(
    const scalar relaxDiameter
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

    const scalar contactDiameter = (1 + contactMargin)*relaxDiameter;
    const scalar minDistance = (1 + gapMargin)*relaxDiameter;
    const Pair<point> range(box_.centreRange(contactDiameter));
    const point& lowestCentre = range.first();
    const point& highestCentre = range.second();

    sphereBins bins(box_, contactDiameter, centres_.size());
    vectorField velocity(centres_.size(), Zero);
    vectorField force(centres_.size());
    scalar dt = dtStart;
    scalar mixing = mixingStart;
    label nDownhill = 0;

    for (label iteration = 0; iteration < maxIterations_; ++iteration)
    {
        bins.fill(centres_);
        force = Zero;
        scalar closest = GREAT;
        bins.forAllPairs
        (
            [&](const label i, const label j)
            {
                const vector d(box_.separation(centres_[i], centres_[j]));
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
        forAll(centres_, i)
        {
            point& p = centres_[i];
            p += dt*velocity[i];
            box_.wrap(p);
            for (direction d = 0; d < vector::nComponents; ++d)
            {
                if
                (
                    !box_.periodic(d)
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


Foam::label Foam::randomSpherePacking::compress
(
    const scalar startDiameter,
    Random& rng,
    scalar& reachedDiameter
)
{
    const scalar growth = 0.05;
    sphereBins bins(box_, (1 + contactMargin)*diameter_, centres_.size());
    bins.fill(centres_);
    reachedDiameter = startDiameter;
    scalar step = 0.1*startDiameter;

    for (label sweep = 0; sweep < maxIterations_; ++sweep)
    {
        const scalar minDistance = (1 + gapMargin)*reachedDiameter;
        label nAccepted = 0;
        forAll(centres_, i)
        {
            point trial(centres_[i]);
            for (direction d = 0; d < vector::nComponents; ++d)
            {
                trial[d] += step*(2*rng.sample01<scalar>() - 1);
            }
            box_.wrap(trial);
            if (box_.wallDistance(trial) < 0.5*minDistance)
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
                     || magSqr(box_.separation(trial, centres_[j]))
                     >= sqr(minDistance);
                }
            );
            if (free)
            {
                bins.move(i, centres_[i], trial);
                centres_[i] = trial;
                ++nAccepted;
            }
        }
        const scalar accepted = scalar(nAccepted)/centres_.size();
        step *= accepted < 0.25 ? 0.8 : (accepted > 0.4 ? 1.2 : 1);
        step = Foam::min(step, 0.1*diameter_);

        scalar smallest = closestPairDistance(bins);
        for (const point& p : centres_)
        {
            smallest = Foam::min(smallest, 2*box_.wallDistance(p));
        }
        reachedDiameter = Foam::min
        (
            diameter_,
            reachedDiameter
          + growth*(smallest/(1 + gapMargin) - reachedDiameter)
        );
        if (reachedDiameter >= diameter_)
        {
            return sweep + 1;
        }
        if ((sweep + 1) % reportInterval == 0)
        {
            Info<< "Sweep " << sweep + 1 << ": diameter / final "
                << reachedDiameter/diameter_ << endl;
        }
    }
    return -1;
}


Foam::scalar Foam::randomSpherePacking::closestPairDistance
(
    const sphereBins& bins
) const
{
    scalar smallest = GREAT;
    bins.forAllPairs
    (
        [&](const label i, const label j)
        {
            smallest = Foam::min
            (
                smallest,
                mag(box_.separation(centres_[i], centres_[j]))
            );
        }
    );
    return smallest;
}


Foam::scalar Foam::randomSpherePacking::smallestDistance() const
{
    for (scalar width = diameter_; ; width *= 2)
    {
        sphereBins bins(box_, width, centres_.size());
        bins.fill(centres_);
        const scalar smallest = closestPairDistance(bins);

        // Exact once below the bin width, or with all pairs visited
        if (smallest < bins.minWidth() || width >= cmptMax(box_.length()))
        {
            return smallest;
        }
    }
}


void Foam::randomSpherePacking::check()
{
    smallestDistance_ = smallestDistance();
    if (smallestDistance_ < diameter_)
    {
        FatalErrorInFunction
            << "Packing check failed: two centres " << smallestDistance_
            << " apart, closer than a diameter " << diameter_
            << exit(FatalError);
    }
    for (const point& p : centres_)
    {
        if (!box_.holds(p, radius_))
        {
            FatalErrorInFunction
                << "Packing check failed: centre " << p << " outside the box"
                << " or closer than a radius to a wall" << exit(FatalError);
        }
    }
}


Foam::word Foam::randomSpherePacking::smallestGap() const
{
    return
        nSpheres_ > 1
      ? Foam::name(smallestDistance_/diameter_ - 1)
      : word("none");
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::randomSpherePacking::randomSpherePacking(const dictionary& dict)
:
    radius_(readRadius(dict)),
    diameter_(2*radius_),
    box_(dict, radius_),
    nSpheres_(readNSpheres(dict, box_.volume(), sphereVolume())),
    solidFraction_(nSpheres_*sphereVolume()/box_.volume()),
    seed_(dict.getOrDefault<label>("seed", 1)),
    maxIterations_(readMaxIterations(dict)),
    centres_(),
    nIterations_(0),
    nSweeps_(0),
    smallestDistance_(GREAT)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::randomSpherePacking::pack()
{
    Info<< "Packing " << nSpheres_ << " spheres of radius " << radius_
        << " at solid fraction " << solidFraction_ << ", seed " << seed_ << nl
        << endl;

    Random rng(seed_);
    placeRandomly(rng);

    // Random centres relax to no overlap at the final fraction up to
    // relaxedMax; denser packings relax at compressionStart and are then
    // compressed by Monte Carlo, which (as Lubachevsky-Stillinger) reaches
    // near random close packing (0.64), where relaxing random centres at the
    // final fraction jams near 0.62
    const scalar relaxDiameter =
        solidFraction_ <= relaxedMax
      ? diameter_
      : diameter_*Foam::cbrt(compressionStart/solidFraction_);
    nIterations_ = removeOverlaps(relaxDiameter);
    if (nIterations_ < 0)
    {
        FatalErrorInFunction
            << "Could not reach solid fraction " << solidFraction_ << " ("
            << nSpheres_ << " spheres): the overlaps of random centres at "
            << solidFraction_*pow3(relaxDiameter/diameter_) << " remain after"
            << " maxIterations " << maxIterations_ << " iterations" << nl
            << "    Lower solidFraction (or nParticles), or raise"
            << " maxIterations."
            << exit(FatalError);
    }
    nSweeps_ = 0;
    if (relaxDiameter < diameter_)
    {
        scalar reached;
        nSweeps_ = compress(relaxDiameter, rng, reached);
        if (nSweeps_ < 0)
        {
            FatalErrorInFunction
                << "Could not reach solid fraction " << solidFraction_ << " ("
                << nSpheres_ << " spheres) in maxIterations " << maxIterations_
                << " compression sweeps: reached "
                << solidFraction_*pow3(reached/diameter_) << nl
                << "    Lower solidFraction (or nParticles): random packings"
                << " of equal spheres jam near 0.64, less with walls; or"
                << " raise maxIterations."
                << exit(FatalError);
        }
    }

    check();

    Info<< "Removed the overlaps in " << nIterations_ << " iterations,"
        << " compressed in " << nSweeps_ << " sweeps;"
        << " smallest gap / diameter " << smallestGap() << nl << endl;
}


void Foam::randomSpherePacking::write(Ostream& os, const word& writer) const
{
    const auto yesNo = [](const bool b) { return b ? "yes" : "no"; };
    os  << "# " << writer << ": random packing of equal spheres, lines"
        << " \"x y z radius\"" << nl
        << "# box " << box_.lowerCorner() << ' ' << box_.upperCorner() << nl
        << "# periodic (" << yesNo(box_.periodic(0)) << ' '
        << yesNo(box_.periodic(1)) << ' ' << yesNo(box_.periodic(2)) << ')'
        << nl
        << "# radius " << radius_ << nl
        << "# nParticles " << nSpheres_ << nl
        << "# solidFraction " << solidFraction_ << nl
        << "# seed " << seed_ << nl
        << "# smallest gap / diameter " << smallestGap() << nl;

    // Full precision: the file is the packing, not a report of it
    os.precision(17);
    for (const point& p : centres_)
    {
        os  << p.x() << ' ' << p.y() << ' ' << p.z() << ' ' << radius_ << nl;
    }
}


// ************************************************************************* //
