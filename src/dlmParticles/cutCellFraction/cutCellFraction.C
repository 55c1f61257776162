/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "cutCellFraction.H"
#include "mathematicalConstants.H"
#include "FixedList.H"
#include "DynamicList.H"

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
           *(t*Foam::sqrt(1 - t*t) + Foam::asin(t) + 0.5*Foam::constant::mathematical::pi);
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
        const scalar yb = Foam::sqrt(rho*rho - b*b);
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

    // Gauss-Legendre points and weights on [-1, 1]
    const Foam::FixedList<scalar, 4> gaussPoints
    ({
        -0.8611363115940526, -0.3399810435848563,
        0.3399810435848563, 0.8611363115940526
    });
    const Foam::FixedList<scalar, 4> gaussWeights
    ({
        0.3478548451374538, 0.6521451548625461,
        0.6521451548625461, 0.3478548451374538
    });
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
    const scalar x0 = max(lo.x(), -R);
    const scalar x1 = min(hi.x(), R);
    if (x1 <= x0)
    {
        return 0;
    }

    // Slices x where the slice circle meets an edge or a corner of the
    // rectangle: the area is smooth between them
    DynamicList<scalar> breaks(16);
    breaks.append(x0);
    const FixedList<scalar, 2> ys({lo.y(), hi.y()});
    const FixedList<scalar, 2> zs({lo.z(), hi.z()});
    DynamicList<scalar> reaches(8);
    for (const scalar y : ys)
    {
        reaches.append(mag(y));
        for (const scalar z : zs)
        {
            reaches.append(sqrt(y*y + z*z));
        }
    }
    for (const scalar z : zs)
    {
        reaches.append(mag(z));
    }
    for (const scalar c : reaches)
    {
        if (c < R)
        {
            const scalar x = sqrt(R*R - c*c);
            for (const scalar xb : {-x, x})
            {
                if (xb > x0 && xb < x1)
                {
                    breaks.append(xb);
                }
            }
        }
    }
    breaks.append(x1);
    Foam::sort(breaks);

    scalar volume = 0;
    for (label i = 0; i + 1 < breaks.size(); ++i)
    {
        const scalar mid = 0.5*(breaks[i] + breaks[i + 1]);
        const scalar half = 0.5*(breaks[i + 1] - breaks[i]);
        if (half <= 0)
        {
            continue;
        }
        for (label k = 0; k < gaussPoints.size(); ++k)
        {
            const scalar x = mid + half*gaussPoints[k];
            const scalar rho = sqrt(max(R*R - x*x, scalar(0)));
            volume +=
                half*gaussWeights[k]
               *circleRectangleArea(rho, lo.y(), hi.y(), lo.z(), hi.z());
        }
    }
    return volume;
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
