/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "Simonin.H"
#include "crossingTrajectories.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace particleTurbulenceModels
{
    defineTypeNameAndDebug(Simonin, 0);
    addToRunTimeSelectionTable(particleTurbulenceModel, Simonin, dictionary);
}
}


Foam::particleTurbulenceModels::Simonin::Simonin
(
    const dictionary& coeffs,
    const curtainSolids& solids,
    const fvMesh& mesh,
    const wordList& extraEntries
)
:
    particleTurbulenceModel(coeffs, solids, mesh),
    C3eps_(coeff("C3eps", 1.2, 0, 5)),
    Cmu_(coeff("Cmu", 0.09, 0.01, 1)),
    Cbeta_(coeff("Cbeta", CsanadyCbeta, 0, 10))
{
    wordList allowed({"C3eps", "Cmu", "Cbeta"});
    allowed.append(extraEntries);
    checkEntries(allowed);
}


Foam::tmp<Foam::volScalarField>
Foam::particleTurbulenceModels::Simonin::sinkRate() const
{
    const volScalarField& kg = k();
    const tmp<volScalarField> teps(epsilon());   // the gas field itself under k-epsilon
    const volScalarField& eps = teps();
    const volVectorField& Ug = Ugas();

    const dimensionedScalar epsSmall("epsSmall", eps.dimensions(), SMALL);
    // eddy life time 3/2 Cmu k/eps (Simonin 1990)
    const volScalarField tauEddy(1.5*Cmu_*kg/max(eps, epsSmall));

    tmp<volScalarField> tD = volScalarField::New
    (
        "particleTurbulence:sinkRate", mesh_, dimensionedScalar(dimless/dimTime, Zero)
    );
    volScalarField& D = tD.ref();
    const dimensionedScalar rhoG("rhoG", dimDensity, solids_.rhoGas());
    forAll(solids_.names(), i)
    {
        const word& c = solids_.names()[i];
        const auto& alpha = mesh_.lookupObject<volScalarField>(IOobject::groupName("alpha", c));
        const auto& beta = mesh_.lookupObject<volScalarField>(IOobject::groupName("beta", c));
        const auto& Up = mesh_.lookupObject<volVectorField>(IOobject::groupName("U", c));
        // Csanady's crossing trajectories: the particle leaves the eddy
        const volScalarField tauT(tauEddy*crossingTrajectoryFactor(Up, Ug, kg, Cbeta_));
        const dimensionedScalar rhoP("rhoP", dimDensity, solids_.rho(i));
        const volScalarField eta(tauT*beta/rhoP);
        D += 2*max(alpha, scalar(0))*beta/(rhoG*(1 + eta));
    }
    return tD;
}


Foam::string Foam::particleTurbulenceModels::Simonin::summary() const
{
    OStringStream os;
    os  << "Simonin drag sink (C3eps " << C3eps_ << ", Cmu " << Cmu_ << ", Cbeta " << Cbeta_ << ")";
    return os.str();
}
