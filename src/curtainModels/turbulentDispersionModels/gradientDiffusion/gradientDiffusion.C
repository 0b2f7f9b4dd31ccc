/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "gradientDiffusion.H"
#include "crossingTrajectories.H"
#include "surfaceInterpolate.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace turbulentDispersionModels
{
    defineTypeNameAndDebug(gradientDiffusion, 0);
    addToRunTimeSelectionTable(turbulentDispersionModel, gradientDiffusion, dictionary);
}
}


Foam::turbulentDispersionModels::gradientDiffusion::gradientDiffusion(const dictionary& dict)
:
    turbulentDispersionModel(dict),
    sigma_(coeff("sigma", 0.9, 0, 10, true)),
    Cbeta_(coeff("Cbeta", CsanadyCbeta, 0, 10, false))
{
    checkEntries(wordList({"sigma", "Cbeta"}));
}


Foam::tmp<Foam::surfaceScalarField>
Foam::turbulentDispersionModels::gradientDiffusion::faceDiffusivity
(
    const volVectorField& Up,
    const volVectorField& Ug,
    const volScalarField& k,
    const volScalarField& nut
) const
{
    tmp<surfaceScalarField> tD
    (
        new surfaceScalarField
        (
            "Dp",
            fvc::interpolate((nut/sigma_)*crossingTrajectoryFactor(Up, Ug, k, Cbeta_))
        )
    );
    // no dispersion through boundaries
    forAll(tD.ref().boundaryField(), patchi)
    {
        tD.ref().boundaryFieldRef()[patchi] = 0;
    }
    return tD;
}


Foam::string Foam::turbulentDispersionModels::gradientDiffusion::summary() const
{
    OStringStream os;
    os  << "gradientDiffusion (sigma " << sigma_ << ", Cbeta " << Cbeta_ << ")";
    return os.str();
}
