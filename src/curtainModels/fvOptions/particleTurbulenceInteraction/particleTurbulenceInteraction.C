/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "particleTurbulenceInteraction.H"
#include "crossingTrajectories.H"
#include "fvMatrices.H"
#include "fvmSup.H"
#include "volFields.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace fv
{
    defineTypeNameAndDebug(particleTurbulenceInteraction, 0);
    addToRunTimeSelectionTable(option, particleTurbulenceInteraction, dictionary);
}
}


void Foam::fv::particleTurbulenceInteraction::readCoeffs()
{
    C3eps_ = coeffs_.getOrDefault<scalar>("C3eps", 1.2);
    Cmu_ = coeffs_.getOrDefault<scalar>("Cmu", 0.09);
    Cbeta_ = coeffs_.getOrDefault<scalar>("Cbeta", 1.35);
    const auto check = [&](const char* entry, scalar v, scalar lo, scalar hi)
    {
        if (!(v >= lo && v <= hi))
        {
            FatalIOErrorInFunction(coeffs_)
                << "Entry '" << entry << "' = " << v << " of fvOption " << name_
                << " outside the allowed range [" << lo << ", " << hi << "]"
                << exit(FatalIOError);
        }
    };
    check("C3eps", C3eps_, 0, 5);
    check("Cmu", Cmu_, 0.01, 1);
    check("Cbeta", Cbeta_, 0, 10);
}


Foam::fv::particleTurbulenceInteraction::particleTurbulenceInteraction
(
    const word& name,
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    option(name, modelType, dict, mesh),
    solids_(mesh),
    C3eps_(1.2),
    Cmu_(0.09),
    Cbeta_(1.35)
{
    readCoeffs();
    fieldNames_.setSize(2);
    fieldNames_[0] = IOobject::groupName("k", solids_.gasName());
    fieldNames_[1] = IOobject::groupName("epsilon", solids_.gasName());
    applied_.setSize(fieldNames_.size(), false);
    Info<< "    " << name_ << ": particle sink in " << fieldNames_[0] << " and " << fieldNames_[1]
        << " from " << solids_.size() << " classes (C3eps " << C3eps_ << ", Cmu " << Cmu_
        << ", Cbeta " << Cbeta_ << ")" << endl;
}


Foam::tmp<Foam::volScalarField>
Foam::fv::particleTurbulenceInteraction::damping() const
{
    const word& gas = solids_.gasName();
    const auto& k = mesh_.lookupObject<volScalarField>(IOobject::groupName("k", gas));
    const auto& eps = mesh_.lookupObject<volScalarField>(IOobject::groupName("epsilon", gas));
    const auto& Ug = mesh_.lookupObject<volVectorField>(IOobject::groupName("U", gas));

    const dimensionedScalar epsSmall("epsSmall", eps.dimensions(), SMALL);
    // eddy life time 3/2 Cmu k/eps (Simonin 1990)
    const volScalarField tauEddy(1.5*Cmu_*k/max(eps, epsSmall));

    tmp<volScalarField> tD
    (
        new volScalarField
        (
            IOobject(name_ + ":damping", mesh_.time().timeName(), mesh_),
            mesh_,
            dimensionedScalar(dimless/dimTime, Zero)
        )
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
        const volScalarField tauT(tauEddy*crossingTrajectoryFactor(Up, Ug, k, Cbeta_));
        const dimensionedScalar rhoP("rhoP", dimDensity, solids_.rho(i));
        const volScalarField eta(tauT*beta/rhoP);
        D += 2*max(alpha, scalar(0))*beta/(rhoG*(1 + eta));
    }
    return tD;
}


void Foam::fv::particleTurbulenceInteraction::addSup
(
    const volScalarField& alpha,
    const volScalarField& rho,
    fvMatrix<scalar>& eqn,
    const label fieldi
)
{
    const volScalarField D(damping());
    if (fieldi == 0)
    {
        eqn -= fvm::Sp(D, eqn.psi());            // S_k = -D k
    }
    else
    {
        eqn -= fvm::Sp(C3eps_*D, eqn.psi());     // S_eps = C3eps eps/k S_k
    }
}


void Foam::fv::particleTurbulenceInteraction::addSup(fvMatrix<scalar>& eqn, const label fieldi)
{
    FatalErrorInFunction
        << "fvOption " << name_ << " (particleTurbulenceInteraction) applies to the phase form of "
        << eqn.psi().name() << " only (the kEpsilon of curtainFoam's gas)" << exit(FatalError);
}


void Foam::fv::particleTurbulenceInteraction::addSup
(
    const volScalarField& rho,
    fvMatrix<scalar>& eqn,
    const label fieldi
)
{
    addSup(eqn, fieldi);
}


bool Foam::fv::particleTurbulenceInteraction::read(const dictionary& dict)
{
    if (option::read(dict))
    {
        readCoeffs();
        return true;
    }
    return false;
}
