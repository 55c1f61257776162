/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "cutCellFraction.H"
#include "mathematicalConstants.H"
#include "FixedList.H"
#include "vector2D.H"


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{
    using Foam::scalar;

    // Integral of the half chord sqrt(rho^2 - y^2) from -rho to y
    scalar halfChordIntegral(const scalar rho, const scalar y)
    {
        const scalar t = Foam::min(Foam::max(y/rho, -1.0), 1.0);
        return
            0.5*Foam::sqr(rho)
           *(
                t*Foam::sqrt((1 - t)*(1 + t)) + Foam::asin(t)
              + 0.5*Foam::constant::mathematical::pi
            );
    }

    // Integral over y in [y0, y1] of clamp(b, -s, s), s = sqrt(rho^2 - y^2)
    // the half chord, given S0 = S(y0) and S1 = S(y1) of halfChordIntegral
    // (y0, y1 within [-rho, rho]): the part of the chords below z = b, less
    // the half chords
    scalar chordsBelow
    (
        const scalar rho,
        const scalar y0,
        const scalar y1,
        const scalar S0,
        const scalar S1,
        const scalar b
    )
    {
        if (b >= rho)
        {
            return S1 - S0;
        }
        if (b <= -rho)
        {
            return S0 - S1;
        }

        // |y| < yb: the chord's part below b ends at b; elsewhere at +-s
        const scalar yb = Foam::sqrt((rho - b)*(rho + b));
        const scalar lo = Foam::max(y0, -yb);
        const scalar hi = Foam::min(y1, yb);
        if (hi <= lo)
        {
            return (b > 0 ? 1 : -1)*(S1 - S0);
        }
        const scalar inner =
            halfChordIntegral(rho, hi) - halfChordIntegral(rho, lo);
        return (b > 0 ? 1 : -1)*(S1 - S0 - inner) + b*(hi - lo);
    }

    // Antiderivative over x of the area of the unit ball's slice at x in
    // the quadrant y > b, z > c (b, c >= 0, x^2 + b^2 + c^2 <= 1), given
    // sb = sqrt(1 - x^2 - b^2) and sc = sqrt(1 - x^2 - c^2). The slice's
    // area is (rho^2 (pi/2 - asin(b/rho) - asin(c/rho)) - b sb - c sc)/2
    // + b c with rho^2 = 1 - x^2; its terms integrate in closed form (the
    // arcsines by parts), written with atan2 of the square roots, which
    // keeps them accurate where a square root vanishes
    scalar quadrantSlicePrimitive
    (
        const scalar x,
        const scalar b,
        const scalar c,
        const scalar sb,
        const scalar sc
    )
    {
        const scalar v = x - x*x*x/3;

        // Integral of (1 - x^2) asin(d/rho) (d = b or c), and of the half
        // chord d s: s = sqrt(k^2 - x^2), k^2 = 1 - d^2
        auto arcsinePart = [x, v](const scalar d, const scalar s)
        {
            const scalar k2 = (1 - d)*(1 + d);
            const scalar t = Foam::atan2(x, s);
            return
                v*Foam::atan2(d, s)
              - d/3*(0.5*(k2*t - x*s) - 2*t)
              - 2.0/3.0*Foam::atan2(x*d, s)
              + 0.5*d*(x*s + k2*t);
        };

        return
            0.25*Foam::constant::mathematical::pi*v
          - 0.5*(arcsinePart(b, sb) + arcsinePart(c, sc))
          + b*c*x;
    }

    // Volume of the unit ball in x > a, y > b, z > c (a, b, c >= 0)
    scalar unitOctantVolume(const scalar a, const scalar b, const scalar c)
    {
        const scalar top = 1 - b*b - c*c;
        if (a >= 1 || a*a >= top)
        {
            return 0;
        }
        const scalar x1 = Foam::sqrt(top);
        const scalar sb = Foam::sqrt(Foam::max(1 - a*a - b*b, scalar(0)));
        const scalar sc = Foam::sqrt(Foam::max(1 - a*a - c*c, scalar(0)));
        return
            quadrantSlicePrimitive(x1, b, c, c, b)
          - quadrantSlicePrimitive(a, b, c, sb, sc);
    }

    // Volume of the unit ball in the box [lo, hi] of the positive octant:
    // the octant volumes of its corners, with alternating signs
    scalar unitOctantBoxVolume(const Foam::vector& lo, const Foam::vector& hi)
    {
        scalar volume = 0;
        for (int i = 0; i < 2; ++i)
        {
            for (int j = 0; j < 2; ++j)
            {
                for (int k = 0; k < 2; ++k)
                {
                    const scalar corner = unitOctantVolume
                    (
                        i ? hi.x() : lo.x(),
                        j ? hi.y() : lo.y(),
                        k ? hi.z() : lo.z()
                    );
                    volume += (i + j + k) % 2 ? -corner : corner;
                }
            }
        }
        return volume;
    }
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

Foam::scalar Foam::cutCellFraction::circleRectangleArea
(
    const scalar rho,
    const scalar y0,
    const scalar y1,
    const scalar z0,
    const scalar z1
)
{
    const scalar ya = max(y0, -rho);
    const scalar yb = min(y1, rho);
    if (rho <= 0 || yb <= ya || z1 <= z0)
    {
        return 0;
    }

    // Each chord y in [ya, yb] keeps its part between z0 and z1
    const scalar S0 = halfChordIntegral(rho, ya);
    const scalar S1 = halfChordIntegral(rho, yb);
    return
        chordsBelow(rho, ya, yb, S0, S1, z1)
      - chordsBelow(rho, ya, yb, S0, S1, z0);
}


Foam::scalar Foam::cutCellFraction::sphereBoxVolume
(
    const scalar R,
    const vector& lo,
    const vector& hi
)
{
    // In units of R, split at the centre's planes, each part reflected
    // into the positive octant (at most eight parts; one for most cells)
    FixedList<FixedList<vector2D, 2>, 3> parts;
    FixedList<label, 3> nParts;
    for (direction d = 0; d < 3; ++d)
    {
        const scalar a = min(max(lo[d]/R, scalar(-1)), scalar(1));
        const scalar b = min(max(hi[d]/R, scalar(-1)), scalar(1));
        if (b <= a)
        {
            return 0;
        }
        nParts[d] = 0;
        if (a < 0)
        {
            parts[d][nParts[d]++] = vector2D(max(-b, scalar(0)), -a);
        }
        if (b > 0)
        {
            parts[d][nParts[d]++] = vector2D(max(a, scalar(0)), b);
        }
    }

    scalar volume = 0;
    for (label i = 0; i < nParts[0]; ++i)
    {
        for (label j = 0; j < nParts[1]; ++j)
        {
            for (label k = 0; k < nParts[2]; ++k)
            {
                volume += unitOctantBoxVolume
                (
                    vector(parts[0][i].x(), parts[1][j].x(), parts[2][k].x()),
                    vector(parts[0][i].y(), parts[1][j].y(), parts[2][k].y())
                );
            }
        }
    }
    return pow3(R)*volume;
}


Foam::scalar Foam::cutCellFraction::unitCube
(
    scalar m1,
    scalar m2,
    scalar m3,
    scalar alpha
)
{
    if (alpha <= 0)
    {
        return 0;
    }
    if (alpha >= 1)
    {
        return 1;
    }

    // The fraction is symmetric: V(alpha) = 1 - V(1 - alpha)
    const bool upperHalf = alpha > 0.5;
    if (upperHalf)
    {
        alpha = 1 - alpha;
    }

    // Below this a component is treated as zero: the lower-dimensional
    // formulas avoid dividing by it (error of the order of the component)
    constexpr scalar negligible = 1e-9;

    scalar V;

    if (m2 < negligible)
    {
        // Plane normal to one axis
        V = alpha;
    }
    else if (m1 < negligible)
    {
        // Square cut by a line
        V =
            alpha < m2
          ? sqr(alpha)/(2*m2*m3)
          : (alpha - 0.5*m2)/m3;
    }
    else
    {
        const scalar m12 = m1 + m2;

        if (alpha < m1)
        {
            V = pow3(alpha)/(6*m1*m2*m3);
        }
        else if (alpha < m2)
        {
            V = alpha*(alpha - m1)/(2*m2*m3) + sqr(m1)/(6*m2*m3);
        }
        else if (alpha < min(m12, m3))
        {
            V =
            (
                sqr(alpha)*(3*m12 - alpha)
              + sqr(m1)*(m1 - 3*alpha)
              + sqr(m2)*(m2 - 3*alpha)
            )/(6*m1*m2*m3);
        }
        else if (m3 < m12)
        {
            V =
            (
                sqr(alpha)*(3 - 2*alpha)
              + sqr(m1)*(m1 - 3*alpha)
              + sqr(m2)*(m2 - 3*alpha)
              + sqr(m3)*(m3 - 3*alpha)
            )/(6*m1*m2*m3);
        }
        else
        {
            V = (2*alpha - m12)/(2*m3);
        }
    }

    V = min(max(V, scalar(0)), scalar(0.5));

    return upperHalf ? 1 - V : V;
}


Foam::scalar Foam::cutCellFraction::box
(
    const vector& n,
    const scalar d,
    const vector& span
)
{
    // In unit-cube coordinates s in [0,1]^3 (axes flipped so that every
    // coefficient is non-negative) the inside is sum(m_i s_i) < alpha
    scalar m[3] =
    {
        mag(n.x())*span.x(),
        mag(n.y())*span.y(),
        mag(n.z())*span.z()
    };
    const scalar sum = m[0] + m[1] + m[2];

    if (sum <= 0)
    {
        return d < 0 ? 1 : 0;
    }

    const scalar alpha = 0.5 - d/sum;

    m[0] /= sum;
    m[1] /= sum;
    m[2] /= sum;

    // Sort ascending
    if (m[0] > m[1]) std::swap(m[0], m[1]);
    if (m[1] > m[2]) std::swap(m[1], m[2]);
    if (m[0] > m[1]) std::swap(m[0], m[1]);

    return unitCube(m[0], m[1], m[2], alpha);
}


// ************************************************************************* //
