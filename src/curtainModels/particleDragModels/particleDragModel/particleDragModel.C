/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "particleDragModel.H"

#include <stdexcept>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(particleDragModel, 0);
    defineRunTimeSelectionTable(particleDragModel, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleDragModel::particleDragModel
(
    const dictionary& dict,
    const particleDrag::DragLaw& law
)
:
    dict_(dict),
    law_(law)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::particleDragModel::CdRe
(
    const scalar Re,
    const scalar alphaC
) const
{
    try
    {
        return law_.CdRe(Re, alphaC);
    }
    catch (const std::invalid_argument& e)
    {
        FatalIOErrorInFunction(dict_)
            << "drag model " << law_.name() << ": " << e.what()
            << exit(FatalIOError);
    }
    return 0;
}


Foam::scalar Foam::particleDragModel::Cd
(
    const scalar Re,
    const scalar alphaC
) const
{
    const scalar cdre = CdRe(Re, alphaC);
    return Re > 0 ? cdre/Re : GREAT;
}


Foam::tmp<Foam::volScalarField> Foam::particleDragModel::CdRe
(
    const volScalarField& Re,
    const volScalarField& alphaC
) const
{
    tmp<volScalarField> tCdRe
    (
        new volScalarField
        (
            IOobject
            (
                "CdRe",
                Re.time().timeName(),
                Re.mesh(),
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            Re.mesh(),
            dimensionedScalar(dimless, Zero)
        )
    );
    volScalarField& cdre = tCdRe.ref();

    forAll(cdre, celli)
    {
        cdre[celli] = CdRe(Re[celli], alphaC[celli]);
    }
    volScalarField::Boundary& bf = cdre.boundaryFieldRef();
    forAll(bf, patchi)
    {
        const scalarField& pRe = Re.boundaryField()[patchi];
        const scalarField& pAlpha = alphaC.boundaryField()[patchi];
        forAll(bf[patchi], facei)
        {
            bf[patchi][facei] = CdRe(pRe[facei], pAlpha[facei]);
        }
    }
    return tCdRe;
}


Foam::tmp<Foam::volScalarField> Foam::particleDragModel::K
(
    const volScalarField& alphaD,
    const volScalarField& alphaC,
    const volScalarField& magUr,
    const dimensionedScalar& d,
    const dimensionedScalar& rhoC,
    const dimensionedScalar& muC,
    const scalar residualAlpha
) const
{
    const volScalarField alphaCb(max(alphaC, dimensionedScalar("residualAlpha", dimless, residualAlpha)));
    const volScalarField Re(rhoC*magUr*d/muC);

    return 0.75*CdRe(Re, min(alphaCb, scalar(1)))*max(alphaD, scalar(0))*muC/sqr(d);
}


// ************************************************************************* //
