/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "noParticleParticleDrag.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace particleParticleDragModels
{
    defineTypeNameAndDebug(none, 0);
    addToRunTimeSelectionTable(particleParticleDragModel, none, dictionary);
}
}


Foam::particleParticleDragModels::none::none(const dictionary& dict)
:
    particleParticleDragModel(dict)
{
    checkEntries(wordList());
}


Foam::tmp<Foam::volScalarField> Foam::particleParticleDragModels::none::K
(
    const volScalarField& alpha1,
    const dimensionedScalar&,
    const dimensionedScalar&,
    const volVectorField&,
    const volScalarField&,
    const dimensionedScalar&,
    const dimensionedScalar&,
    const volVectorField&,
    const volScalarField&,
    const volScalarField&
) const
{
    return volScalarField::New("Kpp", alpha1.mesh(), dimensionedScalar(dimDensity/dimTime, Zero));
}
