/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "Gidaspow.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace particleDragModels
{
    defineTypeNameAndDebug(Gidaspow, 0);
    addToRunTimeSelectionTable(particleDragModel, Gidaspow, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleDragModels::Gidaspow::Gidaspow(const dictionary& dict)
:
    particleDragModel(dict, particleDrag::dragLawFromName("Gidaspow"))
{}


// ************************************************************************* //
