/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "dlmParticle.H"
#include "checkKeywords.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::dlmParticle::motionType>
Foam::dlmParticle::motionTypeNames
({
    { motionType::free, "free" },
    { motionType::fixed, "fixed" },
    { motionType::prescribed, "prescribed" },
});


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::wordList Foam::dlmParticle::keywords()
{
    return wordList
    ({
        "shape", "density", "position", "velocity", "angularVelocity",
        "orientation", "motion", "velocity0", "angularVelocity0", "force",
        "torque", "material", "contactForce", "contactTorque",
        "stepDisplacement", "stepRotation"
    });
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dlmParticle::checkKeywords(const dictionary& dict) const
{
    wordHashSet known(keywords());
    known.insert(shape_->keywords());

    Foam::checkKeywords
    (
        dict,
        known,
        "for particle " + name_ + " (shape " + dict.get<word>("shape") + ")"
    );
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
    stepDisplacement_(dict.getOrDefault<vector>("stepDisplacement", Zero)),
    stepRotation_
    (
        dict.getOrDefault<quaternion>("stepRotation", quaternion::I)
    ),
    coupledMassRatio_(1),
    coupledInertiaRatio_(1),
    steadyFreeSpin_(false)
{
    checkKeywords(dict);

    const symmTensor I(shape_->inertiaPerUnitDensity());
    steadyFreeSpin_ =
        shape_->nDimensions() == 2
     || (
            I.xy() == 0 && I.xz() == 0 && I.yz() == 0
         && I.xx() == I.yy() && I.yy() == I.zz()
        );

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

    // A written state's quaternion is unit to round-off: normalising it
    // again would change its last bits, and a restart would not continue
    // with the orientation the run had
    if (mag(mag(orientation_) - 1) > 1e-14)
    {
        orientation_.normalize();
    }
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
    stepDisplacement_(p.stepDisplacement_),
    stepRotation_(p.stepRotation_),
    coupledMassRatio_(p.coupledMassRatio_),
    coupledInertiaRatio_(p.coupledInertiaRatio_),
    steadyFreeSpin_(p.steadyFreeSpin_)
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

void Foam::dlmParticle::followSource
(
    const dlmParticle& source,
    const vector& offset
)
{
    position_ = source.position_ + offset;
    velocity_ = source.velocity_;
    angularVelocity_ = source.angularVelocity_;
    orientation_ = source.orientation_;
    velocity0_ = source.velocity0_;
    angularVelocity0_ = source.angularVelocity0_;
    force_ = source.force_;
    torque_ = source.torque_;
    contactForce_ = source.contactForce_;
    contactTorque_ = source.contactTorque_;
    stepDisplacement_ = source.stepDisplacement_;
    stepRotation_ = source.stepRotation_;
    coupledMassRatio_ = source.coupledMassRatio_;
    coupledInertiaRatio_ = source.coupledInertiaRatio_;
}


void Foam::dlmParticle::move(const scalar deltaT)
{
    if (motion_ == motionType::fixed)
    {
        return;
    }

    position_ += 0.5*deltaT*(velocity_ + velocity0_);

    rotateFree(orientation_, angularVelocity_, deltaT);

    velocity0_ = velocity_;
    angularVelocity0_ = angularVelocity_;
}


void Foam::dlmParticle::rotateFree
(
    quaternion& q,
    vector& omega,
    const scalar deltaT
) const
{
    if (steadyFreeSpin_)
    {
        const scalar angle = mag(omega)*deltaT;
        if (angle > VSMALL)
        {
            q = quaternion(omega/mag(omega), angle)*q;
            q.normalize();
        }
        return;
    }

    // Body frame: pi0 the angular momentum (per unit density) at the start,
    // w the rotation rate of the step, pi1 = Q^T pi0 at the end, where Q
    // turns by w deltaT. The implicit midpoint rule takes w = I^-1 (pi0 +
    // pi1)/2, found by fixed-point iteration (its contraction is about the
    // step's rotation angle times the inertia's anisotropy). Any rotation
    // about w keeps pi.w, so the energy pi.I^-1 pi/2 stays exactly when w
    // is that midpoint rate; composing Q on the orientation keeps R pi, the
    // angular momentum, exactly.
    const symmTensor& I = shape_->inertiaPerUnitDensity();
    const symmTensor invI(inv(I));
    const vector pi0(I & (q.R().T() & omega));

    auto turn = [deltaT](const vector& w)
    {
        const scalar angle = mag(w)*deltaT;
        return
            angle > VSMALL ? quaternion(w/mag(w), angle) : quaternion::I;
    };

    vector w(invI & pi0);
    vector pi1(pi0);
    const label maxIter = 100;
    label iter = 0;
    for (; iter < maxIter; ++iter)
    {
        pi1 = turn(w).R().T() & pi0;
        const vector wNew(invI & (0.5*(pi0 + pi1)));
        const scalar change = mag(wNew - w);
        w = wNew;
        if (change <= 1e-15*mag(w))
        {
            break;
        }
    }
    if (iter == maxIter)
    {
        FatalErrorInFunction
            << "Particle " << name_ << " turns by " << mag(w)*deltaT
            << " rad in a step of " << deltaT << " s: too far for its"
            << " torque-free rotation to converge. Reduce the time step."
            << exit(FatalError);
    }

    const quaternion Q(turn(w));
    pi1 = Q.R().T() & pi0;
    q = q*Q;
    q.normalize();
    omega = q.R() & (invI & pi1);
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


void Foam::dlmParticle::writeProperties(Ostream& os) const
{
    shape_->write(os);
    os.writeEntry("density", density_);
    os.writeEntry("material", material_);
    os.writeEntry("motion", motionTypeNames[motion_]);
}


void Foam::dlmParticle::write(Ostream& os) const
{
    os.beginBlock(name_);
    writeProperties(os);
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
    os.writeEntry("stepDisplacement", stepDisplacement_);
    os.writeEntry("stepRotation", stepRotation_);
    os.endBlock();
}


// ************************************************************************* //
