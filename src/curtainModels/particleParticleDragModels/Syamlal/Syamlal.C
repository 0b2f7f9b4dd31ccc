/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "Syamlal.H"
#include "boundedEntry.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace particleParticleDragModels
{
    defineTypeNameAndDebug(Syamlal, 0);
    addToRunTimeSelectionTable(particleParticleDragModel, Syamlal, dictionary);
}
}


Foam::particleParticleDragModels::Syamlal::Syamlal(const dictionary& dict)
:
    particleParticleDragModel(dict),
    e_(boundedEntry(dict, "restitution", 0.9, 0, 1, false, "particleParticleDrag")),
    Cf_(boundedEntry(dict, "friction", 0, 0, 1, false, "particleParticleDrag"))
{
    checkEntries(wordList({"restitution", "friction"}));
}


Foam::tmp<Foam::volScalarField> Foam::particleParticleDragModels::Syamlal::K
(
    const volScalarField& alpha1,
    const dimensionedScalar& rho1,
    const dimensionedScalar& d1,
    const volVectorField& U1,
    const volScalarField& alpha2,
    const dimensionedScalar& rho2,
    const dimensionedScalar& d2,
    const volVectorField& U2,
    const volScalarField& alphaGas,
    const volScalarField& alphaByD
) const
{
    using constant::mathematical::pi;

    // The classes are pressureless and capped below packing (alphaMax), so
    // alpha_g stays well above this floor; it only guards round-off
    const volScalarField ag(max(alphaGas, scalar(0.05)));

    // Lebowitz (1964)
    const volScalarField g0(1/ag + 3*d1*d2/(sqr(ag)*(d1 + d2))*alphaByD);

    return volScalarField::New
    (
        "Kpp",
        3*(1 + e_)*(pi/2 + Cf_*sqr(pi)/8)
       *max(alpha1, scalar(0))*rho1*max(alpha2, scalar(0))*rho2
       *sqr(d1 + d2)*g0*mag(U1 - U2)
       /(2*pi*(rho1*pow3(d1) + rho2*pow3(d2)))
    );
}


Foam::string Foam::particleParticleDragModels::Syamlal::summary() const
{
    return "Syamlal (restitution " + Foam::name(e_) + ", friction " + Foam::name(Cf_) + ")";
}
