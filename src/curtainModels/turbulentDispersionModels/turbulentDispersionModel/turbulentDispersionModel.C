/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "turbulentDispersionModel.H"
#include "refuseUnknownEntries.H"
#include "boundedEntry.H"
#include "selectModel.H"

namespace Foam
{
    defineTypeNameAndDebug(turbulentDispersionModel, 0);
    defineRunTimeSelectionTable(turbulentDispersionModel, dictionary);
}


Foam::turbulentDispersionModel::turbulentDispersionModel(const dictionary& dict)
:
    dict_(dict)
{}


void Foam::turbulentDispersionModel::checkEntries(const wordList& allowed) const
{
    refuseUnknownEntries
    (
        dict_, allowed, "of turbulentDispersion (type " + dict_.get<word>("type") + ")", "type"
    );
}


Foam::scalar Foam::turbulentDispersionModel::coeff
(
    const word& entry,
    scalar deflt,
    scalar lo,
    scalar hi,
    bool loOpen
) const
{
    return boundedEntry(dict_, entry, deflt, lo, hi, loOpen, "turbulentDispersion");
}


Foam::autoPtr<Foam::turbulentDispersionModel>
Foam::turbulentDispersionModel::New(const dictionary& curtainProperties)
{
    return selectModel<turbulentDispersionModel>(curtainProperties, "turbulentDispersion");
}
