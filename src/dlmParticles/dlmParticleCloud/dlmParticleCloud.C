/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "dlmParticleCloud.H"
#include "convexOverlap.H"
#include "zeroGradientFvPatchFields.H"
#include "surfaceFields.H"
#include "IFstream.H"
#include "PtrDynList.H"
#include "cpuTime.H"
#include "checkKeywords.H"
#include "OSspecific.H"
#include "emptyPolyPatch.H"
#include "cyclicPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "centreDistances.H"
#include "uniformDimensionedFields.H"
#include <sstream>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dlmParticleCloud, 0);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dlmParticleCloud::readParticles(const dictionary& particlesDict)
{
    for (const entry& e : particlesDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(particlesDict)
                << "Entry '" << e.keyword() << "' of 'particles' is not a"
                << " particle sub-dictionary" << exit(FatalIOError);
        }
        particles_.append(new dlmParticle(e.dict()));
    }
}


void Foam::dlmParticleCloud::readInput()
{
    if (properties_.found("particles"))
    {
        checkRepeatedNames();
        readParticles(properties_.subDict("particles"));
    }
    readParticleFile();
}


void Foam::dlmParticleCloud::checkRepeatedNames() const
{
    // A dictionary keeps one entry of a repeated keyword (the last merged
    // into the first): scan the file's 'particles' block for repeats
    IFstream is(properties_.filePath());
    if (!is.good())
    {
        return;
    }
    label depth = 0;
    label particlesDepth = -1;
    bool particlesNext = false;
    wordHashSet names;
    word last;
    token t;
    while (is.read(t).good())
    {
        if (t == token::BEGIN_BLOCK)
        {
            ++depth;
            if (particlesNext)
            {
                particlesDepth = depth;
            }
            else if (depth == particlesDepth + 1 && particlesDepth > 0)
            {
                if (!names.insert(last))
                {
                    FatalIOErrorInFunction(properties_)
                        << "Particle " << last << " is listed twice in"
                        << " 'particles' (line " << is.lineNumber() << "):"
                        << " each particle needs its own name"
                        << exit(FatalIOError);
                }
            }
        }
        else if (t == token::END_BLOCK)
        {
            if (depth == particlesDepth)
            {
                particlesDepth = -1;
            }
            --depth;
        }
        particlesNext = depth == 0 && t.isWord() && t.wordToken() == "particles";
        last = t.isWord() ? t.wordToken() : word::null;
    }
}


void Foam::dlmParticleCloud::readParticleFile()
{
    fileName file;
    if (!properties_.readIfPresent("particleFile", file))
    {
        return;
    }
    file.expand();
    if (!file.isAbsolute())
    {
        file = mesh_.time().globalPath()/file;
    }

    const dictionary& defaults = properties_.subDict("particleFileDefaults");

    IFstream is(file);
    if (!is.good())
    {
        FatalIOErrorInFunction(properties_)
            << "Cannot open particleFile " << file << exit(FatalIOError);
    }

    const word stem(file.nameLessExt());
    // Appending to the PtrList would reallocate it per particle (quadratic)
    PtrDynList<dlmParticle> read;
    std::string line;
    label lineNo = 0;
    label nRead = 0;
    while (is.getLine(line))
    {
        ++lineNo;
        const auto hash = line.find('#');
        if (hash != std::string::npos)
        {
            line.erase(hash);
        }
        if (line.find_first_not_of(" \t\r") == std::string::npos)
        {
            continue;
        }
        std::istringstream iss(line);
        scalar x, y, z, radius;
        std::string rest;
        if (!(iss >> x >> y >> z >> radius) || (iss >> rest))
        {
            FatalErrorInFunction
                << file << ", line " << lineNo << ": expected 'x y z radius'"
                << ", got '" << line.c_str() << "'" << exit(FatalError);
        }

        dictionary particleDict(defaults);
        particleDict.name() =
            file + ":" + Foam::name(lineNo) + "." + stem + "_"
          + Foam::name(nRead);
        particleDict.set("position", point(x, y, z));
        particleDict.set("radius", radius);
        read.append(new dlmParticle(particleDict));
        ++nRead;
    }
    const label nBefore = particles_.size();
    particles_.resize(nBefore + nRead);
    forAll(read, k)
    {
        particles_.set(nBefore + k, read.release(k));
    }

    if (nRead == 0)
    {
        FatalErrorInFunction
            << "particleFile " << file << " holds no particles (lines"
            << " 'x y z radius')" << exit(FatalError);
    }
    Info<< "Read " << nRead << " particles from " << file << endl;
}


void Foam::dlmParticleCloud::checkParticles()
{
    const fileName source(properties_.filePath());
    const boundBox& bounds = mesh_.bounds();

    wordHashSet names(2*particles_.size());
    for (const dlmParticle& p : particles_)
    {
        if (!names.insert(p.name()))
        {
            FatalErrorInFunction
                << "Particle name " << p.name() << " (" << source << ") is"
                << " used twice: each particle needs its own name"
                << exit(FatalError);
        }
    }

    forAll(particles_, i)
    {
        dlmParticle& p = particles_[i];
        const label nDims = p.shape().nDimensions();

        if (twoD())
        {
            if (nDims != 2)
            {
                FatalErrorInFunction
                    << "Particle " << p.name() << " (" << source << "): shape "
                    << p.shape().type() << " is 3D but the mesh is 2D (one"
                    << " cell thick, empty front and back). Use a 2D shape"
                    << " such as disk." << exit(FatalError);
            }
            if (mesh_.solutionD()[vector::Z] != -1)
            {
                FatalErrorInFunction
                    << "Particle " << p.name() << " (" << source << "): 2D"
                    << " shapes need the mesh's empty direction to be z"
                    << exit(FatalError);
            }
            // A 2D particle moves in the x-y plane and turns about z: any
            // other component given would be dropped without a word
            const vector& U = p.velocity();
            const vector& omega = p.angularVelocity();
            if
            (
                !restarted_
             && (U.z() != 0 || omega.x() != 0 || omega.y() != 0)
            )
            {
                FatalErrorInFunction
                    << "Particle " << p.name() << " (" << source << "):"
                    << " velocity " << U << " and angularVelocity " << omega
                    << " must lie in the 2D mesh's plane: a 2D particle moves"
                    << " in x and y and turns about z, so give (u v 0) and"
                    << " (0 0 w)" << exit(FatalError);
            }

            // A 2D shape sits in the mesh's mid-plane
            point X(p.position());
            X.z() = 0.5*(bounds.min().z() + bounds.max().z());
            p.setPosition(X);
        }
        else if (nDims != 3)
        {
            FatalErrorInFunction
                << "Particle " << p.name() << " (" << source << "): shape "
                << p.shape().type() << " is 2D but the mesh is 3D. Use a 3D"
                << " shape such as sphere." << exit(FatalError);
        }

        // Contacts of a shape that is not round, with walls and with
        // other particles, come from its parts beyond planes (planeCut)
        if
        (
            !p.shape().round()
         && properties_.found("contact")
         && properties_.subDict("contact").getOrDefault<bool>("active", true)
        )
        {
            scalar V, area;
            vector centroid;
            if (!p.shape().planeCut(vector(0, 0, 1), 0, V, centroid, area))
            {
                FatalIOErrorInFunction(properties_.subDict("contact"))
                    << "Particle " << p.name() << " has shape "
                    << p.shape().type() << ", whose contacts with walls are"
                    << " not implemented (no formula for its part beyond a"
                    << " plane). Use 'active false' in the contact settings,"
                    << " or an ellipsoid, cylinder, box or triSurface (in 2D"
                    << " an ellipse or polygon)."
                    << exit(FatalIOError);
            }
        }

        label celli = findCell(p.position());
        reduce(celli, maxOp<label>());
        if (celli < 0)
        {
            FatalErrorInFunction
                << "Particle " << p.name() << " (" << source << "): its centre "
                << p.position() << " is outside the mesh " << bounds
                << exit(FatalError);
        }
    }
}


void Foam::dlmParticleCloud::failStop() const
{
    if (touchingBoundary())
    {
        failAtBoundary();
    }
    if (reachingPeriodic())
    {
        failAtPeriodic();
    }
    if (leftMesh())
    {
        failOutsideMesh();
    }
    if (overlapping())
    {
        failOverlapping();
    }
}


Foam::labelPair Foam::dlmParticleCloud::findOverlap
(
    const scalar allowed,
    scalar& depth,
    scalar& size
) const
{
    // Sweep along x: each particle meets those whose interval starts
    // within its own
    const label n = particles_.size();
    scalarField lower(n);
    forAll(particles_, i)
    {
        lower[i] =
            particles_[i].position().x()
          - particles_[i].shape().boundingRadius();
    }
    const labelList order(sortedOrder(lower));

    for (label a = 0; a < n; ++a)
    {
        const dlmParticle& pi = particles_[order[a]];
        const scalar Ri = pi.shape().boundingRadius();
        const scalar upper = pi.position().x() + Ri;
        for (label b = a + 1; b < n && lower[order[b]] <= upper; ++b)
        {
            if (contact_.valid() && contact_->passThrough(order[a], order[b]))
            {
                continue;
            }
            const dlmParticle& pj = particles_[order[b]];
            const scalar Rj = pj.shape().boundingRadius();
            depth = Ri + Rj - mag(pi.position() - pj.position());
            // Round shapes: the depth and diameters; others: the least
            // depth (convexOverlap) and the thicknesses across it
            size = 2*min(Ri, Rj);
            if (!(pi.shape().round() && pj.shape().round()) && depth > 0)
            {
                const convexOverlap::result o = convexOverlap().overlap
                (
                    pi.shape(), pi.position(), pi.R(),
                    pj.shape(), pj.position(), pj.R()
                );
                depth = o.depth;
                const vector ni(pi.R().T() & o.normal);
                const vector nj(pj.R().T() & o.normal);
                size = min(pi.shape().thickness(ni), pj.shape().thickness(nj));
            }
            // Touching (as in a packing) is no overlap, to round-off
            if (depth > max(allowed*size, 1e-9*(Ri + Rj)))
            {
                return labelPair(order[a], order[b]);
            }
        }
    }
    return labelPair(-1, -1);
}


Foam::word Foam::dlmParticleCloud::overlapSize(const labelPair& pair) const
{
    return
        particles_[pair.first()].shape().round()
     && particles_[pair.second()].shape().round()
      ? "smaller diameter"
      : "smaller thickness across it";
}


void Foam::dlmParticleCloud::checkOverlaps() const
{
    // Without contact forces nothing would part overlapping particles;
    // with them an overlap beyond a few percent would part them violently
    const scalar allowed =
        contact_.valid() ? contact_->maxStartOverlap() : 0;
    scalar depth = 0;
    scalar smaller = 0;
    const labelPair pair(findOverlap(allowed, depth, smaller));
    if (pair.first() < 0)
    {
        return;
    }

    const word size(overlapSize(pair));
    FatalErrorInFunction
        << "Particles " << particles_[pair.first()].name() << " and "
        << particles_[pair.second()].name() << " ("
        << properties_.filePath() << ") overlap by " << depth << " ("
        << 100*depth/smaller << " % of the " << size << ") at the start: ";
    if (contact_.valid())
    {
        FatalError
            << "more than the contact laws resolve"
            << " (contact.maxStartOverlap " << allowed << " of the " << size
            << ")";
    }
    else
    {
        FatalError
            << "without contacts (a 'contact' dictionary) particles must not"
            << " overlap";
    }
    FatalError << exit(FatalError);
}


void Foam::dlmParticleCloud::checkApart()
{
    overlapping_ = labelPair(-1, -1);
    if (contact_.valid() || particles_.size() < 2 || allFixed())
    {
        return;
    }
    const cpuTime timer;
    scalar depth = 0;
    scalar size = 0;
    overlapping_ = findOverlap(0, depth, size);
    addWorkTime(workPart::motion, timer.elapsedCpuTime());
}


void Foam::dlmParticleCloud::failOverlapping() const
{
    // The pair's depth and size, found again: nothing moved since
    scalar depth = 0;
    scalar smaller = 0;
    findOverlap(0, depth, smaller);
    const dlmParticle& a = particles_[overlapping_.first()];
    const dlmParticle& b = particles_[overlapping_.second()];
    FatalErrorInFunction
        << "Particles " << a.name() << " and " << b.name() << " overlap by "
        << depth << " (" << 100*depth/smaller << " % of the "
        << overlapSize(overlapping_) << ") at t = " << mesh_.time().value()
        << " (positions " << a.position() << " and " << b.position()
        << "). Particle-particle contact is not modelled without a"
        << " 'contact' dictionary in " << properties_.filePath()
        << ": add one (see README.md, Contacts; law none lets particles"
        << " pass through each other). The state of this time has been"
        << " written" << exit(FatalError);
}


Foam::scalar Foam::dlmParticleCloud::cellsPerDiameter(const label i) const
{
    const dlmParticle& p = particles_[i];
    const label celli = findCell(p.position());
    scalar h = 0;
    if (celli >= 0)
    {
        h = GREAT;
        const vector span(cellBoxes_[celli].span());
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (splitDirections_[d] > 0)
            {
                h = min(h, span[d]);
            }
        }
    }
    reduce(h, maxOp<scalar>());
    return h > 0 ? 2*p.shape().boundingRadius()/h : 0;
}


void Foam::dlmParticleCloud::checkStart() const
{
    const fileName source(properties_.filePath());

    if (touchingBoundary())
    {
        const dlmParticle& p = particles_[touchingBoundary_];
        FatalErrorInFunction
            << "Particle " << p.name() << " (" << source << ") at "
            << p.position() << " covers cells next to a wall at the start."
            << " Without contacts a free particle must keep off the cells"
            << " next to the walls: move it, or add a 'contact' dictionary"
            << " to " << source << exit(FatalError);
    }
    if (reachingPeriodic())
    {
        const dlmParticle& p = particles_[reachingPeriodic_];
        FatalErrorInFunction
            << "Particle " << p.name() << " (" << source << ") at "
            << p.position() << " covers cells next to a cyclic patch that"
            << " is not a translation at the start. Particles have periodic"
            << " images across translational cyclic patches only: a free"
            << " particle must keep off the cells next to other cyclic"
            << " patches" << exit(FatalError);
    }

    // The projection needs a cell centre inside each particle wherever it
    // is: a diameter of two cells has one. A cell's span, a difference of
    // its points, may exceed its nominal size by round-off (a diameter of
    // exactly two cells was refused in some cells)
    const scalar minCellsPerDiameter = 2;
    const scalar roundOff = 1e-9;
    const bool wet = rhoFluid_.value() > 0;
    for (label i = 0; wet && i < nParticles(); ++i)
    {
        const scalar nCells = cellsPerDiameter(i);
        if (nCells < (1 - roundOff)*minCellsPerDiameter)
        {
            const dlmParticle& p = particles_[i];
            FatalErrorInFunction
                << "Particle " << p.name() << " (" << source << ") at "
                << p.position() << " has a diameter of " << nCells
                << " cells; the rigid projection needs at least "
                << minCellsPerDiameter << " (6 or more for accuracy, see"
                << " validation/cases/tenCate.md): refine the mesh or"
                << " enlarge the particle" << exit(FatalError);
        }
    }

    // Prescribed particles keep their velocity: find when one would reach
    // the mesh's bounds, in the directions without periodic images
    vector periodic(Zero);
    for (const vector& t : periodicImages::translations(mesh_))
    {
        periodic += cmptMag(t);
    }
    const Time& runTime = mesh_.time();
    const scalar timeLeft = runTime.endTime().value() - runTime.value();
    const boundBox& bounds = mesh_.bounds();
    for (label i = 0; i < nParticles(); ++i)
    {
        const dlmParticle& p = particles_[i];
        if (p.motion() != dlmParticle::motionType::prescribed)
        {
            continue;
        }
        const scalar R = p.shape().boundingRadius();
        scalar reach = GREAT;
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            const scalar v = p.velocity()[d];
            if (splitDirections_[d] == 0 || periodic[d] > 0 || v == 0)
            {
                continue;
            }
            const scalar distance =
                v > 0
              ? bounds.max()[d] - (p.position()[d] + R)
              : (p.position()[d] - R) - bounds.min()[d];
            reach = min(reach, max(distance, scalar(0))/mag(v));
        }
        if (reach < timeLeft)
        {
            FatalErrorInFunction
                << "Particle " << p.name() << " (" << source << ") is"
                << " prescribed to move at " << p.velocity() << " from "
                << p.position() << ": it reaches the mesh's bounds "
                << bounds << " at t = " << runTime.value() + reach
                << " (after about " << label(reach/runTime.deltaTValue())
                << " steps of " << runTime.deltaTValue() << "), before"
                << " endTime " << runTime.endTime().value() << "."
                << " Shorten endTime (system/controlDict) or change the"
                << " particle's velocity or position" << exit(FatalError);
        }
    }
}


void Foam::dlmParticleCloud::reduceTouching()
{
    for (label* first : {&touchingBoundary_, &reachingPeriodic_})
    {
        label i = *first < 0 ? labelMax : *first;
        reduce(i, minOp<label>());
        *first = i == labelMax ? -1 : i;
    }
}


void Foam::dlmParticleCloud::failAtPeriodic() const
{
    const dlmParticle& p = particles_[reachingPeriodic_];
    FatalErrorInFunction
        << "Free particle " << p.name() << " reached the cells next to a"
        << " cyclic patch that is not a translation at t = "
        << mesh_.time().value() << " (position " << p.position()
        << ", velocity " << p.velocity() << "). Particles have periodic"
        << " images across translational cyclic patches only: widen the"
        << " domain or use walls. The state of this time has been written"
        << exit(FatalError);
}


void Foam::dlmParticleCloud::failAtBoundary() const
{
    const dlmParticle& p = particles_[touchingBoundary_];
    FatalErrorInFunction
        << "Particle " << p.name() << " reached the cells next to a wall at"
        << " t = " << mesh_.time().value() << " (position " << p.position()
        << ", velocity " << p.velocity() << "). Particle-wall contact is"
        << " not modelled without a 'contact' dictionary in "
        << properties_.filePath() << ": add one (see README.md,"
        << " Contacts). The state of this time has been written"
        << exit(FatalError);
}


void Foam::dlmParticleCloud::checkInMesh()
{
    const cpuTime timer;
    // Images outside the mesh are no error: their particles are checked
    boolList inMesh(particles_.size(), true);
    for (label i = 0; i < nParticles(); ++i)
    {
        if (particles_[i].isFree())
        {
            inMesh[i] = findCell(particles_[i].position()) >= 0;
        }
    }
    Pstream::listCombineGather(inMesh, orEqOp<bool>());
    Pstream::listCombineScatter(inMesh);
    leftMesh_ = inMesh.find(false);
    addWorkTime(workPart::motion, timer.elapsedCpuTime());
}


void Foam::dlmParticleCloud::failOutsideMesh() const
{
    const dlmParticle& p = particles_[leftMesh_];
    FatalErrorInFunction
        << "Particle " << p.name() << " left the mesh, which bounds the"
        << " scene, at t = " << mesh_.time().value() << " (position "
        << p.position() << ", velocity " << p.velocity() << "). A particle"
        << " leaves the mesh when an overlap throws it out, at an absurd"
        << " velocity, or where no wall holds it (meshWalls false): check"
        << " the particles' overlaps, velocities and walls and gravity"
        << " (constant/g); to let particles leave, give an outlet ('outlets'"
        << " in " << properties_.filePath() << ", see README.md). The state"
        << " of this time has been written" << exit(FatalError);
}


Foam::label Foam::dlmParticleCloud::findCell(const point& x) const
{
    DynamicList<label> candidates;
    cellBins_->findBox(boundBox(x, x), candidates);
    // A box cell holds the points of its closed box: a point on a face or
    // corner shared by box cells is in one of them, where the tet test
    // could reject it in all of them by round-off
    for (const label celli : candidates)
    {
        if
        (
            cellIsBox_[celli]
          ? cellBoxes_[celli].contains(x)
          : mesh_.pointInCell(x, celli, polyMesh::CELL_TETS)
        )
        {
            return celli;
        }
    }
    return -1;
}


void Foam::dlmParticleCloud::readOutlets(const dictionary& state)
{
    const dictionary* dictPtr = properties_.findDict("outlets");
    if (!dictPtr)
    {
        return;
    }
    const dictionary* statePtr = state.findDict("outlets");
    for (const entry& e : *dictPtr)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(*dictPtr)
                << "outlets: entry '" << e.keyword() << "' is not an outlet"
                << " dictionary" << exit(FatalIOError);
        }
        outlets_.append(particleOutlet::New(e.dict()));
        if (statePtr)
        {
            outlets_.last().readState(*statePtr);
        }
    }
}


void Foam::dlmParticleCloud::checkInputAgainstState
(
    const PtrList<dlmParticle>& input,
    const fileName& statePath
) const
{
    // The particles, not their periodic images
    HashTable<label> stateIndex(2*nParticles());
    for (label i = 0; i < nParticles(); ++i)
    {
        stateIndex.insert(particles_[i].name(), i);
    }
    wordHashSet removed;
    label nRemoved = 0;
    for (const particleOutlet& outlet : outlets_)
    {
        removed.insert(outlet.removedNames());
        nRemoved += outlet.nRemoved();
    }
    // States written before the outlets recorded names cannot tell a
    // removed particle from one added to the input
    const bool removedKnown = removed.size() == nRemoved;

    const word startTime(mesh_.time().timeName());
    const fileName inputName(properties_.instance()/properties_.name());
    const auto fail = [&](const word& name, const string& what)
    {
        FatalIOErrorInFunction(properties_)
            << "Particle " << name << " " << what.c_str() << nl
            << "A run from time " << startTime << " continues the particles"
            << " written with that time (" << statePath << "), which"
            << " replace those of " << inputName.c_str() << "; the two must"
            << " list the same particles with the same properties." << nl
            << "To change the particles, start from time 0, or edit both"
            << " files alike." << exit(FatalIOError);
    };

    // An entry on one line, at 15 digits: the decimals as given
    const auto oneLine = [](const entry& e)
    {
        OStringStream os;
        os.precision(15);
        os << e;
        string line(os.str());
        line.replaceAll("\n", " ");
        line.removeRepeated(' ');
        line.removeTrailing(' ');
        return line;
    };

    const auto properties = [](const dlmParticle& p)
    {
        OStringStream os;
        os.precision(17);
        p.writeProperties(os);
        if (p.motion() == dlmParticle::motionType::prescribed)
        {
            os.writeEntry("velocity", p.velocity());
            os.writeEntry("angularVelocity", p.angularVelocity());
        }
        return dictionary(IStringStream(os.str())());
    };

    wordHashSet inInput(2*input.size());
    for (const dlmParticle& p : input)
    {
        inInput.insert(p.name());
        const auto iter = stateIndex.cfind(p.name());
        if (!iter.found())
        {
            if (removedKnown && !removed.found(p.name()))
            {
                fail
                (
                    p.name(),
                    "is in " + inputName + " but not among the particles"
                    " of time " + startTime
                  + (
                        outlets_.size()
                      ? " (nor among those the outlets removed)."
                      : "."
                    )
                );
            }
            continue;
        }

        const dictionary given(properties(p));
        const dictionary continued(properties(particles_[iter.val()]));
        for (const entry& e : continued)
        {
            const entry* g = given.findEntry(e.keyword(), keyType::LITERAL);
            if (!g || *g != e)
            {
                fail
                (
                    p.name(),
                    "has other properties in " + inputName + " than at"
                    " time " + startTime + ": "
                  + (g ? oneLine(*g) : "no " + e.keyword())
                  + " there, " + oneLine(e) + " at time " + startTime + "."
                );
            }
        }
        for (const entry& g : given)
        {
            if (!continued.found(g.keyword(), keyType::LITERAL))
            {
                fail
                (
                    p.name(),
                    "has " + g.keyword() + " in " + inputName + ", which"
                    " its state at time " + startTime + " has not."
                );
            }
        }
    }

    for (label i = 0; i < nParticles(); ++i)
    {
        const word& name = particles_[i].name();
        if (!inInput.found(name))
        {
            fail
            (
                name,
                "is among the particles of time " + startTime
              + " but not in " + inputName + "."
            );
        }
    }
}


void Foam::dlmParticleCloud::checkOutlets() const
{
    for (label i = 0; i < nParticles(); ++i)
    {
        const dlmParticle& p = particles_[i];
        for (const particleOutlet& outlet : outlets_)
        {
            if (p.isFree() && outlet.holds(p.position()))
            {
                FatalIOErrorInFunction(properties_)
                    << "Particle " << p.name() << " at " << p.position()
                    << " starts in outlet " << outlet.name() << " of"
                    << " 'outlets': it would leave at the first step (is"
                    << " the outlet on the side of the domain, its normal"
                    << " pointing out?)" << exit(FatalIOError);
            }
        }
    }
}


Foam::autoPtr<Foam::OFstream> Foam::dlmParticleCloud::newRecord
(
    const word& name,
    const word& file
) const
{
    const fileName dir
    (
        mesh_.time().globalPath()/"postProcessing"/name/startTimeName_
    );
    mkDir(dir);
    autoPtr<OFstream> os(new OFstream(dir/file));
    os().precision(15);
    return os;
}


void Foam::dlmParticleCloud::recordRemoval
(
    const particleOutlet& outlet,
    const dlmParticle& p,
    const scalar mass
)
{
    if (!Pstream::master())
    {
        return;
    }
    if (!outletFile_.valid())
    {
        outletFile_ = newRecord("particleOutlets", "outlets.dat");
        outletFile_()
            << "# time outlet particle mass x y z Ux Uy Uz"
            << " outletParticles outletMass" << nl
            << "# mass: of the particle" << (twoD() ? " per unit depth" : "")
            << "; outletParticles, outletMass: the outlet's totals" << nl;
    }
    OFstream& os = outletFile_();
    os  << mesh_.time().value() << ' ' << outlet.name().c_str() << ' '
        << p.name().c_str() << ' ' << mass;
    for (const vector& v : {p.position(), p.velocity()})
    {
        os  << ' ' << v.x() << ' ' << v.y() << ' ' << v.z();
    }
    os  << ' ' << outlet.nRemoved() << ' ' << outlet.massRemoved() << endl;
}


void Foam::dlmParticleCloud::removeParticles(const labelList& oldToNew)
{
    label nKept = 0;
    forAll(oldToNew, i)
    {
        const label k = oldToNew[i];
        if (k < 0)
        {
            continue;
        }
        ++nKept;
        if (k != i)
        {
            particles_.set(k, particles_.set(i, nullptr));
            cells_[k].transfer(cells_[i]);
            fractions_[k].transfer(fractions_[i]);
            nearCells_[k].transfer(nearCells_[i]);
            if (i < speedChange_.size())
            {
                speedChange_[k] = speedChange_[i];
            }
            if (i < nearSpeed_.size())
            {
                nearSpeed_[k] = nearSpeed_[i];
            }
        }
    }
    particles_.resize(nKept);
    cells_.resize(nKept);
    fractions_.resize(nKept);
    nearCells_.resize(nKept);
    speedChange_.resize(min(speedChange_.size(), nKept));
    nearSpeed_.resize(min(nearSpeed_.size(), nKept));
    images_.renumber(oldToNew);

    if (contact_.valid())
    {
        contact_->removeParticles(oldToNew);
    }
}


bool Foam::dlmParticleCloud::removeLeaving()
{
    if (outlets_.empty())
    {
        return false;
    }
    const cpuTime timer;

    labelList oldToNew(identity(particles_.size()));
    label nLeft = 0;
    for (label i = 0; i < nParticles(); ++i)
    {
        const dlmParticle& p = particles_[i];
        if (!p.isFree())
        {
            continue;
        }
        for (particleOutlet& outlet : outlets_)
        {
            if (outlet.holds(p.position()))
            {
                const scalar mass = p.density()*p.shape().volume();
                outlet.count(p.name(), mass);
                recordRemoval(outlet, p, mass);
                Info<< "Particle " << p.name() << " leaves through outlet "
                    << outlet.name() << " (" << outlet.nRemoved()
                    << " particles, " << outlet.massRemoved() << " kg"
                    << (twoD() ? "/m" : "") << " so far)" << endl;
                oldToNew[i] = -1;
                ++nLeft;
                break;
            }
        }
    }
    if (nLeft == 0)
    {
        addWorkTime(workPart::motion, timer.elapsedCpuTime());
        return false;
    }
    images_.removeWithSources(oldToNew);

    label k = 0;
    for (label& index : oldToNew)
    {
        if (index >= 0)
        {
            index = k++;
        }
    }
    removeParticles(oldToNew);
    if (resolved_)
    {
        updateFields();
    }

    addWorkTime(workPart::motion, timer.elapsedCpuTime());
    return true;
}


void Foam::dlmParticleCloud::updateCellGeometry()
{
    cellSizes_ = gMinMax(centreDistances(mesh_)());

    // The cell searches use the tet decomposition, which every processor
    // must build together (its first use is collective): a search that
    // finds nothing on one processor would otherwise leave the others
    // waiting
    mesh_.tetBasePtIs();

    const pointField& points = mesh_.points();
    const labelListList& cellPoints = mesh_.cellPoints();
    const scalarField& V = mesh_.V();
    cellBoxes_.setSize(mesh_.nCells());
    cellIsBox_.setSize(mesh_.nCells());
    forAll(cellBoxes_, celli)
    {
        cellBoxes_[celli] = boundBox(points, cellPoints[celli], false);
        cellIsBox_[celli] =
            mag(cellBoxes_[celli].volume() - V[celli]) < 1e-6*V[celli];
    }
    cellBins_.reset(new cellBins(cellBoxes_));

    boundaryCell_.setSize(mesh_.nCells());
    boundaryCell_ = false;
    periodicCell_.setSize(mesh_.nCells());
    periodicCell_ = false;
    const bool translational = images_.periodic();
    for (const polyPatch& patch : mesh_.boundaryMesh())
    {
        if (!patch.coupled() && !isA<emptyPolyPatch>(patch))
        {
            for (const label celli : patch.faceCells())
            {
                boundaryCell_[celli] = true;
            }
        }
        if
        (
            !translational
         && (isA<cyclicPolyPatch>(patch) || isA<processorCyclicPolyPatch>(patch))
        )
        {
            for (const label celli : patch.faceCells())
            {
                periodicCell_[celli] = true;
            }
        }
    }
}


void Foam::dlmParticleCloud::updateFractions(const label i)
{
    const dlmParticle& p = particles_[i];
    const particleShape& shape = p.shape();
    const point& X = p.position();
    const scalar Rb = shape.boundingRadius();

    const scalar reach = Rb + 1.01*cellSizes_.max();
    point lo(X - reach*vector::one);
    point hi(X + reach*vector::one);
    if (twoD())
    {
        const boundBox& bounds = mesh_.bounds();
        lo.z() = bounds.min().z();
        hi.z() = bounds.max().z();
    }

    nearCells_[i].clear();
    cellBins_->findBox(boundBox(lo, hi), nearCells_[i]);

    const tensor R(p.R());
    const scalar leafSize = Rb/surfaceResolution_;

    DynamicList<label>& cells = cells_[i];
    DynamicList<scalar>& fractions = fractions_[i];
    cells.clear();
    fractions.clear();

    for (const label celli : nearCells_[i])
    {
        const scalar f = shape.boxFraction
        (
            cellBoxes_[celli],
            X,
            R,
            splitDirections_,
            leafSize
        );

        if (f > 0)
        {
            if
            (
                boundaryCell_[celli] && p.isFree() && !contact_.valid()
             && (touchingBoundary_ < 0 || i < touchingBoundary_)
            )
            {
                touchingBoundary_ = i;
            }
            if
            (
                periodicCell_[celli] && p.isFree()
             && (reachingPeriodic_ < 0 || i < reachingPeriodic_)
            )
            {
                reachingPeriodic_ = i;
            }
            if (f < 1 && !cellIsBox_[celli])
            {
                FatalErrorInFunction
                    << "Particle " << p.name() << " cuts cell " << celli
                    << " at " << mesh_.C()[celli] << ", which is not an"
                    << " axis-aligned box. The solid fraction needs box cells"
                    << " (blockMesh, hexahedral refinement) where particles go"
                    << exit(FatalError);
            }
            cells.append(celli);
            fractions.append(f);
        }
    }
}


void Foam::dlmParticleCloud::updateFields()
{
    scalarField& alpha = alpha_.primitiveFieldRef();
    scalarField& rho = rho_.primitiveFieldRef();
    alpha = 0;
    rho = rhoFluid_.value();

    forAll(particles_, i)
    {
        const scalar deltaRho =
            particles_[i].mixtureDensity(rhoFluid_.value()) - rhoFluid_.value();
        const DynamicList<label>& cells = cells_[i];
        const DynamicList<scalar>& fractions = fractions_[i];

        forAll(cells, k)
        {
            alpha[cells[k]] += fractions[k];
            rho[cells[k]] += deltaRho*fractions[k];
        }
    }

    alpha_.correctBoundaryConditions();
    rho_.correctBoundaryConditions();
}


void Foam::dlmParticleCloud::writeVTKPoints(const fileName& dir) const
{
    const word timeName(mesh_.time().timeName());
    {
        OFstream os(dir/"particles_" + timeName + ".vtk");
        os.precision(10);
        const label n = nParticles();

        os  << "# vtk DataFile Version 3.0" << nl
            << "pimpleDLMFoam particles, time " << timeName << nl
            << "ASCII" << nl
            << "DATASET POLYDATA" << nl
            << "POINTS " << n << " double" << nl;
        for (label i = 0; i < n; ++i)
        {
            const dlmParticle& p = particles_[i];
            const point& X = p.position();
            os  << X.x() << ' ' << X.y() << ' ' << X.z() << nl;
        }
        os  << "VERTICES " << n << ' ' << 2*n << nl;
        for (label i = 0; i < n; ++i)
        {
            os  << "1 " << i << nl;
        }

        os  << "POINT_DATA " << n << nl
            << "SCALARS id int 1" << nl
            << "LOOKUP_TABLE default" << nl;
        for (label i = 0; i < n; ++i)
        {
            os  << i << nl;
        }
        os  << "SCALARS diameter double 1" << nl
            << "LOOKUP_TABLE default" << nl;
        for (label i = 0; i < n; ++i)
        {
            const dlmParticle& p = particles_[i];
            os  << 2*p.shape().boundingRadius() << nl;
        }
        os  << "SCALARS density double 1" << nl
            << "LOOKUP_TABLE default" << nl;
        for (label i = 0; i < n; ++i)
        {
            const dlmParticle& p = particles_[i];
            os  << p.density() << nl;
        }

        auto writeVectors = [&](const char* name, vector (*get)(const dlmParticle&))
        {
            os  << "VECTORS " << name << " double" << nl;
            for (label i = 0; i < n; ++i)
            {
                const dlmParticle& p = particles_[i];
                const vector v(get(p));
                os  << v.x() << ' ' << v.y() << ' ' << v.z() << nl;
            }
        };
        writeVectors("velocity", [](const dlmParticle& p) { return p.velocity(); });
        writeVectors
        (
            "angularVelocity",
            [](const dlmParticle& p) { return p.angularVelocity(); }
        );
        writeVectors("force", [](const dlmParticle& p) { return p.force(); });
        writeVectors("torque", [](const dlmParticle& p) { return p.torque(); });

        os  << "SCALARS orientation double 4" << nl
            << "LOOKUP_TABLE default" << nl;
        for (label i = 0; i < n; ++i)
        {
            const quaternion& q = particles_[i].orientation();
            os  << q.w() << ' ' << q.v().x() << ' ' << q.v().y() << ' '
                << q.v().z() << nl;
        }
    }
}


void Foam::dlmParticleCloud::writeVTKSeries
(
    const fileName& dir,
    const word& prefix,
    const word& seriesName
)
{
    // Every <prefix><time>.vtk present
    const fileNameList files(readDir(dir, fileName::FILE));
    List<Tuple2<scalar, word>> series;
    for (const fileName& f : files)
    {
        const word name(f.name());
        if (name.startsWith(prefix) && f.hasExt("vtk"))
        {
            const word t
            (
                name.substr(prefix.size(), name.size() - prefix.size() - 4)
            );
            scalar value;
            if (readScalar(t, value))
            {
                series.append(Tuple2<scalar, word>(value, name));
            }
        }
    }
    Foam::sort(series);

    OFstream os(dir/seriesName);
    os.precision(10);
    os  << "{" << nl
        << "  \"file-series-version\" : \"1.0\"," << nl
        << "  \"files\" : [" << nl;
    forAll(series, i)
    {
        os  << "    { \"name\" : \"" << series[i].second().c_str()
            << "\", \"time\" : " << series[i].first() << " }"
            << (i + 1 < series.size() ? "," : "") << nl;
    }
    os  << "  ]" << nl
        << "}" << nl;
}


void Foam::dlmParticleCloud::writeVTKSurfaces(const fileName& dir) const
{
    const word timeName(mesh_.time().timeName());
    OFstream os(dir/"surfaces_" + timeName + ".vtk");
    os.precision(10);

    // Each particle's drawing, placed and turned
    List<pointField> points(nParticles());
    List<faceList> faces(nParticles());
    label nPoints = 0;
    label nFaces = 0;
    label nEntries = 0;
    for (label i = 0; i < nParticles(); ++i)
    {
        const dlmParticle& p = particles_[i];
        p.shape().drawing(points[i], faces[i]);
        points[i] = p.position() + (p.R() & points[i]);
        nPoints += points[i].size();
        nFaces += faces[i].size();
        for (const face& f : faces[i])
        {
            nEntries += f.size() + 1;
        }
    }

    os  << "# vtk DataFile Version 3.0" << nl
        << "pimpleDLMFoam particle surfaces, time " << timeName << nl
        << "ASCII" << nl
        << "DATASET POLYDATA" << nl
        << "POINTS " << nPoints << " double" << nl;
    for (const pointField& pts : points)
    {
        for (const point& x : pts)
        {
            os  << x.x() << ' ' << x.y() << ' ' << x.z() << nl;
        }
    }
    os  << "POLYGONS " << nFaces << ' ' << nEntries << nl;
    label offset = 0;
    forAll(faces, i)
    {
        for (const face& f : faces[i])
        {
            os  << f.size();
            for (const label pointi : f)
            {
                os  << ' ' << offset + pointi;
            }
            os  << nl;
        }
        offset += points[i].size();
    }

    // Per face: the particle's id, density and the velocity of the rigid
    // motion at the face's centre
    os  << "CELL_DATA " << nFaces << nl
        << "SCALARS id int 1" << nl
        << "LOOKUP_TABLE default" << nl;
    forAll(faces, i)
    {
        for (label k = 0; k < faces[i].size(); ++k)
        {
            os  << i << nl;
        }
    }
    os  << "SCALARS density double 1" << nl
        << "LOOKUP_TABLE default" << nl;
    forAll(faces, i)
    {
        for (label k = 0; k < faces[i].size(); ++k)
        {
            os  << particles_[i].density() << nl;
        }
    }
    os  << "VECTORS velocity double" << nl;
    forAll(faces, i)
    {
        const dlmParticle& p = particles_[i];
        for (const face& f : faces[i])
        {
            const vector v
            (
                p.velocity()
              + (p.angularVelocity() ^ (f.centre(points[i]) - p.position()))
            );
            os  << v.x() << ' ' << v.y() << ' ' << v.z() << nl;
        }
    }
}


void Foam::dlmParticleCloud::writeVTK() const
{
    if (!Pstream::master())
    {
        return;
    }

    const fileName dir(mesh_.time().globalPath()/"VTK"/"particles");
    mkDir(dir);

    writeVTKPoints(dir);
    writeVTKSeries(dir, "particles_", "particles.vtk.series");

    bool allRound = true;
    for (label i = 0; i < nParticles(); ++i)
    {
        allRound = allRound && particles_[i].shape().round();
    }
    if (!allRound)
    {
        writeVTKSurfaces(dir);
        writeVTKSeries(dir, "surfaces_", "surfaces.vtk.series");
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dlmParticleCloud::dlmParticleCloud
(
    const fvMesh& mesh,
    const dimensionedScalar& rhoFluid,
    const bool dry
)
:
    regIOobject
    (
        IOobject
        (
            "particles",
            mesh.time().timeName(),
            "uniform",
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        )
    ),
    mesh_(mesh),
    properties_
    (
        IOobject
        (
            "particleProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    rhoFluid_(rhoFluid),
    surfaceResolution_
    (
        properties_.getOrDefault<scalar>("surfaceResolution", 32)
    ),
    historyInterval_(properties_.getOrDefault<label>("historyInterval", 1)),
    images_(mesh),
    touchingBoundary_(-1),
    reachingPeriodic_(-1),
    leftMesh_(-1),
    overlapping_(-1, -1),
    nMoves_(0),
    resolved_(!dry),
    splitDirections_(Zero),
    alpha_
    (
        IOobject
        (
            "alpha.solid",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar(dimless, Zero),
        zeroGradientFvPatchScalarField::typeName
    ),
    rho_
    (
        IOobject
        (
            "rho",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        rhoFluid,
        zeroGradientFvPatchScalarField::typeName
    ),
    projected_(false),
    contactPredicted_(false),
    workTimes_(Zero),
    startTimeName_(mesh.time().timeName()),
    restarted_(false)
{
    const wordHashSet known
    ({
        "surfaceResolution", "particles", "particleFile",
        "particleFileDefaults", "contact", "historyInterval", "outlets",
        "FoamFile"
    });
    checkKeywords(properties_, known);
    if (historyInterval_ < 0)
    {
        FatalIOErrorInFunction(properties_)
            << "historyInterval " << historyInterval_ << " must not be"
            << " negative" << exit(FatalIOError);
    }
    if (surfaceResolution_ < 1)
    {
        FatalIOErrorInFunction(properties_)
            << "surfaceResolution " << surfaceResolution_
            << " must be at least 1" << exit(FatalIOError);
    }

    // On restart the state written with the start time replaces the input,
    // which is kept to be checked against it
    const fileName statePath(objectPath());
    dictionary state;
    PtrList<dlmParticle> input;
    readInput();
    if (isFile(statePath))
    {
        Info<< "Reading particle state from " << statePath << endl;
        restarted_ = true;
        IFstream is(statePath);
        state.read(is);
        input.transfer(particles_);
        readParticles(state.subDict("particles"));
    }

    updateCellGeometry();

    for (direction d = 0; d < vector::nComponents; ++d)
    {
        splitDirections_[d] = mesh.solutionD()[d] == 1 ? 1 : 0;
    }

    checkParticles();

    // The particles and the flow of a 2D case move in the x-y plane:
    // gravity along z would be dropped without a word
    if (twoD() && mesh.time().foundObject<uniformDimensionedVectorField>("g"))
    {
        const uniformDimensionedVectorField& g =
            mesh.time().lookupObject<uniformDimensionedVectorField>("g");
        if (g.value().z() != 0)
        {
            FatalErrorInFunction
                << g.objectPath() << ": value " << g.value() << " has a"
                << " component along z, the 2D mesh's empty direction, where"
                << " nothing moves: give (gx gy 0)" << exit(FatalError);
        }
    }
    images_.add(particles_);

    if (properties_.found("contact"))
    {
        const dictionary& contactDict = properties_.subDict("contact");
        if (contactDict.getOrDefault<bool>("active", true))
        {
            contact_.reset(new particleContact(*this, contactDict, state));
            resolved_ = resolved_ || contact_->needsFractions();
        }
    }

    readOutlets(state);
    if (restarted_)
    {
        checkInputAgainstState(input, statePath);
    }

    // The last step's change of speed and speeds near contacts set the next
    // step's particle Courant number: a restart takes them from the written
    // state
    state.readIfPresent("speedChange", speedChange_);
    state.readIfPresent("nearSpeed", nearSpeed_);

    // Overlaps are input errors at a fresh start only: a restart continues
    // the contacts of the written time, however deep (a brick landing on a
    // wall at 7 % of its thickness stopped a restart of the mixed pile)
    if (!restarted_)
    {
        checkOverlaps();
        if (contact_.valid())
        {
            contact_->checkWalls();
        }
    }
    checkOutlets();

    cells_.setSize(particles_.size());
    fractions_.setSize(particles_.size());
    nearCells_.setSize(particles_.size());
    if (resolved_)
    {
        forAll(particles_, i)
        {
            updateFractions(i);
        }
        reduceTouching();
        updateFields();
    }
    checkStart();

    Info<< "Particles: " << nParticles() << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::dlmParticleCloud::loadDepth() const
{
    if (!twoD())
    {
        return 1;
    }
    const Vector<label>& solved = mesh_.solutionD();
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (solved[d] < 0)
        {
            return mesh_.bounds().span()[d];
        }
    }
    return 1;
}


void Foam::dlmParticleCloud::updateMesh()
{
    updateCellGeometry();

    if (resolved_)
    {
        forAll(particles_, i)
        {
            updateFractions(i);
        }
        reduceTouching();
        updateFields();
    }
}


bool Foam::dlmParticleCloud::moving() const
{
    for (const dlmParticle& p : particles_)
    {
        if (magSqr(p.velocity()) > 0 || magSqr(p.angularVelocity()) > 0)
        {
            return true;
        }
    }
    return false;
}


bool Foam::dlmParticleCloud::allFixed() const
{
    for (const dlmParticle& p : particles_)
    {
        if (p.motion() != dlmParticle::motionType::fixed)
        {
            return false;
        }
    }
    return true;
}


void Foam::dlmParticleCloud::setProjected()
{
    projected_ = true;
}


void Foam::dlmParticleCloud::move()
{
    const cpuTime timer;

    if (!projected_)
    {
        for (const dlmParticle& p : particles_)
        {
            if (p.isFree())
            {
                FatalErrorInFunction
                    << "Particle " << p.name() << " is free but no rigid"
                    << " projection ran this step: add a rigidProjection"
                    << " entry to system/fvOptions" << exit(FatalError);
            }
        }
    }
    const bool predicted = contactPredicted_;
    contactPredicted_ = false;
    projected_ = false;
    ++nMoves_;

    const scalar deltaT = mesh_.time().deltaTValue();

    // Each particle's velocities at the start of the step, for the step's
    // change of its surface speed
    vectorField startVelocity(particles_.size());
    vectorField startOmega(particles_.size());
    pointField startPosition(particles_.size());
    List<quaternion> startOrientation(particles_.size());
    forAll(particles_, i)
    {
        startVelocity[i] = particles_[i].velocity0();
        startOmega[i] = particles_[i].angularVelocity0();
        startPosition[i] = particles_[i].position();
        startOrientation[i] = particles_[i].orientation();
    }

    touchingBoundary_ = -1;
    reachingPeriodic_ = -1;
    if (contact_.valid())
    {
        // The projected motion holds the last step's mean contact loads,
        // which the mixture took this step as a prediction (the rigid
        // projection's source): they come off, the sub-steps add the
        // actual contact, and the rigid projection then gives the
        // particle's cells its velocity at the end of the step (the
        // solver's follow step). The prediction makes a resting particle's
        // load on its contact exact. Both act on the particle with the
        // fluid its cells carry (its coupled mass and inertia), which the
        // follow step moves with it: with the particle's own mass alone a
        // particle lighter than the fluid bounced under a plate every
        // step, the follow step amplifying each contact impulse.
        if (predicted)
        {
            for (dlmParticle& p : particles_)
            {
                if (!p.isFree())
                {
                    continue;
                }
                const scalar perDensity = deltaT/p.density();
                p.setVelocities
                (
                    p.velocity()
                  - perDensity/(p.coupledMassRatio()*p.shape().volume())
                   *p.contactForce(),
                    p.angularVelocity()
                  - perDensity/p.coupledInertiaRatio()
                   *p.spinPerUnitDensity(p.contactTorque())
                );
                p.setLoads
                (
                    p.force() - loadDepth()*p.contactForce(),
                    p.torque() - loadDepth()*p.contactTorque()
                );
            }
        }

        // Held accelerations of the step: fluid and gravity, as projected
        vectorField accel(particles_.size(), Zero);
        vectorField angularAccel(particles_.size(), Zero);
        forAll(particles_, i)
        {
            const dlmParticle& p = particles_[i];
            if (p.isFree())
            {
                accel[i] = (p.velocity() - p.velocity0())/deltaT;
                angularAccel[i] =
                    (p.angularVelocity() - p.angularVelocity0())/deltaT;
            }
        }
        contact_->evolve(deltaT, accel, angularAccel);
    }
    else
    {
        // The images take their particles' state below
        for (label i = 0; i < nParticles(); ++i)
        {
            particles_[i].move(deltaT);
        }
    }

    forAll(particles_, i)
    {
        particles_[i].setStepMotion(startPosition[i], startOrientation[i]);
    }
    images_.wrap(particles_);
    images_.follow(particles_);
    addWorkTime(workPart::motion, timer.elapsedCpuTime());

    if (resolved_)
    {
        const cpuTime fractionTimer;
        forAll(particles_, i)
        {
            if (particles_[i].motion() != dlmParticle::motionType::fixed)
            {
                updateFractions(i);
            }
        }
        reduceTouching();
        updateFields();
        addWorkTime(workPart::fractions, fractionTimer.elapsedCpuTime());
    }

    speedChange_.setSize(particles_.size());
    forAll(particles_, i)
    {
        const dlmParticle& p = particles_[i];
        speedChange_[i] =
            mag(p.velocity() - startVelocity[i])
          + mag(p.angularVelocity() - startOmega[i])
           *p.shape().boundingRadius();
    }
    if (contact_.valid())
    {
        nearSpeed_ = contact_->nearSpeeds(particles_);
    }
}


void Foam::dlmParticleCloud::writeStep(const bool forceVTK)
{
    const bool historyStep =
        historyInterval_ > 0
     && mesh_.time().timeIndex() % historyInterval_ == 0;

    if (historyStep && Pstream::master())
    {
        if (!historyFile_.valid())
        {
            historyFile_ = newRecord("particles", "particles.dat");
            historyFile_()
                << "# time particle x y z Ux Uy Uz omegax omegay omegaz"
                << " Fx Fy Fz Tx Ty Tz Fcx Fcy Fcz Tcx Tcy Tcz qw qx qy qz"
                << nl
                << "# F, T: hydrodynamic force and torque (about the"
                << " centroid)" << (twoD() ? " on the mesh's depth" : "")
                << nl
                << "# Fc, Tc: mean contact force and torque of the step"
                << (twoD() ? " per unit depth" : "") << nl
                << "# q: orientation quaternion (body to global)" << endl;
        }

        OFstream& os = historyFile_();
        const word timeName(mesh_.time().timeName());
        for (label i = 0; i < nParticles(); ++i)
        {
            const dlmParticle& p = particles_[i];
            os  << mesh_.time().value() << ' ' << p.name().c_str();
            for (const vector& v :
                {
                    p.position(), p.velocity(), p.angularVelocity(),
                    p.force(), p.torque(), p.contactForce(), p.contactTorque()
                })
            {
                os  << ' ' << v.x() << ' ' << v.y() << ' ' << v.z();
            }
            const quaternion& q = p.orientation();
            os  << ' ' << q.w() << ' ' << q.v().x() << ' ' << q.v().y()
                << ' ' << q.v().z() << nl;
        }
        os.flush();
    }

    if (forceVTK || mesh_.time().writeTime())
    {
        writeVTK();
    }
}


void Foam::dlmParticleCloud::printWorkTime(const scalar executionTime) const
{
    const scalar share = 100/max(executionTime, SMALL);
    Info<< "Particle work (fractions, projection, motion, output): "
        << workTime() << " s, " << share*workTime()
        << " % of the execution time" << nl
        << "    fractions " << workTimes_[label(workPart::fractions)]
        << " s, projection "
        << workTimes_[label(workPart::projection)]
        << " s, contacts and motion " << workTimes_[label(workPart::motion)]
        << " s, output " << workTimes_[label(workPart::output)] << " s"
        << nl << endl;
}


void Foam::dlmParticleCloud::printSummary() const
{
    Info<< "Particles: " << nParticles() << ", largest speed "
        << maxSurfaceSpeed() << " m/s";
    if (contact_.valid())
    {
        Info<< ", largest overlap "
            << 100*contact_->maxOverlapRatio() << " % of d, "
            << contact_->maxTouching() << " contacts, "
            << contact_->nSubSteps() << " sub-steps";
    }
    Info<< endl;
}


Foam::scalar Foam::dlmParticleCloud::maxSurfaceSpeed() const
{
    scalar speed = 0;
    for (label i = 0; i < nParticles(); ++i)
    {
        speed = max(speed, particles_[i].surfaceSpeed());
    }
    return speed;
}


Foam::scalar Foam::dlmParticleCloud::courantNumber(const scalar deltaT) const
{
    scalar speed = 0;
    for (label i = 0; i < nParticles(); ++i)
    {
        const dlmParticle& p = particles_[i];
        if (!p.isFree())
        {
            continue;
        }
        // The fluid around lags a sudden change of the particle's motion:
        // it meets the particle at the change's speed, the last step's
        // change and the one a bounce off its near neighbours may bring
        // (up to its speed relative to them: a pile moving together bounces
        // nothing off)
        const scalar change =
            i < speedChange_.size() ? speedChange_[i] : 0;
        const scalar bounce = i < nearSpeed_.size() ? nearSpeed_[i] : 0;
        speed = max(speed, p.surfaceSpeed() + change + bounce);
    }
    return speed*deltaT/cellSizes_.min();
}


bool Foam::dlmParticleCloud::writeObject
(
    IOstream::streamFormat,
    IOstream::versionNumber ver,
    IOstream::compressionType cmp,
    const bool valid
) const
{
    return regIOobject::writeObject(IOstream::ASCII, ver, cmp, valid);
}


bool Foam::dlmParticleCloud::writeData(Ostream& os) const
{
    // Full precision, so that a restart continues to round-off
    const auto oldPrecision = os.precision(17);

    os.beginBlock("particles");
    for (label i = 0; i < nParticles(); ++i)
    {
        const dlmParticle& p = particles_[i];
        p.write(os);
    }
    os.endBlock();

    if (contact_.valid())
    {
        contact_->write(os);
    }

    if (outlets_.size())
    {
        os.beginBlock("outlets");
        for (const particleOutlet& outlet : outlets_)
        {
            outlet.writeState(os);
        }
        os.endBlock();
    }

    if (speedChange_.size())
    {
        os.writeEntry("speedChange", speedChange_);
    }
    if (nearSpeed_.size())
    {
        os.writeEntry("nearSpeed", nearSpeed_);
    }

    os.precision(oldPrecision);

    return os.good();
}


// ************************************************************************* //
