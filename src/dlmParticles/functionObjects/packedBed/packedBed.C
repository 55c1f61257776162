/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "packedBed.H"
#include "dlmParticleCloud.H"
#include "volFields.H"
#include "surfaceFields.H"
#include "uniformDimensionedFields.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(packedBed, 0);
    addToRunTimeSelectionTable(functionObject, packedBed, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::functionObjects::packedBed::patchPressure
(
    const label patchi
) const
{
    const volScalarField& p = lookupObject<volScalarField>(pName_);
    const scalarField& magSf = mesh_.magSf().boundaryField()[patchi];
    return
        gSum(magSf*p.boundaryField()[patchi])
       /max(gSum(magSf), VSMALL);
}


Foam::scalar Foam::functionObjects::packedBed::diameter() const
{
    if (diameter_ > 0)
    {
        return diameter_;
    }
    const dlmParticleCloud& cloud =
        lookupObject<dlmParticleCloud>("particles");
    scalar volume = 0;
    label nDims = 3;
    for (label i = 0; i < cloud.nParticles(); ++i)
    {
        volume += cloud.particles()[i].shape().volume();
        nDims = cloud.particles()[i].shape().nDimensions();
    }
    volume /= max(cloud.nParticles(), 1);
    if (nDims == 2)
    {
        return 2*sqrt(volume/constant::mathematical::pi);
    }
    return cbrt(6*volume/constant::mathematical::pi);
}


void Foam::functionObjects::packedBed::findCells()
{
    DynamicList<label> cells;
    const vectorField& C = mesh_.C();
    forAll(C, celli)
    {
        if (box_.contains(C[celli]))
        {
            cells.append(celli);
        }
    }
    cells_.transfer(cells);
    cellsFound_ = true;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::packedBed::packedBed
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, dict),
    direction_(Zero),
    box_(mesh_.bounds()),
    pName_("p_rgh"),
    diameter_(0),
    cellsFound_(false)
{
    read(dict);

    writeHeader(file(), "Flow through a bed of particles");
    writeHeaderValue(file(), "direction", direction_);
    writeHeaderValue(file(), "box", box_);
    writeHeaderValue(file(), "diameter", diameter());
    writeCommented
    (
        file(),
        "u: superficial velocity; eps: porosity; G: pressure gradient"
        " (drag: from the particles' drag; patches: from the pressure drop);"
        " Lambda = G eps^3 D^2/((1 - eps)^2 mu u);"
        " F/Fs: drag per particle over 3 pi mu D u"
    );
    file() << nl;
    writeCommented(file(), "Time");
    for
    (
        const char* column :
        {
            "u", "eps", "G_drag", "G_patches", "Re", "Lambda",
            "Lambda_Ergun", "dragPerParticle", "F/Fs"
        }
    )
    {
        writeTabbed(file(), column);
    }
    file() << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::packedBed::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);

    direction_ = dict.get<vector>("direction");
    if (mag(direction_) < VSMALL)
    {
        FatalIOErrorInFunction(dict)
            << "direction " << direction_ << " must not be zero"
            << exit(FatalIOError);
    }
    direction_.normalise();

    box_ = mesh_.bounds();
    if (dict.found("box"))
    {
        ITstream& is = dict.lookup("box");
        point lo, hi;
        is >> lo >> hi;
        if (lo.x() >= hi.x() || lo.y() >= hi.y() || lo.z() >= hi.z())
        {
            FatalIOErrorInFunction(dict)
                << "box " << lo << ' ' << hi << ": the first corner must be"
                << " below the second in every direction"
                << exit(FatalIOError);
        }
        box_ = boundBox(lo, hi);
    }

    patches_.clear();
    wordList patchNames;
    if (dict.readIfPresent("patches", patchNames))
    {
        if (patchNames.size() != 2)
        {
            FatalIOErrorInFunction(dict)
                << "patches " << patchNames << ": give two, the upstream and"
                << " the downstream patch" << exit(FatalIOError);
        }
        patches_.setSize(2);
        forAll(patchNames, k)
        {
            patches_[k] = mesh_.boundaryMesh().findPatchID(patchNames[k]);
            if (patches_[k] < 0)
            {
                FatalIOErrorInFunction(dict)
                    << "patches: no patch " << patchNames[k] << ". Patches: "
                    << flatOutput(mesh_.boundaryMesh().names())
                    << exit(FatalIOError);
            }
        }
    }
    pName_ = dict.getOrDefault<word>("p", "p_rgh");

    diameter_ = dict.getOrDefault<scalar>("diameter", 0);
    if (dict.found("diameter") && diameter_ <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "diameter " << diameter_ << " must be positive"
            << exit(FatalIOError);
    }

    findCells();

    return true;
}


void Foam::functionObjects::packedBed::updateMesh(const mapPolyMesh&)
{
    // Called before the mesh has its new cell centres: found at the next
    // write
    cellsFound_ = false;
}


bool Foam::functionObjects::packedBed::execute()
{
    return true;
}


bool Foam::functionObjects::packedBed::write()
{
    if (!cellsFound_)
    {
        findCells();
    }
    const dlmParticleCloud& cloud =
        lookupObject<dlmParticleCloud>("particles");
    const volVectorField& U = lookupObject<volVectorField>("U");
    const scalarField& alpha = cloud.alpha();
    const scalarField& V = mesh_.V();

    scalar volume = 0;
    scalar solidVolume = 0;
    scalar flux = 0;
    for (const label celli : cells_)
    {
        volume += V[celli];
        solidVolume += alpha[celli]*V[celli];
        flux += (U[celli] & direction_)*V[celli];
    }
    reduce(volume, sumOp<scalar>());
    reduce(solidVolume, sumOp<scalar>());
    reduce(flux, sumOp<scalar>());

    const scalar eps = 1 - solidVolume/volume;
    const scalar u = flux/volume;

    // Drag: the hydrodynamic force less the fluid's hydrostatic buoyancy
    const scalar rhoFluid = cloud.rhoFluid().value();
    const vector g
    (
        time_.foundObject<uniformDimensionedVectorField>("g")
      ? time_.lookupObject<uniformDimensionedVectorField>("g").value()
      : vector::zero
    );
    scalar drag = 0;
    label nBed = 0;
    for (label i = 0; i < cloud.nParticles(); ++i)
    {
        const dlmParticle& p = cloud.particles()[i];
        if (box_.contains(p.position()))
        {
            drag +=
                (p.force() + rhoFluid*p.shape().volume()*g) & direction_;
            ++nBed;
        }
    }

    const scalar gradDrag = drag/volume;
    scalar gradPatches = 0;
    if (patches_.size())
    {
        const scalar length = box_.span() & cmptMag(direction_);
        gradPatches =
            (patchPressure(patches_[0]) - patchPressure(patches_[1]))/length;
    }

    const dictionary& transport =
        mesh_.lookupObject<IOdictionary>("transportProperties");
    const scalar mu = rhoFluid*transport.get<dimensionedScalar>("nu").value();
    const scalar D = diameter();
    const scalar G = patches_.size() ? gradPatches : gradDrag;
    // Undefined without particles or flow (a bed starting at rest): 0
    const bool defined = eps < 1 && mag(u) > 0;
    const scalar Re = defined ? rhoFluid*D*u/(mu*(1 - eps)) : 0;
    const scalar Lambda =
        defined ? G*pow3(eps)*sqr(D)/(sqr(1 - eps)*mu*u) : 0;
    const scalar LambdaErgun = 150 + 1.75*Re;
    const scalar dragPerParticle = drag/max(nBed, 1);
    const scalar stokesDrag = 3*constant::mathematical::pi*mu*D*u;
    const scalar dragRatio = defined ? dragPerParticle/stokesDrag : 0;

    if (Pstream::master())
    {
        writeCurrentTime(file());
        for
        (
            const scalar value :
            {
                u, eps, gradDrag, gradPatches, Re, Lambda, LambdaErgun,
                dragPerParticle, dragRatio
            }
        )
        {
            file() << tab << value;
        }
        file() << endl;
    }

    Log << type() << ' ' << name() << ": u = " << u << ", eps = " << eps
        << ", pressure gradient " << G << " (drag " << gradDrag << ")"
        << ", Re = " << Re << ", Lambda = " << Lambda << " (Ergun "
        << LambdaErgun << ")" << nl << endl;

    return true;
}


// ************************************************************************* //
