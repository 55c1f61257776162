/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
-------------------------------------------------------------------------------
Application
    dlmShapeFractions

Group
    grpMiscellaneousUtilities

Description
    Accuracy and cost of a particle shape's solid fractions on a mesh of
    cubic cells, as the solver computes them (dlmParticleCloud: every cell
    within the bounding radius plus a cell of the centre, boxFraction with
    leaves of the bounding radius over surfaceResolution). For a number of
    random centres (and random orientations with -rotate) it sums fraction
    times cell volume and reports the relative error of the sum against the
    shape's exact volume: the mean of its magnitude, the largest magnitude
    and the signed mean. It times the fractions of one particle (CPU time,
    repeated over the samples until -minTime has passed) against those of
    a sphere of the same volume (a disk of the same area in 2D) at the same
    centres and cell size.

    Two-dimensional shapes lie in a layer of cells of unit depth along z,
    subdivided in x and y only, rotated about z.

Usage
    \b dlmShapeFractions -shape '<shape entries>' [OPTIONS]

    Options:
      - \par -shape '<entries>'
        The shape's entries as in a particle dictionary, e.g.
        'shape ellipsoid; semiAxes (0.02 0.01 0.01);'
      - \par -cells \<n\>
        Cells per smallest dimension (the least extent along the body
        axes), default 8
      - \par -samples \<n\>
        Random centres (and orientations), default 8
      - \par -rotate
        Random orientations (default: the body axes along the mesh axes)
      - \par -surfaceResolution \<s\>
        Bounding radius over the leaf size, default 32 (the solver's)
      - \par -seed \<n\>
        Random seed, default 1
      - \par -minTime \<s\>
        Least CPU time over which each timing is averaged, default 0.2

    The last line of the output holds the results as name-value pairs.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "particleShape.H"
#include "quaternion.H"
#include "Random.H"
#include "cpuTime.H"
#include "IStringStream.H"
#include "OStringStream.H"
#include "labelVector.H"
#include "mathematicalConstants.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

// Sum of fraction times cell volume over the cells of side h (a unit depth
// along z in 2D) that the solver visits for the shape at X with rotation R
scalar fractionVolume
(
    const particleShape& shape,
    const point& X,
    const tensor& R,
    const scalar h,
    const scalar leafSize
)
{
    const bool twoD = shape.nDimensions() == 2;
    const vector split(1, 1, twoD ? 0 : 1);
    const scalar reach = shape.boundingRadius() + 1.01*h;
    labelVector lo, hi;
    for (direction d = 0; d < 3; ++d)
    {
        lo[d] = std::floor((X[d] - reach)/h);
        hi[d] = std::floor((X[d] + reach)/h);
    }
    if (twoD)
    {
        lo.z() = 0;
        hi.z() = 0;
    }

    scalar sum = 0;
    for (label i = lo.x(); i <= hi.x(); ++i)
    {
        for (label j = lo.y(); j <= hi.y(); ++j)
        {
            for (label k = lo.z(); k <= hi.z(); ++k)
            {
                const point cellLo(h*i, h*j, twoD ? 0 : h*k);
                const point cellHi(cellLo + vector(h, h, twoD ? 1 : h));
                const boundBox bb(cellLo, cellHi);
                sum +=
                    shape.boxFraction(bb, X, R, split, leafSize)*bb.volume();
            }
        }
    }
    return sum;
}


// CPU time per particle of the fractions at the given centres, averaged
// over repeats of all of them until minTime has passed
scalar timePerParticle
(
    const particleShape& shape,
    const List<point>& centres,
    const List<tensor>& rotations,
    const scalar h,
    const scalar leafSize,
    const scalar minTime
)
{
    cpuTime timer;
    label nParticles = 0;
    do
    {
        forAll(centres, s)
        {
            fractionVolume(shape, centres[s], rotations[s], h, leafSize);
            ++nParticles;
        }
    } while (timer.elapsedCpuTime() < minTime);
    return timer.elapsedCpuTime()/nParticles;
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Relative error of a shape's solid fractions summed over a mesh of"
        " cubic cells against its volume, and their CPU time against a"
        " sphere's of the same volume"
    );
    argList::noParallel();
    argList::noBanner();
    argList::addOption("shape", "entries", "The shape's dictionary entries");
    argList::addOption("cells", "n", "Cells per smallest dimension (8)");
    argList::addOption("samples", "n", "Random centres (8)");
    argList::addBoolOption("rotate", "Random orientations");
    argList::addOption
    (
        "surfaceResolution", "s", "Bounding radius over leaf size (32)"
    );
    argList::addOption("seed", "n", "Random seed (1)");
    argList::addOption("minTime", "s", "Least CPU time of a timing (0.2)");

    argList args(argc, argv, false, false, false);
    if (!args.found("shape"))
    {
        FatalErrorInFunction
            << "Give the shape's entries: -shape 'shape ...; ...;'"
            << exit(FatalError);
    }

    IStringStream is(args.opt<string>("shape"));
    const dictionary dict(is);
    autoPtr<particleShape> shape(particleShape::New(dict));

    const label cells = args.opt<label>("cells", 8);
    const label samples = args.opt<label>("samples", 8);
    const bool rotate = args.found("rotate");
    const scalar surfaceResolution =
        args.opt<scalar>("surfaceResolution", 32);
    const scalar minTime = args.opt<scalar>("minTime", 0.2);
    Random rnd(args.opt<label>("seed", 1));

    const bool twoD = shape->nDimensions() == 2;
    scalar smallest = GREAT;
    for (direction d = 0; d < (twoD ? 2 : 3); ++d)
    {
        vector axis(Zero);
        axis[d] = 1;
        smallest = min(smallest, shape->thickness(axis));
    }
    const scalar h = smallest/cells;
    const scalar V = shape->volume();
    const scalar leafSize = shape->boundingRadius()/surfaceResolution;

    // Random centres within a cell and orientations (uniform rotations, by
    // quaternions from three uniform numbers; about z in 2D)
    List<point> centres(samples);
    List<tensor> rotations(samples, tensor::I);
    forAll(centres, s)
    {
        centres[s] = h*rnd.sample01<vector>();
        if (twoD)
        {
            centres[s].z() = 0.5;
        }
        if (rotate)
        {
            const scalar twoPi = constant::mathematical::twoPi;
            if (twoD)
            {
                const scalar angle = twoPi*rnd.sample01<scalar>();
                rotations[s] = quaternion(vector(0, 0, 1), angle).R();
            }
            else
            {
                const scalar u1 = rnd.sample01<scalar>();
                const scalar u2 = twoPi*rnd.sample01<scalar>();
                const scalar u3 = twoPi*rnd.sample01<scalar>();
                const scalar a = Foam::sqrt(1 - u1);
                const scalar b = Foam::sqrt(u1);
                rotations[s] = quaternion
                (
                    a*Foam::cos(u2),
                    vector(a*Foam::sin(u2), b*Foam::sin(u3), b*Foam::cos(u3))
                ).R();
            }
        }
    }

    scalar meanMagError = 0;
    scalar maxMagError = 0;
    scalar meanError = 0;
    forAll(centres, s)
    {
        const scalar error =
            fractionVolume(*shape, centres[s], rotations[s], h, leafSize)/V
          - 1;
        Info<< "sample " << s << " centre " << centres[s]
            << " error " << error << nl;
        meanMagError += mag(error)/samples;
        maxMagError = max(maxMagError, mag(error));
        meanError += error/samples;
    }

    // The sphere (disk) of the same volume (area)
    OStringStream reference;
    if (twoD)
    {
        reference
            << "shape disk; radius "
            << Foam::sqrt(V/constant::mathematical::pi) << ";";
    }
    else
    {
        reference
            << "shape sphere; radius "
            << Foam::cbrt(3*V/(4*constant::mathematical::pi)) << ";";
    }
    IStringStream referenceStream(reference.str());
    autoPtr<particleShape> sphere
    (
        particleShape::New(dictionary(referenceStream))
    );
    const scalar time =
        timePerParticle(*shape, centres, rotations, h, leafSize, minTime);
    const scalar sphereTime = timePerParticle
    (
        *sphere, centres, rotations, h,
        sphere->boundingRadius()/surfaceResolution, minTime
    );

    Info<< "shape " << shape->type()
        << " volume " << V
        << " smallest " << smallest
        << " cells " << cells
        << " cellSize " << h
        << " leafSize " << leafSize
        << " samples " << samples
        << " rotated " << rotate
        << " meanMagError " << meanMagError
        << " maxMagError " << maxMagError
        << " meanError " << meanError
        << " timePerParticle " << time
        << " sphereTimePerParticle " << sphereTime
        << " timeRatio " << time/sphereTime << endl;

    return 0;
}


// ************************************************************************* //
