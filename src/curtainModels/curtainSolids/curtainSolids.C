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

    // The particle classes: the one reader of particles { name { d; rho; drag; } }
    // for curtainFoam and the library's function objects and fvOptions
    if (!curtain->isDict("particles") || curtain->subDict("particles").empty())
    {
        FatalIOErrorInFunction(*curtain)
            << "Sub-dictionary 'particles' missing or empty: give at least one "
            << "particle class, e.g. particles { sand { d 0.5e-3; rho 2650; } }"
            << exit(FatalIOError);
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
        if (!e.isDict())
        {
            FatalIOErrorInFunction(particles)
                << "Entry '" << e.keyword() << "' in 'particles' is not a "
                << "dictionary { d ..; rho ..; }" << exit(FatalIOError);
        }
        if (!e.dict().found("drag") && defaultDrag.empty())
        {
            FatalIOErrorInFunction(*curtain)
                << "No 'drag' dictionary for particle class " << e.keyword()
                << ": give drag { type SchillerNaumann; } at the top level "
                << "or in the class" << exit(FatalIOError);
        }
        names_[i] = e.keyword();
        d_[i] = e.dict().get<scalar>("d");
        rho_[i] = e.dict().get<scalar>("rho");
        // Sieve sizes of dryer solids: a micron to a few centimetres
        if (!(d_[i] >= 1e-6 && d_[i] <= 0.05))
        {
            FatalIOErrorInFunction(e.dict())
                << "Particle class " << names_[i] << ": entry 'd' = " << d_[i]
                << " m outside the allowed range [1e-6, 0.05] m"
                << exit(FatalIOError);
        }
        if (!(rho_[i] > rhoGas_ && rho_[i] < 1e5))
        {
            FatalIOErrorInFunction(e.dict())
                << "Particle class " << names_[i] << ": entry 'rho' = "
                << rho_[i] << " kg/m3 outside the allowed range ("
                << rhoGas_ << " (the gas), 1e5) kg/m3"
                << exit(FatalIOError);
        }
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
