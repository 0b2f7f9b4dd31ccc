/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "particleTurbulenceInteraction.H"
#include "refuseUnknownEntries.H"
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


void Foam::fv::particleTurbulenceInteraction::readModel(const dictionary& dict)
{
    const word model(dict.get<word>("model"));
    refuseUnknownEntries
    (
        dict,
        wordList({"type", "active", "timeStart", "duration", "model", model + "Coeffs"}),
        "of fvOption " + name_
    );
    model_ = particleTurbulenceModel::New(dict, solids_, mesh_);

    const word& gas = solids_.gasName();
    omegaForm_ = mesh_.foundObject<volScalarField>(IOobject::groupName("omega", gas));
    if (model_->active())
    {
        fieldNames_.setSize(2);
        fieldNames_[0] = IOobject::groupName("k", gas);
        fieldNames_[1] = IOobject::groupName(omegaForm_ ? "omega" : "epsilon", gas);
    }
    else
    {
        fieldNames_.clear();
    }
    applied_.setSize(fieldNames_.size(), false);
    Info<< "    " << name_ << ": " << model_->summary().c_str();
    if (model_->active())
    {
        Info<< " in " << fieldNames_[0] << " and " << fieldNames_[1];
    }
    Info<< " from " << solids_.size() << " classes" << endl;
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
    model_(),
    omegaForm_(false)
{
    readModel(dict);
}


void Foam::fv::particleTurbulenceInteraction::addSup
(
    const volScalarField& alpha,
    const volScalarField& rho,
    fvMatrix<scalar>& eqn,
    const label fieldi
)
{
    const volScalarField D(model_->sinkRate());
    const volScalarField P(model_->production());
    const bool producing = gMax(P.primitiveField()) > 0;
    const scalar C3 = model_->C3eps();
    if (fieldi == 0)
    {
        if (producing)
        {
            eqn += P;                                 // S_k = P - D k
        }
        eqn -= fvm::Sp(D, eqn.psi());
        return;
    }
    if (!producing && !omegaForm_)
    {
        eqn -= fvm::Sp(C3*D, eqn.psi());              // S_eps = -C3eps D eps
        return;
    }
    const volScalarField& k = mesh_.lookupObject<volScalarField>(fieldNames_[0]);
    const dimensionedScalar kSmall("kSmall", k.dimensions(), SMALL);
    const volScalarField rate(D - P/max(k, kSmall));  // -S_k/k
    if (omegaForm_)
    {
        eqn -= fvm::SuSp((C3 - 1)*rate, eqn.psi());   // S_omega = (C3eps - 1) omega S_k/k
    }
    else
    {
        eqn -= fvm::SuSp(C3*rate, eqn.psi());         // S_eps = C3eps eps S_k/k
    }
}


void Foam::fv::particleTurbulenceInteraction::addSup(fvMatrix<scalar>& eqn, const label fieldi)
{
    FatalErrorInFunction
        << "fvOption " << name_ << " (particleTurbulenceInteraction) applies to the phase form of "
        << eqn.psi().name() << " only (the turbulence model of curtainFoam's gas)" << exit(FatalError);
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
        readModel(dict);
        return true;
    }
    return false;
}
