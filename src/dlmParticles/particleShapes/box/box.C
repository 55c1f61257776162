/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "box.H"
#include "cutCellFraction.H"
#include "DynamicList.H"
#include "vector2D.H"
#include "labelVector.H"
#include "gaussLegendre.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

#include <functional>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace particleShapes
{
    defineTypeNameAndDebug(box, 0);
    addToRunTimeSelectionTable(particleShape, box, dictionary);
}
}


namespace
{

using namespace Foam;

// The part of a rounded rectangle beyond a line: the rectangle of half
// extents p, q along x and y grown by rho, the line m.x = e (m unit), the
// part on m's side. Its area, first moments about the origin and the length
// of the chord, from boundary integrals (Green) over the kept parts of the
// sides and arcs, in the line's frame: u along the line from its point
// nearest the origin, v = m.x - e across it. There the chord (v = 0) adds
// nothing and every term is as small as the part (a sliver of depth 1e-16
// of the size keeps its relative precision: the contacts' first touch).
// An arc adds its chord and the circular segment between chord and arc.
struct sliceCut
{
    scalar area;
    vector2D moment;
    scalar chord;
};

sliceCut roundedRectangleCut
(
    const scalar p,
    const scalar q,
    const scalar rho,
    const vector2D& m,
    const scalar e
)
{
    sliceCut cut{0, vector2D::zero, 0};

    // Nothing beyond the line, or all (centred: no first moments)
    const scalar support = p*mag(m.x()) + q*mag(m.y()) + rho;
    if (e >= support)
    {
        return cut;
    }
    if (e <= -support)
    {
        cut.area =
            4*p*q + 4*rho*(p + q) + constant::mathematical::pi*sqr(rho);
        return cut;
    }

    const vector2D t(m.y(), -m.x());
    const vector2D x0(e*m);
    auto frame = [&](const vector2D& x) { return vector2D(t & x, (m & x) - e); };

    // Counter-clockwise pieces (u, v): area -v du, moments -u v du and
    // -v^2/2 du
    scalar area = 0;
    vector2D moment(Zero);
    auto addSegment = [&](const vector2D& a, const vector2D& b)
    {
        const scalar du = b.x() - a.x();
        area -= 0.5*(a.y() + b.y())*du;
        moment.x() -=
            du*(2*a.x()*a.y() + a.x()*b.y() + b.x()*a.y() + 2*b.x()*b.y())/6;
        moment.y() -= du*(sqr(a.y()) + a.y()*b.y() + sqr(b.y()))/6;
    };
    // The arc about c (x, y frame) from angle ta to tb: its chord and the
    // segment beyond it (area rho^2 (w - sin w)/2, w = tb - ta; first
    // moment about c 2/3 rho^3 sin^3(w/2) along the bisector)
    auto addArc = [&](const vector2D& c, const scalar ta, const scalar tb)
    {
        addSegment
        (
            frame(c + rho*vector2D(Foam::cos(ta), Foam::sin(ta))),
            frame(c + rho*vector2D(Foam::cos(tb), Foam::sin(tb)))
        );
        const scalar w = tb - ta;
        const scalar wLessSin =
            w < 1e-3
          ? pow3(w)/6*(1 - sqr(w)/20*(1 - sqr(w)/42))
          : w - Foam::sin(w);
        const scalar segment = 0.5*sqr(rho)*wLessSin;
        const scalar bisector = 0.5*(ta + tb);
        const vector2D cuv(frame(c));
        const vector2D along
        (
            frame(c + vector2D(Foam::cos(bisector), Foam::sin(bisector)))
          - cuv
        );
        area += segment;
        moment +=
            segment*cuv + 2.0/3.0*pow3(rho*Foam::sin(0.5*w))*along;
    };

    // The sides, each followed by the arc about the corner it leads to
    const vector2D corners[4] =
        {vector2D(p, q), vector2D(-p, q), vector2D(-p, -q), vector2D(p, -q)};
    const vector2D outward[4] =
        {vector2D(1, 0), vector2D(0, 1), vector2D(-1, 0), vector2D(0, -1)};
    const scalar angleM = Foam::atan2(m.y(), m.x());
    for (label k = 0; k < 4; ++k)
    {
        const vector2D a(frame(corners[(k + 3) % 4] + rho*outward[k]));
        const vector2D b(frame(corners[k] + rho*outward[k]));
        if (a.y() >= 0 && b.y() >= 0)
        {
            addSegment(a, b);
        }
        else if (a.y() >= 0)
        {
            addSegment(a, a + a.y()/(a.y() - b.y())*(b - a));
        }
        else if (b.y() >= 0)
        {
            addSegment(a + a.y()/(a.y() - b.y())*(b - a), b);
        }

        // The arc from angle k pi/2 to (k + 1) pi/2 about corner k: kept
        // within a half-width of angleM where cos(angle - angleM) >= s
        // (by its sine where s is near 1: a sliver's precision)
        const vector2D& c = corners[k];
        const scalar oneLessS = (rho - e + (m & c))/rho;
        const scalar start = k*constant::mathematical::piByTwo;
        if (oneLessS >= 2)
        {
            addArc(c, start, start + constant::mathematical::piByTwo);
        }
        else if (oneLessS > 0)
        {
            const scalar halfWidth =
                oneLessS < 1
              ? 2*Foam::asin(Foam::sqrt(0.5*oneLessS))
              : Foam::acos(1 - oneLessS);
            // The arc relative to angleM, starting in (-pi, pi]
            scalar psiA = start - angleM;
            while (psiA > constant::mathematical::pi)
            {
                psiA -= constant::mathematical::twoPi;
            }
            while (psiA <= -constant::mathematical::pi)
            {
                psiA += constant::mathematical::twoPi;
            }
            const scalar psiB = psiA + constant::mathematical::piByTwo;
            for (const scalar centre : {0.0, constant::mathematical::twoPi})
            {
                const scalar lo = max(psiA, centre - halfWidth);
                const scalar hi = min(psiB, centre + halfWidth);
                if (hi > lo)
                {
                    addArc(c, angleM + lo, angleM + hi);
                }
            }
        }
    }

    // Back to the origin's frame
    cut.area = area;
    cut.moment = area*x0 + moment.x()*t + moment.y()*m;

    // The chord: the line's interval inside the union of the two crossed
    // rectangles and the four corner disks (a convex union)
    scalar lo = GREAT;
    scalar hi = -GREAT;
    auto addRectangle = [&](const vector2D& h)
    {
        scalar tIn = -GREAT;
        scalar tOut = GREAT;
        for (direction d = 0; d < 2; ++d)
        {
            if (mag(t[d]) > SMALL)
            {
                const scalar t1 = (-h[d] - x0[d])/t[d];
                const scalar t2 = (h[d] - x0[d])/t[d];
                tIn = max(tIn, min(t1, t2));
                tOut = min(tOut, max(t1, t2));
            }
            else if (mag(x0[d]) > h[d])
            {
                return;
            }
        }
        if (tIn <= tOut)
        {
            lo = min(lo, tIn);
            hi = max(hi, tOut);
        }
    };
    addRectangle(vector2D(p + rho, q));
    addRectangle(vector2D(p, q + rho));
    for (const vector2D& c : corners)
    {
        const vector2D w(x0 - c);
        const scalar b = w & t;
        const scalar disc = sqr(b) - (magSqr(w) - sqr(rho));
        if (disc >= 0)
        {
            lo = min(lo, -b - Foam::sqrt(disc));
            hi = max(hi, -b + Foam::sqrt(disc));
        }
    }
    cut.chord = max(hi - lo, scalar(0));
    return cut;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleShapes::box::box
(
    const vector& halfExtents,
    const scalar edgeRadius
)
:
    halfExtents_(halfExtents),
    edgeRadius_(edgeRadius)
{}


Foam::particleShapes::box::box(const dictionary& dict)
:
    halfExtents_(dict.get<vector>("halfExtents")),
    edgeRadius_(dict.getOrDefault<scalar>("edgeRadius", 0))
{
    if (cmptMin(halfExtents_) <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "halfExtents " << halfExtents_ << " of particle "
            << dict.dictName() << " must all be positive"
            << exit(FatalIOError);
    }
    if (edgeRadius_ < 0 || edgeRadius_ > cmptMin(halfExtents_))
    {
        FatalIOErrorInFunction(dict)
            << "edgeRadius " << edgeRadius_ << " of particle "
            << dict.dictName() << " must be between 0 and the smallest of"
            << " the (outer) halfExtents " << halfExtents_
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::particleShapes::box::roundedSurfaceCrossing
(
    const vector& r0,
    const vector& e,
    const scalar L
) const
{
    const vector b(innerHalfExtents());
    const scalar r = edgeRadius_;

    // The line's parameter interval [tIn, tOut] inside a piece, narrowed
    // by each slab and circle or sphere of the piece
    scalar tIn, tOut;
    // Within h of the centroid along d
    auto slab = [&](const direction d, const scalar h)
    {
        if (mag(e[d]) > SMALL)
        {
            const scalar t1 = (-h - r0[d])/e[d];
            const scalar t2 = (h - r0[d])/e[d];
            tIn = max(tIn, min(t1, t2));
            tOut = min(tOut, max(t1, t2));
        }
        else if (mag(r0[d]) > h)
        {
            tIn = GREAT;
        }
    };
    // Within r of the centre c in the directions of mask (1 or 0)
    auto ball = [&](const vector& c, const vector& mask)
    {
        const vector w(cmptMultiply(mask, r0 - c));
        const vector f(cmptMultiply(mask, e));
        const scalar a = magSqr(f);
        if (a > SMALL)
        {
            const scalar B = (w & f)/a;
            const scalar disc = sqr(B) - (magSqr(w) - sqr(r))/a;
            if (disc < 0)
            {
                tIn = GREAT;
                return;
            }
            tIn = max(tIn, -B - Foam::sqrt(disc));
            tOut = min(tOut, -B + Foam::sqrt(disc));
        }
        else if (magSqr(w) > sqr(r))
        {
            tIn = GREAT;
        }
    };

    // The earliest entry into any piece the line reaches
    scalar t = GREAT;
    auto enter = [&]()
    {
        if (tIn <= tOut && tOut >= 0)
        {
            t = min(t, max(tIn, scalar(0)));
        }
    };
    for (direction d = 0; d < 3; ++d)
    {
        const direction i = (d + 1) % 3;
        const direction j = (d + 2) % 3;

        // The box reaching the faces normal to d
        tIn = -GREAT;
        tOut = GREAT;
        slab(d, b[d] + r);
        slab(i, b[i]);
        slab(j, b[j]);
        enter();

        // The cylinders along the edges along d
        vector mask(vector::one);
        mask[d] = 0;
        for (const scalar si : {-1.0, 1.0})
        {
            for (const scalar sj : {-1.0, 1.0})
            {
                vector c(Zero);
                c[i] = si*b[i];
                c[j] = sj*b[j];
                tIn = -GREAT;
                tOut = GREAT;
                slab(d, b[d]);
                ball(c, mask);
                enter();
            }
        }
    }
    for (label corner = 0; corner < 8; ++corner)
    {
        const vector c
        (
            cmptMultiply
            (
                b,
                vector
                (
                    corner & 1 ? 1 : -1,
                    corner & 2 ? 1 : -1,
                    corner & 4 ? 1 : -1
                )
            )
        );
        tIn = -GREAT;
        tOut = GREAT;
        ball(c, vector::one);
        enter();
    }
    return min(t, L);
}


void Foam::particleShapes::box::roundedPlaneCut
(
    const vector& n,
    const scalar distance,
    scalar& volume,
    vector& centroid,
    scalar& sectionArea
) const
{
    const vector b(innerHalfExtents());
    const scalar r = edgeRadius_;

    // Slices across the axis k along which n has its least component (so
    // that the plane crosses the slices at 55 degrees or more):
    // at z along k, a rectangle of half extents b_i, b_j grown by rho(z),
    // r over the inner box and shrinking as a circle's chord beyond it,
    // and the plane the line m.(x_i, x_j) = e(z)
    const vector magN(cmptMag(n));
    const direction k =
        magN.x() <= magN.y()
      ? (magN.x() <= magN.z() ? 0 : 2)
      : (magN.y() <= magN.z() ? 1 : 2);
    const direction i = (k + 1) % 3;
    const direction j = (k + 2) % 3;
    const scalar nPerp = Foam::sqrt(sqr(n[i]) + sqr(n[j]));
    const vector2D m(n[i]/nPerp, n[j]/nPerp);
    const scalar bk = b[k];
    const scalar ak = halfExtents_[k];
    auto offset = [&](const scalar z) { return (distance - n[k]*z)/nPerp; };
    auto rho = [&](const scalar z)
    {
        const scalar beyond = max(mag(z) - bk, scalar(0));
        return Foam::sqrt(max(sqr(r) - sqr(beyond), scalar(0)));
    };

    // The part beyond is smooth in z between the positions where the
    // slices start and stop being cut (the line at the slice's support,
    // e(z) = +-(B + rho(z))), where the line crosses a junction of a side
    // and an arc (the curvature of the boundary jumps there) and where the
    // rounding starts. Each is a root of e(z) - C = kappa rho(z).
    const scalar B = b[i]*mag(m.x()) + b[j]*mag(m.y());
    DynamicList<scalar> breaks({-ak, -bk, bk, ak});
    auto addRoots = [&](const scalar C, const scalar kappa)
    {
        // alpha + beta z = kappa rho(z)
        const scalar alpha = distance/nPerp - C;
        const scalar beta = -n[k]/nPerp;
        if (mag(beta) > VSMALL)
        {
            const scalar z = (kappa*r - alpha)/beta;
            if (mag(z) < bk)
            {
                breaks.append(z);
            }
        }
        // Over the rounded ends, z = c + w: (gamma + beta w)^2
        // = kappa^2 (r^2 - w^2), gamma + beta w of kappa's sign
        for (const scalar end : {-1.0, 1.0})
        {
            const scalar c = end*bk;
            const scalar gamma = alpha + beta*c;
            const scalar a2 = sqr(beta) + sqr(kappa);
            const scalar b2 = beta*gamma;
            const scalar disc = sqr(b2) - a2*(sqr(gamma) - sqr(kappa*r));
            if (a2 < VSMALL || disc < 0)
            {
                continue;
            }
            for (const scalar root : {-1.0, 1.0})
            {
                const scalar w = (-b2 + root*Foam::sqrt(disc))/a2;
                if (end*w > 0 && end*w < r && (gamma + beta*w)*kappa >= 0)
                {
                    breaks.append(c + w);
                }
            }
        }
    };
    for (const scalar sign : {-1.0, 1.0})
    {
        addRoots(sign*B, sign);
    }
    for (const scalar si : {-1.0, 1.0})
    {
        for (const scalar sj : {-1.0, 1.0})
        {
            // Junctions (si (b_i + rho), sj b_j) and (si b_i, sj (b_j + rho))
            const scalar C = si*m.x()*b[i] + sj*m.y()*b[j];
            addRoots(C, si*m.x());
            addRoots(C, sj*m.y());
        }
    }
    Foam::sort(breaks);

    static const gaussLegendre rule(16);
    scalar sumV = 0;
    scalar sumChord = 0;
    vector sumM(Zero);
    auto addSlice = [&](const scalar z, const scalar weight)
    {
        const sliceCut cut =
            roundedRectangleCut(b[i], b[j], rho(z), m, offset(z));
        sumV += weight*cut.area;
        sumM[i] += weight*cut.moment.x();
        sumM[j] += weight*cut.moment.y();
        sumM[k] += weight*z*cut.area;
        sumChord += weight*cut.chord;
    };
    // Gauss-Legendre over each interval [u0, u1] of u (z, or the angle
    // over a rounded end); where the slices are cut, in phi, u = uMid
    // + uHalf sin(phi): a slice's chord grows as the square root of the
    // distance from where it starts being cut, which the sine makes smooth
    auto integrate = [&]
    (
        const scalar u0,
        const scalar u1,
        const bool cut,
        const std::function<void(scalar, scalar)>& addAt
    )
    {
        const scalar uMid = 0.5*(u0 + u1);
        const scalar uHalf = 0.5*(u1 - u0);
        forAll(rule.nodes(), g)
        {
            if (cut)
            {
                const scalar phi =
                    constant::mathematical::piByTwo*rule.nodes()[g];
                addAt
                (
                    uMid + uHalf*Foam::sin(phi),
                    constant::mathematical::piByTwo*rule.weights()[g]
                   *uHalf*Foam::cos(phi)
                );
            }
            else
            {
                addAt(uMid + uHalf*rule.nodes()[g], uHalf*rule.weights()[g]);
            }
        }
    };
    for (label p = 0; p + 1 < breaks.size(); ++p)
    {
        const scalar z0 = breaks[p];
        const scalar z1 = breaks[p + 1];
        const scalar zMid = 0.5*(z0 + z1);
        // Nothing beyond, or an empty interval; or whole slices
        const scalar eMid = offset(zMid);
        if (z1 <= z0 || eMid >= B + rho(zMid))
        {
            continue;
        }
        const bool cut = eMid > -B - rho(zMid);
        if (mag(zMid) <= bk)
        {
            integrate(z0, z1, cut, addSlice);
        }
        else
        {
            // Over a rounded end, in the angle theta of z = c + r sin(theta)
            // (rho = r cos(theta), smooth to the tip)
            const scalar c = zMid > 0 ? bk : -bk;
            auto angle = [&](const scalar z)
            {
                return Foam::asin(min(max((z - c)/r, scalar(-1)), scalar(1)));
            };
            integrate
            (
                angle(z0),
                angle(z1),
                cut,
                [&](const scalar theta, const scalar weight)
                {
                    addSlice
                    (
                        c + r*Foam::sin(theta),
                        weight*r*Foam::cos(theta)
                    );
                }
            );
        }
    }

    // Round-off can leave a sliver's volume just below zero
    volume = max(sumV, scalar(0));
    centroid = sumV > 0 ? sumM/sumV : vector::zero;
    sectionArea = sumChord/nPerp;
}


void Foam::particleShapes::box::roundedDrawing
(
    pointField& points,
    faceList& faces
) const
{
    // Grid coordinates along each axis: the outer faces, the rounding
    // (four steps of equal angle over the 45 degrees each face's grid
    // covers) and the inner box's faces (one where the inner box is flat)
    const vector b(innerHalfExtents());
    const scalar r = edgeRadius_;
    const label nSteps = 4;
    List<scalarList> grid(3);
    for (direction d = 0; d < 3; ++d)
    {
        DynamicList<scalar> upper;
        if (b[d] > 0)
        {
            upper.append(b[d]);
        }
        for (label s = 1; s <= nSteps; ++s)
        {
            upper.append
            (
                b[d] + r*Foam::tan(constant::mathematical::pi*s/(4*nSteps))
            );
        }
        DynamicList<scalar> coordinates;
        for (label s = upper.size() - 1; s >= 0; --s)
        {
            coordinates.append(-upper[s]);
        }
        if (b[d] == 0)
        {
            coordinates.append(0);
        }
        coordinates.append(upper);
        grid[d] = coordinates;
    }

    // Points of the grid on the outer box's faces, each moved to the
    // closest point of the surface: the closest point of the inner box
    // plus r along the way out
    const labelVector size(grid[0].size(), grid[1].size(), grid[2].size());
    labelList pointLabel(size.x()*size.y()*size.z(), -1);
    auto index = [&](const labelVector& ijk)
    {
        return ijk.x() + size.x()*(ijk.y() + size.y()*ijk.z());
    };
    DynamicList<point> surfacePoints;
    auto pointAt = [&](const labelVector& ijk)
    {
        label& slot = pointLabel[index(ijk)];
        if (slot < 0)
        {
            const point x(grid[0][ijk.x()], grid[1][ijk.y()], grid[2][ijk.z()]);
            const point inner(max(min(x, b), -b));
            surfacePoints.append(inner + r*normalised(x - inner));
            slot = surfacePoints.size() - 1;
        }
        return slot;
    };

    // Each face's quads, ordered along the two other axes in turn
    // (outward on the upper face, reversed on the lower)
    DynamicList<face> quads;
    for (direction d = 0; d < 3; ++d)
    {
        const direction i = (d + 1) % 3;
        const direction j = (d + 2) % 3;
        for (const label side : {0, 1})
        {
            for (label p = 0; p + 1 < size[i]; ++p)
            {
                for (label q = 0; q + 1 < size[j]; ++q)
                {
                    face quad(4);
                    const label corners[4][2] =
                        {{p, q}, {p + 1, q}, {p + 1, q + 1}, {p, q + 1}};
                    for (label c = 0; c < 4; ++c)
                    {
                        labelVector ijk;
                        ijk[d] = side*(size[d] - 1);
                        ijk[i] = corners[c][0];
                        ijk[j] = corners[c][1];
                        quad[side ? c : 3 - c] = pointAt(ijk);
                    }
                    quads.append(quad);
                }
            }
        }
    }
    points.transfer(surfacePoints);
    faces.transfer(quads);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::particleShapes::box::typeKeywords()
{
    return wordList({"halfExtents", "edgeRadius"});
}


Foam::wordList Foam::particleShapes::box::keywords() const
{
    return typeKeywords();
}


Foam::label Foam::particleShapes::box::nDimensions() const
{
    return 3;
}


Foam::scalar Foam::particleShapes::box::boundingRadius() const
{
    return mag(innerHalfExtents()) + edgeRadius_;
}


Foam::scalar Foam::particleShapes::box::volume() const
{
    if (edgeRadius_ == 0)
    {
        return 8*cmptProduct(halfExtents_);
    }

    // Inner box, six face slabs, four quarter cylinders along each axis
    // (a cylinder of the axis's inner length) and eight sphere octants
    const vector b(innerHalfExtents());
    const scalar r = edgeRadius_;
    return
        8*cmptProduct(b)
      + 8*r*(b.x()*b.y() + b.y()*b.z() + b.z()*b.x())
      + constant::mathematical::twoPi*sqr(r)*cmptSum(b)
      + 4*constant::mathematical::pi*pow3(r)/3;
}


Foam::symmTensor Foam::particleShapes::box::inertiaPerUnitDensity() const
{
    if (edgeRadius_ > 0)
    {
        // Second moments S_d, the integrals of x_d^2, over each piece: for
        // a piece offset by b_d along d, the integral of (b_d + s)^2 over
        // its section or volume, s >= 0 the distance outward (a quarter
        // disk of radius r: area pi r^2/4, moments r^3/3 and pi r^4/16; a
        // sphere octant: volume pi r^3/6, moments pi r^4/16 and pi r^5/30)
        const vector b(innerHalfExtents());
        const scalar r = edgeRadius_;
        const scalar pi = constant::mathematical::pi;
        vector S;
        for (direction d = 0; d < 3; ++d)
        {
            const scalar bd = b[d];
            const scalar others = b[(d + 1) % 3] + b[(d + 2) % 3];
            const scalar across = b[(d + 1) % 3]*b[(d + 2) % 3];
            S[d] =
                // Inner box
                8*cmptProduct(b)*sqr(bd)/3
                // Slabs on the faces normal to d, and on the others
              + 8*across*(pow3(bd + r) - pow3(bd))/3
              + 8*r*pow3(bd)*others/3
                // Quarter cylinders along d, and along the other axes
              + 2*pi*sqr(r)*pow3(bd)/3
              + 8*others*(pi*sqr(r*bd)/4 + 2*bd*pow3(r)/3 + pi*pow4(r)/16)
                // Sphere octants
              + 8*(pi*pow3(r)*sqr(bd)/6 + pi*pow4(r)*bd/8 + pi*pow5(r)/30);
        }
        return symmTensor
        (
            S.y() + S.z(), 0, 0,
            S.x() + S.z(), 0,
            S.x() + S.y()
        );
    }

    const vector h2(cmptMultiply(halfExtents_, halfExtents_));
    const scalar V3 = volume()/3;
    return symmTensor
    (
        V3*(h2.y() + h2.z()), 0, 0,
        V3*(h2.x() + h2.z()), 0,
        V3*(h2.x() + h2.y())
    );
}


Foam::scalar Foam::particleShapes::box::signedDistance
(
    const vector& r,
    vector& normal
) const
{
    const vector sign
    (
        r.x() < 0 ? -1 : 1,
        r.y() < 0 ? -1 : 1,
        r.z() < 0 ? -1 : 1
    );
    // Beyond each pair of the inner box's faces (positive outside them):
    // the distance to the inner box less the rounding radius
    const vector q(cmptMag(r) - innerHalfExtents());
    const vector beyond(max(q, vector::zero));
    const scalar outside = mag(beyond);
    if (outside > 0)
    {
        // Nearest a face, an edge or a corner
        normal = cmptMultiply(sign, beyond)/outside;
        return outside - edgeRadius_;
    }

    // Inside: nearest the face least deep below
    const direction nearest =
        q.x() >= q.y()
      ? (q.x() >= q.z() ? 0 : 2)
      : (q.y() >= q.z() ? 1 : 2);
    normal = Zero;
    normal[nearest] = sign[nearest];
    return q[nearest] - edgeRadius_;
}


Foam::scalar Foam::particleShapes::box::surfaceCrossing
(
    const vector& r0,
    const vector& e,
    const scalar L
) const
{
    if (edgeRadius_ > 0)
    {
        return roundedSurfaceCrossing(r0, e, L);
    }

    // Entering the solid is entering the slabs of all three pairs of faces:
    // the latest of the three entries
    scalar t = 0;
    for (direction d = 0; d < 3; ++d)
    {
        if (mag(e[d]) > SMALL)
        {
            const scalar t1 = (-halfExtents_[d] - r0[d])/e[d];
            const scalar t2 = (halfExtents_[d] - r0[d])/e[d];
            t = max(t, min(t1, t2));
        }
    }
    return min(t, L);
}


Foam::scalar Foam::particleShapes::box::boxFraction
(
    const boundBox& bb,
    const point& X,
    const tensor& R,
    const vector& splitDirections,
    const scalar leafSize
) const
{
    // Axes along the mesh axes: each row of R, a unit vector, then holds a
    // single +-1, and only then do its components' magnitudes sum to 1
    if (edgeRadius_ > 0)
    {
        return particleShape::boxFraction
        (
            bb, X, R, splitDirections, leafSize
        );
    }

    const tensor magR(cmptMag(R));
    const vector rowSums
    (
        magR.xx() + magR.xy() + magR.xz(),
        magR.yx() + magR.yy() + magR.yz(),
        magR.zx() + magR.zy() + magR.zz()
    );
    if (cmptMax(cmptMag(rowSums - vector::one)) > 1e-12)
    {
        return particleShape::boxFraction
        (
            bb, X, R, splitDirections, leafSize
        );
    }

    const vector H(magR & halfExtents_);
    const vector lo(bb.min() - X);
    const vector hi(bb.max() - X);
    scalar fraction = 1;
    for (direction d = 0; d < 3; ++d)
    {
        const scalar overlap = min(hi[d], H[d]) - max(lo[d], -H[d]);
        if (overlap <= 0)
        {
            return 0;
        }
        fraction *= overlap/(hi[d] - lo[d]);
    }
    return fraction;
}


Foam::scalar Foam::particleShapes::box::planeOverlap
(
    const vector& n,
    const scalar distance
) const
{
    if (edgeRadius_ > 0)
    {
        return particleShape::planeOverlap(n, distance);
    }

    // The part beyond the plane is the part below the plane of normal -n
    // at the centroid's distance
    return volume()*cutCellFraction::box(-n, distance, 2*halfExtents_);
}


void Foam::particleShapes::box::drawing
(
    pointField& points,
    faceList& faces
) const
{
    if (edgeRadius_ > 0)
    {
        roundedDrawing(points, faces);
        return;
    }

    // Corner i has the sign pattern of i's bits (x: 1, y: 2, z: 4)
    points.setSize(8);
    forAll(points, i)
    {
        points[i] = cmptMultiply
        (
            halfExtents_,
            vector(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1)
        );
    }
    faces = faceList
    ({
        face{0, 4, 6, 2}, face{1, 3, 7, 5},     // -x, +x
        face{0, 1, 5, 4}, face{2, 6, 7, 3},     // -y, +y
        face{0, 2, 3, 1}, face{4, 5, 7, 6}      // -z, +z
    });
}


Foam::scalar Foam::particleShapes::box::support(const vector& u) const
{
    return cmptSum(cmptMultiply(innerHalfExtents(), cmptMag(u))) + edgeRadius_;
}


bool Foam::particleShapes::box::planeCut
(
    const vector& n,
    const scalar distance,
    scalar& volume,
    vector& centroid,
    scalar& sectionArea
) const
{
    if (edgeRadius_ > 0)
    {
        roundedPlaneCut(n, distance, volume, centroid, sectionArea);
        return true;
    }

    volume = planeOverlap(n, distance);
    centroid = Zero;
    sectionArea = 0;
    if (volume <= 0)
    {
        return true;
    }

    // Each face's part beyond the plane: the centroid of the tetrahedra
    // from a point on the plane, the section from the area vectors
    static const label faceCorners[6][4] =
    {
        {0, 4, 6, 2}, {1, 3, 7, 5},     // -x, +x
        {0, 1, 5, 4}, {2, 6, 7, 3},     // -y, +y
        {0, 2, 3, 1}, {4, 5, 7, 6}      // -z, +z
    };
    FixedList<point, 8> corners;
    forAll(corners, i)
    {
        corners[i] = cmptMultiply
        (
            halfExtents_,
            vector(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1)
        );
    }
    const point apex(distance*n);
    scalar sumV = 0;
    vector moment(Zero);
    vector areaSum(Zero);
    for (const auto& f : faceCorners)
    {
        const FixedList<point, 4> face
        ({
            corners[f[0]], corners[f[1]], corners[f[2]], corners[f[3]]
        });
        addFaceBeyondPlane
        (
            face.cdata(), 4, n, distance, sumV, moment, areaSum
        );
    }
    centroid = cutCentroid(apex, moment, sumV, boundingRadius());
    sectionArea = areaSum & n;
    return true;
}


void Foam::particleShapes::box::supportKinks
(
    DynamicList<vector>& ridgeAxes,
    DynamicList<vector>& cornerDirections
) const
{
    const vector b(innerHalfExtents());
    for (direction d = 0; d < 3; ++d)
    {
        if (b[d] > 0)
        {
            vector axis(Zero);
            axis[d] = 1;
            ridgeAxes.append(axis);
        }
    }
}


void Foam::particleShapes::box::write(Ostream& os) const
{
    os.writeEntry("shape", typeName);
    os.writeEntry("halfExtents", halfExtents_);
    if (edgeRadius_ > 0)
    {
        os.writeEntry("edgeRadius", edgeRadius_);
    }
}


// ************************************************************************* //
