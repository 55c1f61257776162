/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "randomShapeInsertion.H"
#include "dlmParticle.H"
#include "mathematicalConstants.H"
#include "SortableList.H"

// * * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

const Foam::wordList Foam::randomShapeInsertion::keywords
({
    "box", "periodic", "gap", "seed", "maxAttempts", "particles"
});

const Foam::wordList Foam::randomShapeInsertion::groupKeywords
({
    "number", "orientation"
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::randomShapeInsertion::readGroups()
{
    const dictionary& groups = dict_.subDict("particles");
    const label nGroups = groups.size();
    groupNames_.setSize(nGroups);
    groupEntries_.setSize(nGroups);
    shapes_.setSize(nGroups);
    numbers_.setSize(nGroups);
    randomOrientation_.setSize(nGroups);
    fixedOrientation_.setSize(nGroups, quaternion::I);

    if (nGroups == 0)
    {
        FatalIOErrorInFunction(groups)
            << "'particles' holds no group: give at least one, as"
            << " name { number N; shape ...; ... }" << exit(FatalIOError);
    }

    scalar largest = 0;
    label g = 0;
    for (const entry& e : groups)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(groups)
                << "Entry '" << e.keyword() << "' of 'particles' is not a"
                << " group dictionary" << exit(FatalIOError);
        }
        const dictionary& group = e.dict();
        if (group.found("position"))
        {
            FatalIOErrorInFunction(group)
                << "Group " << e.keyword() << " gives a position: the"
                << " packing places the particles" << exit(FatalIOError);
        }
        const label number = group.get<label>("number");
        if (number < 1)
        {
            FatalIOErrorInFunction(group)
                << "number " << number << " of group " << e.keyword()
                << " must be at least 1" << exit(FatalIOError);
        }

        randomOrientation_[g] = true;
        if (group.found("orientation"))
        {
            if (group.lookup("orientation")[0].isWord())
            {
                const word orientation(group.get<word>("orientation"));
                if (orientation != "random")
                {
                    FatalIOErrorInFunction(group)
                        << "orientation " << orientation << " of group "
                        << e.keyword() << ": give 'random' or a quaternion"
                        << " (w (x y z))" << exit(FatalIOError);
                }
            }
            else
            {
                randomOrientation_[g] = false;
                fixedOrientation_[g] = group.get<quaternion>("orientation");
            }
        }

        // The group's own keywords read, the rest are a particle's
        dictionary entries(group);
        for (const word& key : groupKeywords)
        {
            entries.remove(key);
        }

        // Checked as a particle: unknown keywords and bad values are
        // named as the solvers name them
        dictionary probe(entries);
        probe.name() = group.name();
        probe.set("position", point::zero);
        probe.set("orientation", fixedOrientation_[g]);
        const dlmParticle particle(probe);
        fixedOrientation_[g] = particle.orientation();
        if (particle.shape().nDimensions() != 3)
        {
            FatalIOErrorInFunction(group)
                << "Group " << e.keyword() << " has the 2D shape "
                << group.get<word>("shape") << ": the packing places"
                << " bodies (3D shapes)" << exit(FatalIOError);
        }

        groupNames_[g] = e.keyword();
        groupEntries_[g] = entries;
        shapes_.set(g, particle.shape().clone());
        numbers_[g] = number;
        largest = max(largest, particle.shape().boundingRadius());
        ++g;
    }
    return largest;
}


Foam::quaternion Foam::randomShapeInsertion::randomOrientation(Random& rng)
{
    const scalar u1 = rng.sample01<scalar>();
    const scalar angle1 = constant::mathematical::twoPi*rng.sample01<scalar>();
    const scalar angle2 = constant::mathematical::twoPi*rng.sample01<scalar>();
    const scalar a = Foam::sqrt(1 - u1);
    const scalar b = Foam::sqrt(u1);
    return quaternion
    (
        a*Foam::sin(angle1),
        vector(a*Foam::cos(angle1), b*Foam::sin(angle2), b*Foam::cos(angle2))
    );
}


bool Foam::randomShapeInsertion::randomPosition
(
    const particleShape& shape,
    const tensor& R,
    Random& rng,
    point& X
) const
{
    bool fits = true;
    for (direction i = 0; i < vector::nComponents; ++i)
    {
        // Drawn in every direction, fitting or not: the sequence of
        // random numbers does not depend on the shapes' extents
        const scalar u = rng.sample01<scalar>();
        if (box_.periodic(i))
        {
            X[i] = box_.lowerCorner()[i] + u*box_.length()[i];
        }
        else
        {
            vector e(Zero);
            e[i] = 1;
            const scalar lowest =
                box_.lowerCorner()[i] + shape.support(-(R.T() & e)) + gap_;
            const scalar highest =
                box_.upperCorner()[i] - shape.support(R.T() & e) - gap_;
            fits = fits && lowest <= highest;
            X[i] = lowest + u*(highest - lowest);
        }
    }
    return fits;
}


bool Foam::randomShapeInsertion::free
(
    const particleShape& shape,
    const point& X,
    const tensor& R
) const
{
    forAll(positions_, j)
    {
        const particleShape& other = shapes_[group_[j]];
        const vector d(box_.separation(X, positions_[j]));
        const scalar reach =
            shape.boundingRadius() + other.boundingRadius() + gap_;
        if (magSqr(d) >= sqr(reach))
        {
            continue;
        }
        if (shape.round() && other.round())
        {
            return false;
        }
        if
        (
           !search_.separated
            (
                other, point::zero, orientations_[j].R(), shape, d, R, gap_
            )
        )
        {
            return false;
        }
    }
    return true;
}


Foam::scalar Foam::randomShapeInsertion::solidFraction() const
{
    scalar volume = 0;
    forAll(positions_, i)
    {
        volume += shape(i).volume();
    }
    return volume/box_.volume();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::randomShapeInsertion::randomShapeInsertion(const dictionary& dict)
:
    dict_(dict),
    box_(dict, readGroups() + 0.5*dict.getOrDefault<scalar>("gap", 0)),
    gap_(dict.getOrDefault<scalar>("gap", 0)),
    seed_(dict.getOrDefault<label>("seed", 1)),
    maxAttempts_(dict.getOrDefault<label>("maxAttempts", 10000)),
    search_()
{
    if (gap_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "gap " << gap_ << " must not be negative"
            << exit(FatalIOError);
    }
    if (maxAttempts_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "maxAttempts " << maxAttempts_ << " must be at least 1"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::randomShapeInsertion::nParticles() const
{
    return sum(numbers_);
}


Foam::word Foam::randomShapeInsertion::name(const label i) const
{
    return groupNames_[group_[i]] + "_" + Foam::name(index_[i]);
}


void Foam::randomShapeInsertion::pack()
{
    // The largest first: small particles fill the gaps the large leave,
    // not the other way round. Groups keep their order at equal sizes.
    const label n = nParticles();
    labelList groupOf(n);
    labelList indexOf(n);
    SortableList<scalar> size(n);
    label k = 0;
    forAll(numbers_, g)
    {
        for (label i = 0; i < numbers_[g]; ++i)
        {
            groupOf[k] = g;
            indexOf[k] = i;
            size[k] = -shapes_[g].boundingRadius();
            ++k;
        }
    }
    size.sort();

    group_.clear();
    index_.clear();
    positions_.clear();
    orientations_.clear();

    Random rng(seed_);
    for (const label k : size.indices())
    {
        const label g = groupOf[k];
        const particleShape& shape = shapes_[g];
        bool placed = false;
        for (label attempt = 0; attempt < maxAttempts_ && !placed; ++attempt)
        {
            const quaternion q
            (
                randomOrientation_[g]
              ? randomOrientation(rng)
              : fixedOrientation_[g]
            );
            const tensor R(q.R());
            point X;
            if (randomPosition(shape, R, rng, X) && free(shape, X, R))
            {
                group_.append(g);
                index_.append(indexOf[k]);
                positions_.append(X);
                orientations_.append(q);
                placed = true;
            }
        }
        if (!placed)
        {
            FatalIOErrorInFunction(dict_)
                << "Could place only " << positions_.size() << " of " << n
                << " particles (solid fraction " << solidFraction()
                << "): particle " << groupNames_[g] << "_" << indexOf[k]
                << " (shape " << groupEntries_[g].get<word>("shape")
                << ") found no free place in maxAttempts " << maxAttempts_
                << " random tries." << nl
                << "Random insertion jams at low solid fractions (about"
                << " 0.38 for equal spheres): enlarge the box, lower the"
                << " numbers or the gap, or raise maxAttempts; dense piles"
                << " come from settling the particles" << exit(FatalIOError);
        }
    }
    Info<< "Placed " << positions_.size() << " particles, solid fraction "
        << solidFraction() << endl;
}


void Foam::randomShapeInsertion::write(Ostream& os, const word& writer) const
{
    const auto yesNo = [](const bool b) { return b ? "yes" : "no"; };
    os  << "// " << writer << ": " << positions_.size() << " particles by"
        << " random sequential insertion, entries of 'particles'" << nl
        << "// box " << box_.lowerCorner() << ' ' << box_.upperCorner() << nl
        << "// periodic (" << yesNo(box_.periodic(0)) << ' '
        << yesNo(box_.periodic(1)) << ' ' << yesNo(box_.periodic(2)) << ')'
        << nl
        << "// gap " << gap_ << nl
        << "// seed " << seed_ << nl
        << "// solidFraction " << solidFraction() << nl << nl;

    // Full precision: the file is the packing, not a report of it (written
    // to the stream: entries set in a dictionary keep 6 digits)
    os.precision(17);
    forAll(positions_, i)
    {
        os.beginBlock(name(i));
        groupEntries_[group_[i]].writeEntries(os);
        os.writeEntry("position", positions_[i]);
        os.writeEntry("orientation", orientations_[i]);
        os.endBlock();
    }
}


// ************************************************************************* //
