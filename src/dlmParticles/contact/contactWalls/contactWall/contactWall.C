/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "contactWall.H"
#include "HashSet.H"
#include "FlatOutput.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(contactWall, 0);
    defineRunTimeSelectionTable(contactWall, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactWall::contactWall(const dictionary& dict, const bool meshWall)
:
    name_(dict.dictName()),
    material_(dict.getOrDefault<word>("material", "wall")),
    lubricated_(dict.getOrDefault<bool>("lubrication", meshWall))
{}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::contactWall> Foam::contactWall::New
(
    const dictionary& dict,
    const polyMesh& mesh
)
{
    const word wallType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(wallType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "type",
            wallType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    autoPtr<contactWall> wall(cstrIter()(dict, mesh));

    const wordHashSet known(wall->keywords());
    for (const entry& e : dict)
    {
        if (!known.found(e.keyword()))
        {
            FatalIOErrorInFunction(dict)
                << "Unknown keyword '" << e.keyword() << "' for wall "
                << dict.dictName() << " (type " << wallType << "). Known"
                << " keywords: " << flatOutput(known.sortedToc())
                << exit(FatalIOError);
        }
    }

    return wall;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::contactWall::nearest
(
    const point& X,
    point& location,
    vector& normal,
    scalar& distance
) const
{
    NotImplemented;
}


void Foam::contactWall::near
(
    const point& X,
    const scalar reach,
    DynamicList<label>& features
) const
{
    point location;
    vector normal;
    scalar distance;
    nearest(X, location, normal, distance);
    if (distance < reach)
    {
        features.append(0);
    }
}


void Foam::contactWall::contacts
(
    const point& X,
    const scalar R,
    const labelUList& features,
    DynamicList<wallContact>& found
) const
{
    wallContact c;
    nearest(X, c.location, c.normal, c.distance);
    if (c.distance < R)
    {
        c.feature = 0;
        found.append(c);
    }
}


Foam::wordList Foam::contactWall::keywords() const
{
    return wordList({"type", "material", "lubrication"});
}


// ************************************************************************* //
