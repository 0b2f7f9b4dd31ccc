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
    const classState& c1,
    const classState& c2,
    const volScalarField& alphaGas,
    const volScalarField& alphaByD
) const
{
    using constant::mathematical::pi;

    // The classes are pressureless and capped below packing (alphaMax), so
    // alpha_g stays well above this floor; it only guards round-off
    const volScalarField ag(max(alphaGas, scalar(0.05)));
    const dimensionedScalar& d1 = c1.d;
    const dimensionedScalar& d2 = c2.d;

    // Lebowitz (1964)
    const volScalarField g0(1/ag + 3*d1*d2/(sqr(ag)*(d1 + d2))*alphaByD);

    return volScalarField::New
    (
        "Kpp",
        3*(1 + e_)*(pi/2 + Cf_*sqr(pi)/8)
       *max(c1.alpha, scalar(0))*c1.rho*max(c2.alpha, scalar(0))*c2.rho
       *sqr(d1 + d2)*g0*mag(c1.U - c2.U)
       /(2*pi*(c1.rho*pow3(d1) + c2.rho*pow3(d2)))
    );
}


Foam::string Foam::particleParticleDragModels::Syamlal::summary() const
{
    return "Syamlal (restitution " + Foam::name(e_) + ", friction " + Foam::name(Cf_) + ")";
}
