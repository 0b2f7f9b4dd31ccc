/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "particleParticleDragModel.H"
#include "refuseUnknownEntries.H"
#include "selectModel.H"

namespace Foam
{
    defineTypeNameAndDebug(particleParticleDragModel, 0);
    defineRunTimeSelectionTable(particleParticleDragModel, dictionary);
}


Foam::particleParticleDragModel::particleParticleDragModel(const dictionary& dict)
:
    dict_(dict)
{}


void Foam::particleParticleDragModel::checkEntries(const wordList& allowed) const
{
    refuseUnknownEntries
    (
        dict_, allowed, "of particleParticleDrag (type " + dict_.get<word>("type") + ")", "type"
    );
}


Foam::autoPtr<Foam::particleParticleDragModel>
Foam::particleParticleDragModel::New(const dictionary& curtainProperties)
{
    return selectModel<particleParticleDragModel>(curtainProperties, "particleParticleDrag");
}
