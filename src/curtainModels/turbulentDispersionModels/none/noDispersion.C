/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "noDispersion.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace turbulentDispersionModels
{
    defineTypeNameAndDebug(none, 0);
    addToRunTimeSelectionTable(turbulentDispersionModel, none, dictionary);
}
}


Foam::turbulentDispersionModels::none::none(const dictionary& dict)
:
    turbulentDispersionModel(dict)
{
    checkEntries(wordList());
}


Foam::tmp<Foam::surfaceScalarField>
Foam::turbulentDispersionModels::none::faceDiffusivity
(
    const volVectorField& Up,
    const volVectorField&,
    const volScalarField&,
    const volScalarField&
) const
{
    return surfaceScalarField::New
    (
        "Dp", Up.mesh(), dimensionedScalar(dimViscosity, Zero)
    );
}
