/*---------------------------------------------------------------------------*\
  flightedDryer: curtainFoam
\*---------------------------------------------------------------------------*/

#include "particleClass.H"
#include "fvc.H"
#include "IFstream.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// Point the template's references to other fields of the class
// (e.g. inletOutlet's "phi phi.particles") to this class's fields
void renameGroup(Foam::dictionary& dict, const Foam::word& cls)
{
    using namespace Foam;
    const word suffix(".particles");
    DynamicList<Pair<word>> changes;
    for (entry& e : dict)
    {
        if (e.isDict())
        {
            renameGroup(e.dict(), cls);
        }
        else
        {
            const ITstream& is = e.stream();
            if (is.size() == 1 && is[0].isWord())
            {
                const word& w = is[0].wordToken();
                if (w.size() > suffix.size() && w.endsWith(suffix))
                {
                    changes.append
                    (
                        Pair<word>
                        (
                            e.keyword(),
                            w.substr(0, w.size() - suffix.size()) + "." + cls
                        )
                    );
                }
            }
        }
    }
    for (const Pair<word>& c : changes)
    {
        dict.set(c.first(), c.second());
    }
}

}

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type>
Foam::GeometricField<Type, Foam::fvPatchField, Foam::volMesh>*
Foam::particleClass::readField
(
    const fvMesh& mesh,
    const word& base,
    const word& className
)
{
    typedef GeometricField<Type, fvPatchField, volMesh> fieldType;

    IOobject io
    (
        IOobject::groupName(base, className),
        mesh.time().timeName(),
        mesh,
        IOobject::MUST_READ,
        IOobject::AUTO_WRITE
    );

    if (io.typeHeaderOk<fieldType>(true))
    {
        Info<< "Reading " << io.name() << endl;
        return new fieldType(io, mesh);
    }

    IOobject templ
    (
        IOobject::groupName(base, "particles"),
        mesh.time().timeName(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE
    );
    if (!templ.typeHeaderOk<fieldType>(true))
    {
        FatalErrorInFunction
            << "Neither " << io.name() << " nor the template "
            << templ.name() << " found in " << mesh.time().timeName()
            << " for particle class " << className
            << exit(FatalError);
    }
    Info<< "Reading " << io.name() << " from the template " << templ.name()
        << endl;
    IFstream is(templ.objectPath());
    dictionary dict(is);
    renameGroup(dict, className);
    IOobject ioNew(io.name(), io.instance(), mesh, IOobject::NO_READ, IOobject::AUTO_WRITE);
    return new fieldType(ioNew, mesh, dict);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleClass::particleClass
(
    const curtainSolids& solids,
    const label i,
    const fvMesh& mesh
)
:
    name_(solids.names()[i]),
    dragDict_(solids.drag(i)),
    d_("d", dimLength, solids.d(i)),
    rho_("rho", dimDensity, solids.rho(i)),
    drag_()
{
    drag_ = particleDragModel::New(dragDict_);

    alpha_.reset(readField<scalar>(mesh, "alpha", name_));
    U_.reset(readField<vector>(mesh, "U", name_));
    phi_.reset
    (
        new surfaceScalarField
        (
            IOobject
            (
                IOobject::groupName("phi", name_),
                mesh.time().timeName(),
                mesh,
                IOobject::READ_IF_PRESENT,
                IOobject::AUTO_WRITE
            ),
            fvc::flux(U_())
        )
    );
    alphaPhi_.reset
    (
        new surfaceScalarField
        (
            IOobject
            (
                IOobject::groupName("alphaPhi", name_),
                mesh.time().timeName(),
                mesh,
                IOobject::NO_READ,
                IOobject::NO_WRITE
            ),
            fvc::interpolate(alpha_())*phi_()
        )
    );

    alpha_->oldTime();
    mesh.setFluxRequired(alpha_->name());
    Info<< "Particle class " << name_ << ": d " << d_.value() << " m, rho "
        << rho_.value() << " kg/m3, drag " << dragDict_.get<word>("type")
        << nl << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::volScalarField> Foam::particleClass::beta
(
    const volScalarField& alphaGas,
    const volVectorField& Ugas,
    const dimensionedScalar& rhoGas,
    const dimensionedScalar& muGas,
    const scalar residualAlpha
) const
{
    // K is linear in alphaD at given alphaC (K = 3/4 CdRe alphaD mu/d^2):
    // K at alphaD = 1 is K/alpha
    const volScalarField unity
    (
        IOobject("unity", alpha_->time().timeName(), alpha_->mesh()),
        alpha_->mesh(),
        dimensionedScalar("one", dimless, 1.0)
    );
    tmp<volScalarField> tbeta
    (
        drag_->K(unity, alphaGas, mag(Ugas - U_()), d_, rhoGas, muGas, residualAlpha)
    );
    tbeta.ref().rename(IOobject::groupName("beta", name_));
    return tbeta;
}


// ************************************************************************* //
