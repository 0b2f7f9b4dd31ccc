/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "curtainGasVelocity.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"
#include "surfaceFields.H"
#include "uniformDimensionedFields.H"
#include "gravityMeshObject.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(curtainGasVelocity, 0);
    addToRunTimeSelectionTable(functionObject, curtainGasVelocity, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::curtainGasVelocity::curtainGasVelocity
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, dict),
    flowDir_(1, 0, 0),
    alphaEdge_(curtainSolids::alphaEdgeDefault),
    Vg_(-1),
    hMin_(-GREAT),
    hMax_(GREAT),
    perClass_(false)
{
    read(dict);
    OFstream& os = file();
    writeHeader(os, "Solids-weighted gas velocity inside the curtain");
    writeHeaderValue(os, "alphaEdge", alphaEdge_);
    writeHeaderValue(os, "heights", Pair<scalar>(hMin_, hMax_));
    writeCommented(os, "Time");
    writeTabbed(os, "Vc");
    writeTabbed(os, "Vg");
    writeTabbed(os, "VcByVg");
    writeTabbed(os, "solidsVolume");
    if (perClass_)
    {
        for (const word& c : solids_->names())
        {
            writeTabbed(os, "Vc_" + c);
            writeTabbed(os, "VcByVg_" + c);
        }
    }
    os  << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::curtainGasVelocity::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);
    solids_.reset(new curtainSolids(mesh_));

    flowDir_ = dict.get<vector>("flowDirection");
    if (mag(flowDir_) < SMALL)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'flowDirection' is a zero vector" << exit(FatalIOError);
    }
    flowDir_ /= mag(flowDir_);

    alphaEdge_ = dict.getOrDefault<scalar>("alphaEdge", solids_->alphaEdge());
    if (!(alphaEdge_ > 0 && alphaEdge_ < 1))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'alphaEdge' = " << alphaEdge_
            << " outside the allowed range (0 1)" << exit(FatalIOError);
    }

    const bool hasVg = dict.found("Vg");
    const bool hasInlet = dict.found("gasInlet");
    if (hasVg == hasInlet)
    {
        FatalIOErrorInFunction(dict)
            << "Give exactly one of 'Vg' [m/s] or 'gasInlet' (patch name)"
            << exit(FatalIOError);
    }
    if (hasVg)
    {
        Vg_ = dict.get<scalar>("Vg");
        if (!(Vg_ > 0))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'Vg' = " << Vg_ << " outside the allowed range "
                << "(0 inf) m/s" << exit(FatalIOError);
        }
    }
    else
    {
        gasInlet_ = dict.get<word>("gasInlet");
        if (mesh_.boundaryMesh().findPatchID(gasInlet_) < 0)
        {
            FatalIOErrorInFunction(dict)
                << "gasInlet '" << gasInlet_ << "' is not a patch of the mesh "
                << mesh_.boundaryMesh().names() << exit(FatalIOError);
        }
    }

    if (dict.found("heights"))
    {
        const Pair<scalar> h(dict.get<Pair<scalar>>("heights"));
        hMin_ = min(h.first(), h.second());
        hMax_ = max(h.first(), h.second());
    }
    perClass_ = dict.getOrDefault<bool>("perClass", false);
    return true;
}


bool Foam::functionObjects::curtainGasVelocity::execute()
{
    return true;
}


bool Foam::functionObjects::curtainGasVelocity::write()
{
    const volVectorField& Ug = lookupObject<volVectorField>
    (
        IOobject::groupName("U", solids_->gasName())
    );

    const label n = solids_->size();
    UPtrList<const volScalarField> alpha(n);
    scalarField alphas(mesh_.nCells(), Zero);
    forAll(solids_->names(), i)
    {
        alpha.set
        (
            i,
            &lookupObject<volScalarField>
            (
                IOobject::groupName("alpha", solids_->names()[i])
            )
        );
        alphas += alpha[i].primitiveField();
    }
    // per class: the same cells, weighted by the class's own fraction
    scalarList swi(n, Zero), swui(n, Zero);

    const uniformDimensionedVectorField& g = meshObjects::gravity::New(time_);
    const vector up(-g.value()/max(mag(g.value()), VSMALL));

    const vectorField& C = mesh_.C().primitiveField();
    const scalarField& V = mesh_.V().field();
    scalar sw = 0, swu = 0;
    forAll(alphas, celli)
    {
        const scalar h = C[celli] & up;
        if (alphas[celli] >= alphaEdge_ && h >= hMin_ && h <= hMax_)
        {
            const scalar w = alphas[celli]*V[celli];
            sw += w;
            swu += w*(Ug[celli] & flowDir_);
            if (perClass_)
            {
                forAll(swi, i)
                {
                    const scalar wi = alpha[i][celli]*V[celli];
                    swi[i] += wi;
                    swui[i] += wi*(Ug[celli] & flowDir_);
                }
            }
        }
    }
    reduce(sw, sumOp<scalar>());
    reduce(swu, sumOp<scalar>());
    reduce(swi, sumOp<scalarList>());
    reduce(swui, sumOp<scalarList>());

    scalar Vg = Vg_;
    if (Vg_ < 0)
    {
        const label patchi = mesh_.boundaryMesh().findPatchID(gasInlet_);
        const scalarField& magSf = mesh_.magSf().boundaryField()[patchi];
        const vectorField& Up = Ug.boundaryField()[patchi];
        Vg = gSum(magSf*(Up & flowDir_))/max(gSum(magSf), VSMALL);
    }

    const scalar Vc = sw > 0 ? swu/sw : 0;
    const scalar ratio = mag(Vg) > VSMALL ? Vc/Vg : 0;

    Info<< type() << ' ' << name() << " write:" << nl
        << "    V_c " << Vc << " m/s, V_g " << Vg << " m/s, V_c/V_g "
        << ratio << " (solids volume " << sw << " m3)" << nl << endl;

    setResult("Vc", Vc);
    setResult("Vg", Vg);
    setResult("VcByVg", ratio);
    setResult("solidsVolume", sw);
    scalarList Vci(n, Zero);
    if (perClass_)
    {
        forAll(Vci, i)
        {
            Vci[i] = swi[i] > 0 ? swui[i]/swi[i] : 0;
            Info<< "    " << solids_->names()[i] << ": V_c " << Vci[i]
                << " m/s, V_c/V_g " << (mag(Vg) > VSMALL ? Vci[i]/Vg : 0) << nl;
            setResult("Vc_" + solids_->names()[i], Vci[i]);
            setResult("VcByVg_" + solids_->names()[i], mag(Vg) > VSMALL ? Vci[i]/Vg : 0);
        }
        Info<< endl;
    }

    if (Pstream::master())
    {
        OFstream& os = file();
        writeCurrentTime(os);
        os  << tab << Vc << tab << Vg << tab << ratio << tab << sw;
        if (perClass_)
        {
            forAll(Vci, i)
            {
                os  << tab << Vci[i] << tab << (mag(Vg) > VSMALL ? Vci[i]/Vg : 0);
            }
        }
        os  << endl;
    }
    return true;
}


// ************************************************************************* //
