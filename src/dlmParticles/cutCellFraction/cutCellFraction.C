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

    // Area of the circle of radius rho about the origin with y < a, z < b
    scalar quadrantArea(const scalar rho, const scalar a, const scalar b)
    {
        if (a <= -rho || b <= -rho)
        {
            return 0;
        }
        // Each slice y has the chord [-s, s], s = sqrt(rho^2 - y^2), of
        // which z < b keeps s + clamp(b, -s, s)
        const scalar upToA = halfChordIntegral(rho, a);
        if (b >= rho)
        {
            return 2*upToA;
        }

        const scalar yb = Foam::sqrt(rho*rho - b*b);
        const scalar sign = b >= 0 ? 1 : -1;
        scalar clamped = sign*halfChordIntegral(rho, Foam::min(a, -yb));
        if (a > -yb)
        {
            clamped += b*(Foam::min(a, yb) + yb);
        }
        if (a > yb)
        {
            clamped += sign*(upToA - halfChordIntegral(rho, yb));
        }
        return upToA + clamped;
    }

    // Gauss-Legendre points and weights on [-1, 1]
    const Foam::FixedList<scalar, 8> gaussPoints
    ({
        -0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
        -0.1834346424956498, 0.1834346424956498, 0.5255324099163290,
        0.7966664774136267, 0.9602898564975363
    });
    const Foam::FixedList<scalar, 8> gaussWeights
    ({
        0.1012285362903763, 0.2223810344533745, 0.3137066458778873,
        0.3626837833783620, 0.3626837833783620, 0.3137066458778873,
        0.2223810344533745, 0.1012285362903763
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
    if (rho <= 0 || y1 <= y0 || z1 <= z0)
    {
        return 0;
    }
    return
        quadrantArea(rho, y1, z1) - quadrantArea(rho, y0, z1)
      - quadrantArea(rho, y1, z0) + quadrantArea(rho, y0, z0);
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
