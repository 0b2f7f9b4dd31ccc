/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "particleTurbulenceModel.H"

Foam::autoPtr<Foam::particleTurbulenceModel> Foam::particleTurbulenceModel::New
(
    const dictionary& dict,
    const curtainSolids& solids,
    const fvMesh& mesh
)
{
    const word modelType(dict.get<word>("model"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);
    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "particleTurbulenceModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }
    return autoPtr<particleTurbulenceModel>
    (
        cstrIter()(dict.subOrEmptyDict(modelType + "Coeffs"), solids, mesh)
    );
}
