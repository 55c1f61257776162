/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "convexOverlap.H"
#include <functional>
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::convexOverlap::convexOverlap()
:
    directions_(200),
    spacing_(Foam::sqrt(4*constant::mathematical::pi/200))
{
    // A golden spiral: nearly even over the sphere
    const scalar goldenAngle =
        constant::mathematical::pi*(3 - Foam::sqrt(scalar(5)));
    forAll(directions_, k)
    {
        const scalar z = 1 - (2*k + 1)/scalar(directions_.size());
        const scalar rho = Foam::sqrt(1 - sqr(z));
        const scalar angle = goldenAngle*k;
        directions_[k] = vector(rho*cos(angle), rho*sin(angle), z);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::convexOverlap::cut
(
    const particleShape& shape,
    const point& X,
    const tensor& R,
    const vector& n,
    const scalar distance,
    scalar& volume,
    point& centroid,
    scalar& area
)
{
    vector bodyCentroid;
    shape.planeCut(R.T() & n, distance, volume, bodyCentroid, area);
    centroid = X + (R & bodyCentroid);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::convexOverlap::depth
(
    const particleShape& a,
    const point& Xa,
    const tensor& Ra,
    const particleShape& b,
    const point& Xb,
    const tensor& Rb,
    const vector& n
)
{
    return
        a.support(Ra.T() & n) + b.support(-(Rb.T() & n))
      - (n & (Xb - Xa));
}


Foam::scalar Foam::convexOverlap::leastDepth
(
    const particleShape& a,
    const point& Xa,
    const tensor& Ra,
    const particleShape& b,
    const point& Xb,
    const tensor& Rb,
    const scalar target,
    vector& n
) const
{
    const vector d(Xb - Xa);
    const scalar magD = mag(d);
    auto delta = [&](const vector& e)
    {
        return depth(a, Xa, Ra, b, Xb, Rb, e);
    };

    // The centre line first: most candidate pairs are apart along it
    n = magD > VSMALL ? d/magD : vector(0, 0, 1);
    scalar least = delta(n);
    if (least <= target)
    {
        return least;
    }

    // Where the support functions have kinks, in the global frame: the
    // least depth of shapes with faces and edges lies on them. b's
    // support is taken at -n: its corners turn round
    DynamicList<vector> ridges, corners, ridgesB, cornersB;
    a.supportKinks(ridges, corners);
    forAll(ridges, k)
    {
        ridges[k] = Ra & ridges[k];
    }
    forAll(corners, k)
    {
        corners[k] = Ra & corners[k];
    }
    b.supportKinks(ridgesB, cornersB);
    for (const vector& r : ridgesB)
    {
        ridges.append(Rb & r);
    }
    for (const vector& c : cornersB)
    {
        corners.append(-(Rb & c));
    }

    // A direction facing away from b overlaps by more than the shapes'
    // sizes: never the least
    auto tryDirection = [&](const vector& e)
    {
        if ((e & d) >= 0)
        {
            const scalar candidate = delta(e);
            if (candidate < least)
            {
                least = candidate;
                n = e;
            }
        }
    };
    for (const vector& c : corners)
    {
        tryDirection(c);
    }

    // Golden sections for the least of f over [lo, hi]
    const scalar tolerance = 1e-9;
    auto goldenSection = [tolerance]
    (
        const std::function<scalar(scalar)>& f,
        scalar lo,
        scalar hi
    )
    {
        const scalar golden = 0.5*(Foam::sqrt(scalar(5)) - 1);
        scalar x1 = hi - golden*(hi - lo);
        scalar x2 = lo + golden*(hi - lo);
        scalar f1 = f(x1);
        scalar f2 = f(x2);
        while (hi - lo > tolerance)
        {
            if (f1 < f2)
            {
                hi = x2;
                x2 = x1;
                f2 = f1;
                x1 = hi - golden*(hi - lo);
                f1 = f(x1);
            }
            else
            {
                lo = x1;
                x1 = x2;
                f1 = f2;
                x2 = lo + golden*(hi - lo);
                f2 = f(x2);
            }
        }
        return 0.5*(lo + hi);
    };

    if (a.nDimensions() == 2 && b.nDimensions() == 2)
    {
        // Prisms along z: the directions of the mesh plane only (towards z
        // their supports vanish, and the depth with them). A circle of
        // directions and the kinks (edge normals), then golden sections
        // about the least found
        const label nAngles = 360;
        const scalar spacing = constant::mathematical::twoPi/nAngles;
        for (label k = 0; k < nAngles; ++k)
        {
            tryDirection(vector(cos(k*spacing), sin(k*spacing), 0));
        }
        const scalar theta0 = atan2(n.y(), n.x());
        auto inPlane = [theta0](const scalar phi)
        {
            return vector(cos(theta0 + phi), sin(theta0 + phi), 0);
        };
        const scalar phi = goldenSection
        (
            [&](const scalar phi) { return delta(inPlane(phi)); },
            -spacing,
            spacing
        );
        const scalar candidate = delta(inPlane(phi));
        if (candidate < least)
        {
            least = candidate;
            n = inPlane(phi);
        }
    }
    else
    {
        for (const vector& e : directions_)
        {
            tryDirection(e);
        }
        forAll(ridges, k)
        {
            // Where two ridges cross (a face's normal, the normal across
            // two edges), and the ridge's point nearest the centre line
            for (label l = k + 1; l < ridges.size(); ++l)
            {
                const vector cross(ridges[k] ^ ridges[l]);
                const scalar magCross = mag(cross);
                if (magCross > 1e-6)
                {
                    tryDirection(cross/magCross);
                    tryDirection(-cross/magCross);
                }
            }
            const vector onRidge(d - (d & ridges[k])*ridges[k]);
            if (mag(onRidge) > 1e-6*magD)
            {
                tryDirection(onRidge/mag(onRidge));
            }
        }

        // Pattern search on the sphere: eight neighbours at angle step in
        // the tangent plane, moving to the best, halving the step when
        // none is better; then along each ridge near the point found
        // (where the pattern search stalls: the depth rises steeply off
        // the ridge), by golden sections, until neither improves. Along a
        // ridge that none of the eight directions follows, the search
        // zigzags across it at the small step where it stalled: millions
        // of moves for a sphere on a box's edge in a pile at rest. Past
        // ten moves at one step the golden sections take over, and a new
        // round starts; the last round is not cut
        const label nRounds = 4;
        for (label round = 0; round < nRounds && least > target; ++round)
        {
            scalar step = spacing_;
            label movesAtStep = 0;
            bool zigzag = false;
            while (least > target && step > tolerance)
            {
                vector t1(n ^ vector(1, 0, 0));
                if (magSqr(t1) < 0.1)
                {
                    t1 = n ^ vector(0, 1, 0);
                }
                t1 /= mag(t1);
                const vector t2(n ^ t1);
                bool moved = false;
                vector best(n);
                for (label k = 0; k < 8; ++k)
                {
                    const scalar angle = constant::mathematical::pi*k/4;
                    const vector e
                    (
                        cos(step)*n
                      + sin(step)*(cos(angle)*t1 + sin(angle)*t2)
                    );
                    const scalar candidate = delta(e);
                    if (candidate < least)
                    {
                        least = candidate;
                        best = e;
                        moved = true;
                    }
                }
                if (moved)
                {
                    n = best/mag(best);
                    if (++movesAtStep > 10 && round < nRounds - 1)
                    {
                        zigzag = true;
                        break;
                    }
                }
                else
                {
                    step *= 0.5;
                    movesAtStep = 0;
                }
            }

            bool improved = false;
            for (const vector& r : ridges)
            {
                vector m(n - (n & r)*r);
                const scalar magM = mag(m);
                if (magM < 1e-9 || mag(n & r) > Foam::sin(spacing_))
                {
                    continue;
                }
                m /= magM;
                const vector t(r ^ m);
                auto along = [&](const scalar phi)
                {
                    return delta(cos(phi)*m + sin(phi)*t);
                };
                const scalar phi = goldenSection(along, -spacing_, spacing_);
                const scalar candidate = along(phi);
                if (candidate < least - 1e-12*mag(least))
                {
                    least = candidate;
                    n = cos(phi)*m + sin(phi)*t;
                    improved = true;
                }
            }
            if (!improved && !zigzag)
            {
                break;
            }
        }
    }

    return least;
}


bool Foam::convexOverlap::separated
(
    const particleShape& a,
    const point& Xa,
    const tensor& Ra,
    const particleShape& b,
    const point& Xb,
    const tensor& Rb,
    const scalar gap
) const
{
    vector n;
    return leastDepth(a, Xa, Ra, b, Xb, Rb, -gap, n) <= -gap;
}


Foam::convexOverlap::result Foam::convexOverlap::overlap
(
    const particleShape& a,
    const point& Xa,
    const tensor& Ra,
    const particleShape& b,
    const point& Xb,
    const tensor& Rb
) const
{
    result o{0, 0, vector(0, 0, 1), 0.5*(Xa + Xb), 0};
    const vector d(Xb - Xa);
    vector n;
    const scalar least = leastDepth(a, Xa, Ra, b, Xb, Rb, 0, n);
    o.depth = least;
    o.normal = n;
    if (least <= 0)
    {
        return o;
    }

    // The common plane at distance s from Xa along n, between a's part at
    // depth least (s = ha - least) and b's (s = ha), where the sections
    // are equal: a's shrinks and b's grows as s grows. Regula falsi on the
    // difference with the Illinois halving, a bisection whenever a step
    // fails to halve the bracket (the sections of faces jump)
    const scalar ha = a.support(Ra.T() & n);
    const scalar along = n & d;
    scalar Va = 0, Vb = 0, areaA = 0, areaB = 0;
    point Ca(Xa), Cb(Xb);
    auto difference = [&](const scalar s)
    {
        cut(a, Xa, Ra, n, s, Va, Ca, areaA);
        cut(b, Xb, Rb, -n, along - s, Vb, Cb, areaB);
        return areaA - areaB;
    };
    scalar low = ha - least;
    scalar high = ha;
    scalar gLow = difference(low);
    scalar gHigh = difference(high);
    label side = 0;
    bool bisect = false;
    for (label iter = 0; iter < 60 && high - low > 1e-12*least; ++iter)
    {
        const scalar width = high - low;
        scalar s = 0.5*(low + high);
        if (!bisect && gLow > 0 && gHigh < 0)
        {
            s = (low*gHigh - high*gLow)/(gHigh - gLow);
            if (!(s > low && s < high))
            {
                s = 0.5*(low + high);
            }
        }
        const scalar g = difference(s);
        if (g > 0)
        {
            low = s;
            gLow = g;
            gHigh *= side == 1 ? 0.5 : 1;
            side = 1;
        }
        else
        {
            high = s;
            gHigh = g;
            gLow *= side == -1 ? 0.5 : 1;
            side = -1;
        }
        bisect = high - low > 0.5*width;
    }
    const scalar s = 0.5*(low + high);
    cut(a, Xa, Ra, n, s, Va, Ca, areaA);
    cut(b, Xb, Rb, -n, along - s, Vb, Cb, areaB);

    o.volume = Va + Vb;
    if (o.volume > 0)
    {
        o.location = (Va*Ca + Vb*Cb)/o.volume;
    }
    // The smaller section: the two meet where the shapes are smooth; a
    // face on a larger face touches over the smaller one, the plane then
    // at the larger face, whose part beyond it may round to nothing
    o.sectionArea =
        Va > 0 && Vb > 0 ? min(areaA, areaB) : max(areaA, areaB);
    return o;
}


// ************************************************************************* //
