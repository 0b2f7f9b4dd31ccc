/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "SimoninCrowe.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace particleTurbulenceModels
{
    defineTypeNameAndDebug(SimoninCrowe, 0);
    addToRunTimeSelectionTable(particleTurbulenceModel, SimoninCrowe, dictionary);
}
}


Foam::particleTurbulenceModels::SimoninCrowe::SimoninCrowe
(
    const dictionary& coeffs,
    const curtainSolids& solids,
    const fvMesh& mesh
)
:
    Simonin(coeffs, solids, mesh, wordList({"Cp"})),
    Cp_(coeff("Cp", 1, 0, 1))
{}


Foam::tmp<Foam::volScalarField>
Foam::particleTurbulenceModels::SimoninCrowe::production() const
{
    const volVectorField& Ug = Ugas();
    tmp<volScalarField> tP = volScalarField::New
    (
        "particleTurbulence:production", mesh_, dimensionedScalar(dimVelocity*dimVelocity/dimTime, Zero)
    );
    volScalarField& P = tP.ref();
    const dimensionedScalar rhoG("rhoG", dimDensity, solids_.rhoGas());
    forAll(solids_.names(), i)
    {
        const word& c = solids_.names()[i];
        const auto& alpha = mesh_.lookupObject<volScalarField>(IOobject::groupName("alpha", c));
        const auto& beta = mesh_.lookupObject<volScalarField>(IOobject::groupName("beta", c));
        const auto& Up = mesh_.lookupObject<volVectorField>(IOobject::groupName("U", c));
        // drag work on the mean slip (Crowe 2000)
        P += Cp_*max(alpha, scalar(0))*beta*magSqr(Up - Ug)/rhoG;
    }
    return tP;
}


Foam::string Foam::particleTurbulenceModels::SimoninCrowe::summary() const
{
    OStringStream os;
    os  << "Simonin drag sink + Crowe wake production (Cp " << Cp_ << ", C3eps " << C3eps_
        << ", Cmu " << Cmu_ << ", Cbeta " << Cbeta_ << ")";
    return os.str();
}
