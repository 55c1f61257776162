/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
-------------------------------------------------------------------------------
Description
    Tests of the torque-free rotation of particles (dlmParticle::rotateFree,
    the drift of every move and contact sub-step): kinetic energy and
    angular momentum kept to round-off over many turns, second-order
    agreement with the closed-form precession of an axisymmetric body, the
    flip of a body spun about its intermediate axis (and the stability of
    the other two), and the sphere's steady spin.

\*---------------------------------------------------------------------------*/

#include <catch2/catch.hpp>
#include <iomanip>
#include <sstream>

#include "dlmParticle.H"
#include "IStringStream.H"
#include "mathematicalConstants.H"

using namespace Foam;
using constant::mathematical::pi;

namespace
{

dlmParticle makeParticle(const std::string& shape, const vector& omega)
{
    std::ostringstream os;
    os  << std::setprecision(17) << shape
        << " density 1000; position (0 0 0); angularVelocity ("
        << omega.x() << ' ' << omega.y() << ' ' << omega.z() << ");";
    IStringStream is(os.str());
    dictionary dict(is);
    dict.name() = "particleProperties.body";
    return dlmParticle(dict);
}


// Global inertia per unit density and angular momentum, kinetic energy
tensor inertia(const dlmParticle& p, const quaternion& q)
{
    const tensor R(q.R());
    return R & p.shape().inertiaPerUnitDensity() & R.T();
}

vector angularMomentum(const dlmParticle& p, const quaternion& q, const vector& w)
{
    return inertia(p, q) & w;
}

scalar energy(const dlmParticle& p, const quaternion& q, const vector& w)
{
    return 0.5*(w & angularMomentum(p, q, w));
}

} // End anonymous namespace


TEST_CASE("torque-free rotation keeps energy and angular momentum", "[geometry]")
{
    const std::string shapes[] =
    {
        "shape box; halfExtents (0.3 0.2 0.1);",
        "shape ellipsoid; semiAxes (0.1 0.25 0.4);",
        "shape cylinder; radius 0.1; length 0.5;"
    };
    for (const std::string& shape : shapes)
    {
        const dlmParticle p(makeParticle(shape, vector(0.3, 2, 0.5)));
        quaternion q(p.orientation());
        vector w(p.angularVelocity());
        const vector L0(angularMomentum(p, q, w));
        const scalar E0(energy(p, q, w));

        // 200 turns at about 0.03 rad a step
        const scalar deltaT = 0.03/mag(w);
        const label nSteps = label(200*2*pi/0.03);
        scalar maxEnergyError = 0;
        scalar maxMomentumError = 0;
        for (label n = 0; n < nSteps; ++n)
        {
            p.rotateFree(q, w, deltaT);
            maxEnergyError =
                max(maxEnergyError, mag(energy(p, q, w)/E0 - 1));
            maxMomentumError =
                max(maxMomentumError, mag(angularMomentum(p, q, w) - L0)/mag(L0));
        }
        INFO(shape << ": " << nSteps << " steps, largest relative energy"
            " error " << maxEnergyError << ", angular momentum "
            << maxMomentumError);
        CHECK(maxEnergyError < 1e-10);
        CHECK(maxMomentumError < 1e-10);
        // The body did turn: its angular velocity is not what it started as
        CHECK(mag(w - p.angularVelocity()) > 0.1*mag(w));
    }
}


TEST_CASE("an axisymmetric body precesses as the closed form", "[geometry]")
{
    // Body frame: omega_3 stays, (omega_1, omega_2) turns at
    // lambda = (I3 - I1)/I1 omega_3
    const std::string shape("shape cylinder; radius 0.1; length 0.5;");
    const vector w0(0.4, 0, 2);
    const dlmParticle p(makeParticle(shape, w0));
    const symmTensor I(p.shape().inertiaPerUnitDensity());
    const scalar lambda = (I.zz() - I.xx())/I.xx()*w0.z();
    const scalar T = 3;
    const vector exact
    (
        w0.x()*Foam::cos(lambda*T),
        w0.x()*Foam::sin(lambda*T),
        w0.z()
    );

    scalarList errors;
    for (const label nSteps : {400, 800, 1600})
    {
        quaternion q(p.orientation());
        vector w(w0);
        for (label n = 0; n < nSteps; ++n)
        {
            p.rotateFree(q, w, T/nSteps);
        }
        errors.append(mag((q.R().T() & w) - exact)/mag(w0));
    }
    INFO("errors at 400, 800, 1600 steps: " << errors[0] << " " << errors[1]
        << " " << errors[2]);
    CHECK(errors[0] < 1e-3);
    // Second order: each halving of the step divides the error by 4
    CHECK(errors[0]/errors[1] == Approx(4).epsilon(0.05));
    CHECK(errors[1]/errors[2] == Approx(4).epsilon(0.05));
}


TEST_CASE("a body spun about its intermediate axis flips", "[geometry]")
{
    // Semi-axes 0.1, 0.25, 0.4: the inertia is smallest about z, largest
    // about x, intermediate about y. Spun about one axis with a small
    // disturbance, the body keeps that axis along its angular momentum if
    // it is the smallest or the largest; about the intermediate one it
    // turns over, again and again.
    const std::string shape("shape ellipsoid; semiAxes (0.1 0.25 0.4);");
    const scalar spin = 2*pi;
    const scalar disturbance = 1e-3*spin;

    auto alignment = [&](const vector& axis, scalarList& history)
    {
        const vector w0(spin*axis + disturbance*vector::one);
        const dlmParticle p(makeParticle(shape, w0));
        quaternion q(p.orientation());
        vector w(w0);
        const vector L(angularMomentum(p, q, w)/mag(angularMomentum(p, q, w)));
        const scalar deltaT = 1e-3;
        for (label n = 0; n < 20000; ++n)
        {
            p.rotateFree(q, w, deltaT);
            history.append((q.R() & axis) & L);
        }
    };

    scalarList intermediate, smallest, largest;
    alignment(vector(0, 1, 0), intermediate);
    alignment(vector(0, 0, 1), smallest);
    alignment(vector(1, 0, 0), largest);

    // The intermediate axis turns against the angular momentum and back
    label flipped = -1;
    forAll(intermediate, n)
    {
        if (intermediate[n] < -0.99)
        {
            flipped = n;
            break;
        }
    }
    INFO("intermediate axis: first flip at step " << flipped);
    REQUIRE(flipped > 0);
    scalar back = -1;
    for (label n = flipped; n < intermediate.size(); ++n)
    {
        back = max(back, intermediate[n]);
    }
    CHECK(back > 0.99);
    CHECK(min(smallest) > 0.999);
    CHECK(min(largest) > 0.999);
}


TEST_CASE("a sphere spins steadily", "[geometry]")
{
    const vector w0(0.3, 2, 0.5);
    const dlmParticle p(makeParticle("shape sphere; radius 0.1;", w0));
    CHECK(p.steadyFreeSpin());
    quaternion q(p.orientation());
    vector w(w0);
    for (label n = 0; n < 100; ++n)
    {
        p.rotateFree(q, w, 0.01);
    }
    CHECK(w == w0);
    // Turned by |w| t about w: w is fixed by the rotation
    CHECK(mag((q.R() & w0) - w0) < 1e-12);
    CHECK(!makeParticle("shape box; halfExtents (1 2 3);", w0).steadyFreeSpin());
}


// ************************************************************************* //
