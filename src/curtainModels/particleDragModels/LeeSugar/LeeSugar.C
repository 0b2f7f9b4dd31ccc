/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "LeeSugar.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace particleDragModels
{
    defineTypeNameAndDebug(LeeSugar, 0);
    addToRunTimeSelectionTable(particleDragModel, LeeSugar, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleDragModels::LeeSugar::LeeSugar(const dictionary& dict)
:
    particleDragModel(dict, particleDrag::dragLawFromName("LeeSugar"))
{}


// ************************************************************************* //
