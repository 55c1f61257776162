/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "contactLaw.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(contactLaw, 0);
    defineRunTimeSelectionTable(contactLaw, dictionary);
}

const Foam::Enum<Foam::contactLaw::tangentialType>
Foam::contactLaw::tangentialTypeNames
({
    { tangentialType::coulomb, "coulomb" },
    { tangentialType::spring, "spring" },
});

const Foam::Enum<Foam::contactLaw::frictionLimitType>
Foam::contactLaw::frictionLimitTypeNames
({
    { frictionLimitType::total, "total" },
    { frictionLimitType::spring, "spring" },
});


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

void Foam::contactLaw::collide
(
    const scalar n,
    const scalar beta,
    const bool clip,
    scalar& restitution,
    scalar& contactTime
)
{
    // Clipped at zero, the contact ends when the force would pull
    auto acceleration = [n, beta, clip](const scalar x, const scalar v)
    {
        const scalar xp = max(x, scalar(0));
        const scalar a = -pow(xp, n) - beta*sqrt(n*pow(xp, n - 1))*v;
        return clip ? min(a, scalar(0)) : a;
    };

    const scalar h = 1e-4;
    scalar x = 0;
    scalar v = 1;
    scalar t = 0;
    while (t < 1e3)
    {
        const scalar k1x = v;
        const scalar k1v = acceleration(x, v);
        const scalar k2x = v + 0.5*h*k1v;
        const scalar k2v = acceleration(x + 0.5*h*k1x, k2x);
        const scalar k3x = v + 0.5*h*k2v;
        const scalar k3v = acceleration(x + 0.5*h*k2x, k3x);
        const scalar k4x = v + h*k3v;
        const scalar k4v = acceleration(x + h*k3x, k4x);

        const scalar x1 = x + h*(k1x + 2*k2x + 2*k3x + k4x)/6;
        const scalar v1 = v + h*(k1v + 2*k2v + 2*k3v + k4v)/6;

        if (x1 <= 0)
        {
            // Back at zero overlap within this step
            const scalar s = x/(x - x1);
            restitution = -(v + s*(v1 - v));
            contactTime = t + s*h;
            return;
        }
        if (clip && v1 < 0 && acceleration(x1, v1) == 0)
        {
            // Force released while separating: the contact ends here
            restitution = -v1;
            contactTime = t + h;
            return;
        }
        x = x1;
        v = v1;
        t += h;
    }

    restitution = 0;
    contactTime = t;
}


void Foam::contactLaw::initialise(const reference& ref)
{
    beta_ = dampingFor(exponent(), restitution_, clip_);
    if (beta_ < 0)
    {
        FatalIOErrorInFunction(dict_)
            << "restitution " << restitution_ << " of contact pair "
            << dict_.dictName() << " is below the smallest this law reaches"
            << " (the normal force never pulls): use a larger value"
            << exit(FatalIOError);
    }
    scalar e;
    collide(exponent(), beta_, clip_, e, tau_);

    const bool linear = exponent() == 1;
    if (dict_.found("stiffness") == dict_.found("contactTime"))
    {
        FatalIOErrorInFunction(dict_)
            << "Contact pair " << dict_.dictName() << " (law "
            << dict_.get<word>("law") << ") needs either 'stiffness' or"
            << " 'contactTime'" << (linear ? "" : " with 'impactVelocity'")
            << exit(FatalIOError);
    }
    if (dict_.found("stiffness"))
    {
        stiffness_ = dict_.get<scalar>("stiffness");
    }
    else
    {
        // The collision of the reference contact at speed v lasts
        // tau delta0/v, with K delta0^(n+1) = m v^2 (for the linear law
        // tau sqrt(m/K), whatever v)
        const scalar time = dict_.get<scalar>("contactTime");
        const scalar v = linear ? 1 : dict_.get<scalar>("impactVelocity");
        if (time <= 0 || v <= 0)
        {
            FatalIOErrorInFunction(dict_)
                << "contactTime" << (linear ? "" : " and impactVelocity")
                << " of contact pair " << dict_.dictName()
                << " must be positive" << exit(FatalIOError);
        }
        stiffness_ =
            ref.mass*sqr(v)/pow(time*v/tau_, exponent() + 1)
           /geometryFactor(ref.radius);
    }
    if (stiffness_ <= 0)
    {
        FatalIOErrorInFunction(dict_)
            << "stiffness " << stiffness_ << " of contact pair "
            << dict_.dictName() << " must be positive" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactLaw::contactLaw
(
    const dictionary& dict,
    const label nDimensions
)
:
    dict_(dict),
    nDimensions_(nDimensions),
    restitution_(dict.get<scalar>("restitution")),
    friction_(dict.get<scalar>("friction")),
    rollingFriction_(dict.getOrDefault<scalar>("rollingFriction", 0)),
    twistingFriction_(dict.getOrDefault<bool>("twistingFriction", true)),
    tangential_
    (
        tangentialTypeNames.getOrDefault
        (
            "tangential",
            dict,
            tangentialType::spring
        )
    ),
    frictionLimit_
    (
        frictionLimitTypeNames.getOrDefault
        (
            "frictionLimit",
            dict,
            frictionLimitType::total
        )
    ),
    tangentialStiffnessRatio_
    (
        dict.getOrDefault<scalar>("tangentialStiffnessRatio", 2.0/7.0)
    ),
    tangentialDampingRatio_
    (
        dict.getOrDefault<scalar>("tangentialDampingRatio", 1)
    ),
    clip_(dict.getOrDefault<bool>("clipNormalForce", true)),
    beta_(0),
    tau_(0),
    stiffness_(1)
{
    if (restitution_ <= 0 || restitution_ > 1)
    {
        FatalIOErrorInFunction(dict)
            << "restitution " << restitution_ << " of contact pair "
            << dict.dictName() << " must be in (0, 1]" << exit(FatalIOError);
    }
    if (friction_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "friction " << friction_ << " of contact pair "
            << dict.dictName() << " must not be negative"
            << exit(FatalIOError);
    }
    if (rollingFriction_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "rollingFriction " << rollingFriction_ << " of contact pair "
            << dict.dictName() << " must not be negative"
            << exit(FatalIOError);
    }
    if (tangentialStiffnessRatio_ <= 0 || tangentialDampingRatio_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "tangentialStiffnessRatio must be positive and"
            << " tangentialDampingRatio not negative (contact pair "
            << dict.dictName() << ")" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::contactLaw::typeKeywords()
{
    return wordList
    ({
        "materials", "law", "restitution", "friction", "tangential",
        "frictionLimit", "tangentialStiffnessRatio", "tangentialDampingRatio",
        "clipNormalForce", "stiffness", "contactTime", "rollingFriction",
        "twistingFriction"
    });
}


Foam::wordList Foam::contactLaw::keywords() const
{
    return typeKeywords();
}


Foam::scalar Foam::contactLaw::normalForce
(
    const scalar V,
    const scalar delta,
    const scalar radius,
    const scalar mass,
    const scalar approachSpeed,
    scalar& stiffness,
    scalar& damping,
    const scalar volumeExponent
) const
{
    scalar force;
    elastic(V, delta, radius, force, stiffness);
    const scalar n =
        volumeExponent > 0 ? forceExponent(volumeExponent) : exponent();
    damping = (n == exponent() ? beta_ : dampingAt(n))*sqrt(mass*stiffness);
    const scalar Fn = force + damping*approachSpeed;
    return clip_ ? max(Fn, scalar(0)) : Fn;
}


Foam::scalar Foam::contactLaw::dampingAt(const scalar n) const
{
    const scalar first = 1;
    const scalar spacing = 0.25;
    if (betaTable_.empty())
    {
        betaTable_.setSize(9);
        forAll(betaTable_, k)
        {
            betaTable_[k] =
                max(dampingFor(first + spacing*k, restitution_, clip_), 0);
        }
    }
    const scalar x =
        min(max((n - first)/spacing, scalar(0)), scalar(betaTable_.size() - 1));
    const label k = min(label(x), betaTable_.size() - 2);
    const scalar s = x - k;
    return (1 - s)*betaTable_[k] + s*betaTable_[k + 1];
}


Foam::scalar Foam::contactLaw::contactTime
(
    const scalar radius,
    const scalar mass,
    const scalar v
) const
{
    const scalar n = exponent();
    const scalar delta0 =
        pow(mass*sqr(v)/leadingCoefficient(radius), 1/(n + 1));
    return tau_*delta0/v;
}


Foam::scalar Foam::contactLaw::restitution
(
    const scalar n,
    const scalar beta,
    const bool clip
)
{
    scalar e, tau;
    collide(n, beta, clip, e, tau);
    return e;
}


Foam::scalar Foam::contactLaw::dampingFor
(
    const scalar n,
    const scalar e,
    const bool clip
)
{
    if (e >= 1)
    {
        return 0;
    }

    // Restitution falls as beta grows: bracket, then close the bracket by
    // regula falsi with the Illinois halving (each collision costs 3e4
    // steps: bisection's 35 of them took seconds at a law's start)
    scalar lower = 0;
    scalar upper = 1;
    scalar fLower = 1 - e;
    scalar fUpper = restitution(n, upper, clip) - e;
    while (fUpper > 0)
    {
        lower = upper;
        fLower = fUpper;
        upper *= 2;
        if (upper > 1e3)
        {
            return -1;
        }
        fUpper = restitution(n, upper, clip) - e;
    }
    label side = 0;
    for (label iter = 0; iter < 100 && upper - lower > 1e-10*upper; ++iter)
    {
        const scalar mid =
            fLower == fUpper
          ? 0.5*(lower + upper)
          : upper - fUpper*(upper - lower)/(fUpper - fLower);
        const scalar fMid = restitution(n, mid, clip) - e;
        if (fMid == 0)
        {
            return mid;
        }
        if (fMid > 0)
        {
            lower = mid;
            fLower = fMid;
            if (side == 1)
            {
                fUpper *= 0.5;
            }
            side = 1;
        }
        else
        {
            upper = mid;
            fUpper = fMid;
            if (side == -1)
            {
                fLower *= 0.5;
            }
            side = -1;
        }
    }
    return 0.5*(lower + upper);
}


// ************************************************************************* //
