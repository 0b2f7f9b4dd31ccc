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
    const classState& c1,
    const classState&,
    const volScalarField&,
    const volScalarField&
) const
{
    return volScalarField::New("Kpp", c1.alpha.mesh(), dimensionedScalar(dimDensity/dimTime, Zero));
}
