/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "curtainSolids.H"
#include "IOdictionary.H"
#include "Time.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

Foam::autoPtr<Foam::dictionary> readConstantDict
(
    const Foam::fvMesh& mesh,
    const Foam::word& name
)
{
    using namespace Foam;
    if (mesh.foundObject<IOdictionary>(name))
    {
        return autoPtr<dictionary>(new dictionary(mesh.lookupObject<IOdictionary>(name)));
    }
    IOdictionary dict
    (
        IOobject
        (
            name,
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    return autoPtr<dictionary>(new dictionary(dict));
}

}


constexpr Foam::scalar Foam::curtainSolids::alphaEdgeDefault;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::curtainSolids::curtainSolids(const fvMesh& mesh)
:
    rhoGas_(0),
    muGas_(0),
    alphaEdge_(alphaEdgeDefault)
{
    const autoPtr<dictionary> curtain(readConstantDict(mesh, "curtainProperties"));
    const autoPtr<dictionary> transport(readConstantDict(mesh, "transportProperties"));

    gasName_ = curtain->getOrDefault<word>("continuousPhase", "air");
    rhoGas_ = transport->get<scalar>("rho");
    muGas_ = rhoGas_*transport->get<scalar>("nu");

    alphaEdge_ = curtain->getOrDefault<scalar>("alphaEdge", alphaEdgeDefault);
    if (!(alphaEdge_ > 0 && alphaEdge_ < 1))
    {
        FatalIOErrorInFunction(*curtain)
            << "constant/curtainProperties: entry 'alphaEdge' = " << alphaEdge_
            << " outside the allowed range (0 1)" << exit(FatalIOError);
    }

    const dictionary& particles = curtain->subDict("particles");
    const dictionary emptyDict;
    const dictionary& defaultDrag =
        curtain->isDict("drag") ? curtain->subDict("drag") : emptyDict;

    names_.setSize(particles.size());
    d_.setSize(particles.size());
    rho_.setSize(particles.size());
    drag_.setSize(particles.size());
    label i = 0;
    for (const entry& e : particles)
    {
        names_[i] = e.keyword();
        d_[i] = e.dict().get<scalar>("d");
        rho_[i] = e.dict().get<scalar>("rho");
        drag_.set
        (
            i,
            new dictionary
            (
                e.dict().isDict("drag") ? e.dict().subDict("drag") : defaultDrag
            )
        );
        ++i;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::curtainSolids::find(const word& name) const
{
    forAll(names_, i)
    {
        if (names_[i] == name)
        {
            return i;
        }
    }
    return -1;
}


// ************************************************************************* //
