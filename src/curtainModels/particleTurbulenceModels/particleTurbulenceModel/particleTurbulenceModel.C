/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "particleTurbulenceModel.H"
#include "refuseUnknownEntries.H"

namespace Foam
{
    defineTypeNameAndDebug(particleTurbulenceModel, 0);
    defineRunTimeSelectionTable(particleTurbulenceModel, dictionary);
}


Foam::particleTurbulenceModel::particleTurbulenceModel
(
    const dictionary& coeffs,
    const curtainSolids& solids,
    const fvMesh& mesh
)
:
    mesh_(mesh),
    solids_(solids),
    coeffs_(coeffs)
{}


void Foam::particleTurbulenceModel::checkEntries(const wordList& allowed) const
{
    refuseUnknownEntries(coeffs_, allowed, "in " + coeffs_.name());
}


Foam::scalar Foam::particleTurbulenceModel::coeff
(
    const word& entry,
    scalar deflt,
    scalar lo,
    scalar hi
) const
{
    const scalar v = coeffs_.getOrDefault<scalar>(entry, deflt);
    if (!(v >= lo && v <= hi))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Entry '" << entry << "' = " << v << " of " << coeffs_.name()
            << " outside the allowed range [" << lo << ", " << hi << "]"
            << exit(FatalIOError);
    }
    return v;
}


const Foam::volScalarField& Foam::particleTurbulenceModel::k() const
{
    return mesh_.lookupObject<volScalarField>(IOobject::groupName("k", solids_.gasName()));
}


const Foam::volVectorField& Foam::particleTurbulenceModel::Ugas() const
{
    return mesh_.lookupObject<volVectorField>(IOobject::groupName("U", solids_.gasName()));
}


Foam::tmp<Foam::volScalarField> Foam::particleTurbulenceModel::epsilon() const
{
    const word epsName(IOobject::groupName("epsilon", solids_.gasName()));
    const word omegaName(IOobject::groupName("omega", solids_.gasName()));
    if (mesh_.foundObject<volScalarField>(epsName))
    {
        return tmp<volScalarField>(mesh_.lookupObject<volScalarField>(epsName));
    }
    if (mesh_.foundObject<volScalarField>(omegaName))
    {
        // kOmegaSST: eps = betaStar k omega, betaStar 0.09 (Menter 2003)
        return tmp<volScalarField>::New
        (
            epsName,
            0.09*k()*mesh_.lookupObject<volScalarField>(omegaName)
        );
    }
    FatalErrorInFunction
        << "particle-turbulence interaction needs the gas fields " << epsName
        << " or " << omegaName << " (gas models kEpsilon, realizableKE, kOmegaSST)"
        << exit(FatalError);
    return nullptr;
}


Foam::tmp<Foam::volScalarField> Foam::particleTurbulenceModel::production() const
{
    return volScalarField::New
    (
        "particleTurbulence:production", mesh_, dimensionedScalar(dimVelocity*dimVelocity/dimTime, Zero)
    );
}
