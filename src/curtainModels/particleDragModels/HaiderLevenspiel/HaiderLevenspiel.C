/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "HaiderLevenspiel.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace particleDragModels
{
    defineTypeNameAndDebug(HaiderLevenspiel, 0);
    addToRunTimeSelectionTable(particleDragModel, HaiderLevenspiel, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{
::particleDrag::DragLaw readLaw(const Foam::dictionary& dict)
{
    using namespace Foam;
    const scalar phi = dict.get<scalar>("sphericity");
    if (!(phi > 0 && phi <= 1))
    {
        FatalIOErrorInFunction(dict)
            << "sphericity " << phi << " outside the allowed range (0 1]"
            << exit(FatalIOError);
    }
    return particleDrag::dragLawFromName("HaiderLevenspiel", phi);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleDragModels::HaiderLevenspiel::HaiderLevenspiel(const dictionary& dict)
:
    particleDragModel(dict, readLaw(dict))
{}


// ************************************************************************* //
