/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "particleShape.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::particleShape> Foam::particleShape::New
(
    const dictionary& dict
)
{
    const word shapeType(dict.get<word>("shape"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(shapeType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "shape",
            shapeType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<particleShape>(cstrIter()(dict));
}


// ************************************************************************* //
