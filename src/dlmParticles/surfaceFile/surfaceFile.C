/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "surfaceFile.H"
#include "argList.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * * * Functions  * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::triSurface> Foam::surfaceFile::read
(
    const dictionary& dict,
    const fileName& directory,
    const string& owner
)
{
    fileName file(dict.get<fileName>("file"));
    file.expand();
    if (!file.isAbsolute())
    {
        file = directory/file;
    }
    if (!isFile(file))
    {
        FatalIOErrorInFunction(dict)
            << owner.c_str() << ": cannot find the surface file " << file
            << exit(FatalIOError);
    }
    const scalar scale = dict.getOrDefault<scalar>("scale", 1);
    if (scale <= 0)
    {
        FatalIOErrorInFunction(dict)
            << owner.c_str() << ": scale " << scale
            << " must be positive" << exit(FatalIOError);
    }

    autoPtr<triSurface> surf;
    const bool throwing = FatalError.throwExceptions();
    const bool throwingIO = FatalIOError.throwExceptions();
    try
    {
        surf.reset(new triSurface(file, scale));
    }
    catch (const Foam::error& err)
    {
        FatalError.throwExceptions(throwing);
        FatalIOError.throwExceptions(throwingIO);
        FatalIOErrorInFunction(dict)
            << owner.c_str() << ": cannot read the surface file " << file
            << nl << "    " << err.message().c_str() << exit(FatalIOError);
    }
    FatalError.throwExceptions(throwing);
    FatalIOError.throwExceptions(throwingIO);

    if (surf->empty())
    {
        FatalIOErrorInFunction(dict)
            << owner.c_str() << ": the surface file " << file
            << " holds no faces" << exit(FatalIOError);
    }
    return surf;
}


Foam::fileName Foam::surfaceFile::caseDirectory()
{
    return argList::envGlobalPath()/"constant"/"triSurface";
}


// ************************************************************************* //
