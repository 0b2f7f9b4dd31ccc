/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "noParticleTurbulence.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace particleTurbulenceModels
{
    defineTypeNameAndDebug(none, 0);
    addToRunTimeSelectionTable(particleTurbulenceModel, none, dictionary);
}
}


Foam::particleTurbulenceModels::none::none
(
    const dictionary& coeffs,
    const curtainSolids& solids,
    const fvMesh& mesh
)
:
    particleTurbulenceModel(coeffs, solids, mesh)
{
    checkEntries(wordList());
}


Foam::tmp<Foam::volScalarField> Foam::particleTurbulenceModels::none::sinkRate() const
{
    return volScalarField::New
    (
        "particleTurbulence:sinkRate", mesh_, dimensionedScalar(dimless/dimTime, Zero)
    );
}
