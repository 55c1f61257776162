/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "convexOverlap.H"
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
    const scalar magD = mag(d);
    auto delta = [&](const vector& n)
    {
        return depth(a, Xa, Ra, b, Xb, Rb, n);
    };

    // The centre line first: most candidate pairs are apart along it
    vector n(magD > VSMALL ? d/magD : vector(0, 0, 1));
    scalar least = delta(n);
    if (least > 0)
    {
        for (const vector& e : directions_)
        {
            // A direction facing away from b overlaps by more than the
            // shapes' sizes: never the least
            if ((e & d) > 0)
            {
                const scalar candidate = delta(e);
                if (candidate < least)
                {
                    least = candidate;
                    n = e;
                }
            }
        }
    }

    // Pattern search on the sphere: eight neighbours at angle step in the
    // tangent plane, moving to the best, halving the step when none is
    // better
    scalar step = spacing_;
    while (least > 0 && step > 1e-9)
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
                cos(step)*n + sin(step)*(cos(angle)*t1 + sin(angle)*t2)
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
        }
        else
        {
            step *= 0.5;
        }
    }

    o.depth = least;
    o.normal = n;
    if (least <= 0)
    {
        return o;
    }

    // The common plane at distance s from Xa along n, between a's part at
    // depth least (s = ha - least) and b's (s = ha): bisection for equal
    // sections, a's section shrinking and b's growing as s grows
    const scalar ha = a.support(Ra.T() & n);
    const scalar along = n & d;
    scalar low = ha - least;
    scalar high = ha;
    scalar Va = 0, Vb = 0, areaA = 0, areaB = 0;
    point Ca(Xa), Cb(Xb);
    for (label iter = 0; iter < 60 && high - low > 1e-12*least; ++iter)
    {
        const scalar s = 0.5*(low + high);
        cut(a, Xa, Ra, n, s, Va, Ca, areaA);
        cut(b, Xb, Rb, -n, along - s, Vb, Cb, areaB);
        if (areaA > areaB)
        {
            low = s;
        }
        else
        {
            high = s;
        }
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
    // face on a larger face touches over the smaller one
    o.sectionArea = min(areaA, areaB);
    return o;
}


// ************************************************************************* //
