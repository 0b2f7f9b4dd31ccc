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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::curtainSolids::curtainSolids(const fvMesh& mesh)
:
    rhoGas_(0),
    muGas_(0)
{
    const autoPtr<dictionary> curtain(readConstantDict(mesh, "curtainProperties"));
    const autoPtr<dictionary> transport(readConstantDict(mesh, "transportProperties"));

    gasName_ = curtain->getOrDefault<word>("continuousPhase", "air");
    rhoGas_ = transport->get<scalar>("rho");
    muGas_ = rhoGas_*transport->get<scalar>("nu");

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
