/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
-------------------------------------------------------------------------------
Application
    dlmKeywords

Group
    grpMiscellaneousUtilities

Description
    Lists the keywords the project's dictionaries accept, from the lists
    the code checks them against (Foam::checkKeywords): a particle's, the
    contact settings', a contact pair's for each law, a wall's, an outlet's
    and a refinement target's for each type, a particle shape's for each
    shape, the refinement coefficients' with targets and the packing
    utilities'. It also lists the types of each run-time selectable family.
    The user guide's keyword reference (doc/reference) is compared with
    this output by tests/test_documentation.py, which reads the few lists
    this utility cannot reach (constant/particleProperties' top level, the
    rigidProjection fvOption's, the packedBed function object's, the
    solver's controlDict and PIMPLE entries) from the sources.

    Each family's types are those of its run-time selection table: a type
    added to the library without its keywords here stops the utility with
    an error, and one listed here that the library lacks too.

Usage
    \b dlmKeywords

    Output, one line each, keywords and types in alphabetical order:
    \verbatim
    keywords <dictionary> <keyword> ...
    types <family> <type> ...
    \endverbatim
    where a type's dictionary is <family>/<type> (e.g. shape/sphere,
    wall/cone). Families: shape (a particle's 'shape'), pair (a contact
    pair's 'law'; 'law none' is the dictionary pair/none), wall, outlet,
    target (refinement targets), overlap (the contact settings' 'overlap')
    and mixedCells (the rigid projection's 'mixedCells').

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "HashSet.H"
#include "HashTable.H"
#include "FlatOutput.H"

#include "dlmParticle.H"
#include "sphere.H"
#include "disk.H"
#include "ellipse.H"
#include "ellipsoid.H"
#include "polygon.H"
#include "solidCylinder.H"
#include "box.H"
#include "triSurfaceShape.H"

#include "particleContact.H"
#include "overlapMethod.H"
#include "overlapVolume.H"
#include "linearSpringDashpot.H"
#include "plane.H"
#include "cylinder.H"
#include "cone.H"
#include "surface.H"
#include "patches.H"

#include "planeOutlet.H"
#include "boxOutlet.H"

#include "mixedCellTreatment.H"

#include "dlmRefineFvMesh.H"
#include "particleSurface.H"
#include "vorticity.H"
#include "particleGap.H"

#include "packIntoFile.H"
#include "randomSpherePacking.H"
#include "randomShapeInsertion.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- A type's keywords
typedef wordList (*keywordsFunction)();


//- One line: the dictionary and its keywords in alphabetical order
void printKeywords(const std::string& name, const wordList& keywords)
{
    Info<< "keywords " << name.c_str();
    for (const word& key : wordHashSet(keywords).sortedToc())
    {
        Info<< ' ' << key;
    }
    Info<< nl;
}


//- The types of a family's run-time selection table, in alphabetical order
template<class Table>
wordList selectable(const Table* table)
{
    return table ? table->sortedToc() : wordList();
}


//- One line with the family's types
void printTypes(const word& family, const wordList& types)
{
    Info<< "types " << family;
    for (const word& type : types)
    {
        Info<< ' ' << type;
    }
    Info<< nl;
}


//- The family's types and, for each, a line of its keywords; the types
//  listed here must be those of its run-time selection table
void printFamily
(
    const word& family,
    const wordList& types,
    const HashTable<keywordsFunction>& functions
)
{
    for (const word& type : types)
    {
        if (!functions.found(type))
        {
            FatalErrorInFunction
                << "The " << family << " type " << type << " has no keywords"
                << " in dlmKeywords: add its typeKeywords to the "
                << family << " family in dlmKeywords.C" << exit(FatalError);
        }
    }
    const wordHashSet known(types);
    for (const word& type : functions.sortedToc())
    {
        if (!known.found(type))
        {
            FatalErrorInFunction
                << "dlmKeywords lists the " << family << " type " << type
                << ", which the library does not select. Its types: "
                << flatOutput(types) << exit(FatalError);
        }
    }

    printTypes(family, types);
    for (const word& type : types)
    {
        printKeywords
        (
            static_cast<const std::string&>(family) + "/" + type,
            functions[type]()
        );
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "The keywords the project's dictionaries accept, as the code checks"
        " them, and the types of each run-time selectable family"
    );
    argList::noParallel();
    argList::noBanner();

    argList args(argc, argv, true, true, false);

    // constant/particleProperties: a particle, its shape
    printKeywords("particle", dlmParticle::keywords());
    printFamily
    (
        "shape",
        selectable(particleShape::dictionaryConstructorTablePtr_),
        {
            {
                particleShapes::sphere::typeName,
                particleShapes::sphere::typeKeywords
            },
            {
                particleShapes::disk::typeName,
                particleShapes::disk::typeKeywords
            },
            {
                particleShapes::ellipse::typeName,
                particleShapes::ellipse::typeKeywords
            },
            {
                particleShapes::ellipsoid::typeName,
                particleShapes::ellipsoid::typeKeywords
            },
            {
                particleShapes::polygon::typeName,
                particleShapes::polygon::typeKeywords
            },
            {
                particleShapes::solidCylinder::typeName,
                particleShapes::solidCylinder::typeKeywords
            },
            {
                particleShapes::box::typeName,
                particleShapes::box::typeKeywords
            },
            {
                particleShapes::triSurfaceShape::typeName,
                particleShapes::triSurfaceShape::typeKeywords
            }
        }
    );

    // The contact settings, their pairs and walls
    printKeywords("contact", particleContact::keywords());
    printKeywords("contact/lubrication", particleContact::lubricationKeywords());
    printTypes
    (
        "overlap",
        selectable(overlapMethod::dictionaryConstructorTablePtr_)
    );
    printKeywords("pair/none", particleContact::noLawKeywords());
    printFamily
    (
        "pair",
        selectable(contactLaw::dictionaryConstructorTablePtr_),
        {
            {
                contactLaws::overlapVolume::typeName,
                contactLaws::overlapVolume::typeKeywords
            },
            {
                contactLaws::linearSpringDashpot::typeName,
                contactLaws::linearSpringDashpot::typeKeywords
            }
        }
    );
    printFamily
    (
        "wall",
        selectable(contactWall::dictionaryConstructorTablePtr_),
        {
            {
                contactWalls::plane::typeName,
                contactWalls::plane::typeKeywords
            },
            {
                contactWalls::cylinder::typeName,
                contactWalls::cylinder::typeKeywords
            },
            {
                contactWalls::cone::typeName,
                contactWalls::cone::typeKeywords
            },
            {
                contactWalls::surface::typeName,
                contactWalls::surface::typeKeywords
            },
            {
                contactWalls::patches::typeName,
                contactWalls::patches::typeKeywords
            }
        }
    );

    // The outlets
    printFamily
    (
        "outlet",
        selectable(particleOutlet::dictionaryConstructorTablePtr_),
        {
            {
                particleOutlets::planeOutlet::typeName,
                particleOutlets::planeOutlet::typeKeywords
            },
            {
                particleOutlets::boxOutlet::typeName,
                particleOutlets::boxOutlet::typeKeywords
            }
        }
    );

    // system/fvOptions: the rigid projection's treatments of the cut cells
    printTypes
    (
        "mixedCells",
        selectable(fv::mixedCellTreatment::dictionaryConstructorTablePtr_)
    );

    // constant/dynamicMeshDict: the coefficients with targets, the targets
    printKeywords
    (
        "dynamicMeshDict/dlmRefineFvMesh",
        dlmRefineFvMesh::targetsCoeffsKeywords()
    );
    printFamily
    (
        "target",
        selectable(refinementTarget::dictionaryConstructorTablePtr_),
        {
            {
                refinementTargets::particleSurface::typeName,
                refinementTargets::particleSurface::typeKeywords
            },
            {
                refinementTargets::vorticity::typeName,
                refinementTargets::vorticity::typeKeywords
            },
            {
                refinementTargets::particleGap::typeName,
                refinementTargets::particleGap::typeKeywords
            }
        }
    );

    // The packing utilities' dictionaries
    printKeywords
    (
        "packSpheresDict",
        packIntoFileKeywords<randomSpherePacking>()
    );
    printKeywords
    (
        "packParticlesDict",
        packIntoFileKeywords<randomShapeInsertion>()
    );
    printKeywords
    (
        "packParticlesDict/group",
        randomShapeInsertion::groupKeywords
    );

    return 0;
}


// ************************************************************************* //
