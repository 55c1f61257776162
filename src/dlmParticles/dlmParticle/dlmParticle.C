/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "dlmParticle.H"
#include "HashSet.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::dlmParticle::motionType>
Foam::dlmParticle::motionTypeNames
({
    { motionType::free, "free" },
    { motionType::fixed, "fixed" },
    { motionType::prescribed, "prescribed" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dlmParticle::checkKeywords(const dictionary& dict) const
{
    wordHashSet known
    ({
        "shape", "density", "position", "velocity", "angularVelocity",
        "orientation", "motion", "velocity0", "angularVelocity0", "force",
        "torque", "material", "contactForce", "contactTorque"
    });
    known.insert(shape_->keywords());

    for (const entry& e : dict)
    {
        if (!known.found(e.keyword()))
        {
            FatalIOErrorInFunction(dict)
                << "Unknown keyword '" << e.keyword() << "' for particle "
                << name_ << " (shape " << dict.get<word>("shape") << ")."
                << nl << "Known keywords: " << flatOutput(known.sortedToc())
                << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dlmParticle::dlmParticle(const dictionary& dict)
:
    name_(dict.dictName()),
    shape_(particleShape::New(dict)),
    material_(dict.getOrDefault<word>("material", "particle")),
    density_(dict.get<scalar>("density")),
    motion_
    (
        motionTypeNames.getOrDefault("motion", dict, motionType::free)
    ),
    position_(dict.get<point>("position")),
    velocity_(dict.getOrDefault<vector>("velocity", Zero)),
    angularVelocity_(dict.getOrDefault<vector>("angularVelocity", Zero)),
    orientation_(dict.getOrDefault<quaternion>("orientation", quaternion::I)),
    velocity0_(dict.getOrDefault<vector>("velocity0", velocity_)),
    angularVelocity0_
    (
        dict.getOrDefault<vector>("angularVelocity0", angularVelocity_)
    ),
    force_(dict.getOrDefault<vector>("force", Zero)),
    torque_(dict.getOrDefault<vector>("torque", Zero)),
    contactForce_(dict.getOrDefault<vector>("contactForce", Zero)),
    contactTorque_(dict.getOrDefault<vector>("contactTorque", Zero)),
    coupledMassRatio_(1),
    coupledInertiaRatio_(1)
{
    checkKeywords(dict);

    if (density_ <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "density " << density_ << " of particle " << name_
            << " must be positive" << exit(FatalIOError);
    }

    // Without either, a prescribed particle would silently stay at rest
    if
    (
        motion_ == motionType::prescribed
     && !dict.found("velocity")
     && !dict.found("angularVelocity")
    )
    {
        FatalIOErrorInFunction(dict)
            << "Particle " << name_ << " has motion prescribed but neither"
            << " 'velocity' nor 'angularVelocity': a prescribed particle"
            << " moves with the velocity and angular velocity it is given."
            << nl << "Give either or both, or use motion fixed for a"
            << " particle held at rest." << exit(FatalIOError);
    }

    if (mag(orientation_) < VSMALL)
    {
        FatalIOErrorInFunction(dict)
            << "orientation " << orientation_ << " of particle " << name_
            << " is the zero quaternion, which is no rotation." << nl
            << "Give a non-zero quaternion (w (x y z)), normalised on"
            << " reading: (1 (0 0 0)) for none, (0.7071 (0 0 0.7071)) for"
            << " 90 degrees about z." << exit(FatalIOError);
    }

    if (motion_ == motionType::fixed)
    {
        velocity_ = Zero;
        angularVelocity_ = Zero;
        velocity0_ = Zero;
        angularVelocity0_ = Zero;
    }

    orientation_.normalize();
}


Foam::dlmParticle::dlmParticle(const dlmParticle& p)
:
    name_(p.name_),
    shape_(p.shape_->clone()),
    material_(p.material_),
    density_(p.density_),
    motion_(p.motion_),
    position_(p.position_),
    velocity_(p.velocity_),
    angularVelocity_(p.angularVelocity_),
    orientation_(p.orientation_),
    velocity0_(p.velocity0_),
    angularVelocity0_(p.angularVelocity0_),
    force_(p.force_),
    torque_(p.torque_),
    contactForce_(p.contactForce_),
    contactTorque_(p.contactTorque_),
    coupledMassRatio_(p.coupledMassRatio_),
    coupledInertiaRatio_(p.coupledInertiaRatio_)
{}


Foam::dlmParticle::dlmParticle
(
    const dlmParticle& p,
    const word& name,
    const point& X
)
:
    dlmParticle(p)
{
    name_ = name;
    position_ = X;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dlmParticle::move(const scalar deltaT)
{
    if (motion_ == motionType::fixed)
    {
        return;
    }

    position_ += 0.5*deltaT*(velocity_ + velocity0_);

    const scalar angle = mag(angularVelocity_)*deltaT;
    if (angle > VSMALL)
    {
        orientation_ =
            quaternion(angularVelocity_/mag(angularVelocity_), angle)
           *orientation_;
        orientation_.normalize();
    }

    velocity0_ = velocity_;
    angularVelocity0_ = angularVelocity_;
}


void Foam::dlmParticle::setMotion
(
    const point& X,
    const vector& U,
    const vector& omega,
    const quaternion& q
)
{
    position_ = X;
    velocity_ = U;
    angularVelocity_ = omega;
    orientation_ = q;
    velocity0_ = U;
    angularVelocity0_ = omega;
}


void Foam::dlmParticle::write(Ostream& os) const
{
    os.beginBlock(name_);
    shape_->write(os);
    os.writeEntry("density", density_);
    os.writeEntry("material", material_);
    os.writeEntry("motion", motionTypeNames[motion_]);
    os.writeEntry("position", position_);
    os.writeEntry("velocity", velocity_);
    os.writeEntry("angularVelocity", angularVelocity_);
    os.writeEntry("orientation", orientation_);
    os.writeEntry("velocity0", velocity0_);
    os.writeEntry("angularVelocity0", angularVelocity0_);
    os.writeEntry("force", force_);
    os.writeEntry("torque", torque_);
    os.writeEntry("contactForce", contactForce_);
    os.writeEntry("contactTorque", contactTorque_);
    os.endBlock();
}


// ************************************************************************* //
