/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "curtainDrift.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"
#include "surfaceFields.H"
#include "uniformDimensionedFields.H"
#include "gravityMeshObject.H"
#include "processorPolyPatch.H"
#include "emptyPolyPatch.H"

#include "particleDrag/loneParticleFall.hpp"

#include <stdexcept>
#include <limits>

namespace
{
    const Foam::scalar NaN = std::numeric_limits<Foam::scalar>::quiet_NaN();
    //- Below this share of its slot flux at the floor a class has no drift
    const Foam::scalar minCaptured = 1e-6;
}

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(curtainDrift, 0);
    addToRunTimeSelectionTable(functionObject, curtainDrift, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::vector Foam::functionObjects::curtainDrift::up() const
{
    const uniformDimensionedVectorField& g = meshObjects::gravity::New(time_);
    if (mag(g.value()) < SMALL)
    {
        FatalErrorInFunction
            << type() << ' ' << name() << ": gravity is zero; the floor "
            << "height has no direction" << exit(FatalError);
    }
    return -g.value()/mag(g.value());
}


Foam::scalar Foam::functionObjects::curtainDrift::landed_(const scalar md) const
{
    // on landing patches only what leaves lands (a release patch among them
    // carries its own class in); through a floor plane the net flux counts
    return landingPatches_.empty() ? md : max(md, scalar(0));
}


void Foam::functionObjects::curtainDrift::selectFloorFaces()
{
    if (!landingPatches_.empty())
    {
        // every face of the landing patches; an outward flux lands
        const labelList ids
        (
            mesh_.boundaryMesh().patchSet(landingPatches_, false).sortedToc()
        );
        if (ids.empty())
        {
            FatalErrorInFunction
                << type() << ' ' << name() << ": landingPatches "
                << landingPatches_ << " match no patch of the mesh "
                << mesh_.boundaryMesh().names() << exit(FatalError);
        }
        DynamicList<labelPair> bF;
        for (const label patchi : ids)
        {
            forAll(mesh_.boundaryMesh()[patchi], facei)
            {
                bF.append(labelPair(patchi, facei));
            }
        }
        internalFaces_.clear();
        internalSign_.clear();
        boundaryFaces_.transfer(bF);
        boundarySign_ = scalarList(boundaryFaces_.size(), scalar(1));
        Info<< type() << ' ' << name() << ": "
            << returnReduce(boundaryFaces_.size(), sumOp<label>())
            << " landing faces on " << landingPatches_ << endl;
        return;
    }

    const vector u(up());
    const surfaceVectorField& Sf = mesh_.Sf();
    const surfaceScalarField& magSf = mesh_.magSf();
    const surfaceVectorField& Cf = mesh_.Cf();

    DynamicList<label> iF;
    DynamicList<scalar> iS;
    for (label facei = 0; facei < mesh_.nInternalFaces(); ++facei)
    {
        const scalar nu = (Sf[facei] & u)/magSf[facei];
        if (mag(nu) > 0.999 && mag((Cf[facei] & u) - floorHeight_) < tolerance_)
        {
            iF.append(facei);
            iS.append(-sign(nu));
        }
    }

    DynamicList<labelPair> bF;
    DynamicList<scalar> bS;
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    forAll(pbm, patchi)
    {
        const polyPatch& pp = pbm[patchi];
        if (isA<emptyPolyPatch>(pp))
        {
            continue;
        }
        if (pp.coupled())
        {
            if (!isA<processorPolyPatch>(pp))
            {
                continue;
            }
            if (!refCast<const processorPolyPatch>(pp).owner())
            {
                continue;
            }
        }
        const vectorField& pSf = Sf.boundaryField()[patchi];
        const scalarField& pMagSf = magSf.boundaryField()[patchi];
        const vectorField& pCf = Cf.boundaryField()[patchi];
        forAll(pSf, facei)
        {
            const scalar nu = (pSf[facei] & u)/pMagSf[facei];
            if (mag(nu) > 0.999 && mag((pCf[facei] & u) - floorHeight_) < tolerance_)
            {
                bF.append(labelPair(patchi, facei));
                bS.append(-sign(nu));
            }
        }
    }

    internalFaces_.transfer(iF);
    internalSign_.transfer(iS);
    boundaryFaces_.transfer(bF);
    boundarySign_.transfer(bS);

    const label n = returnReduce
    (
        internalFaces_.size() + boundaryFaces_.size(),
        sumOp<label>()
    );
    if (n == 0)
    {
        FatalErrorInFunction
            << type() << ' ' << name() << ": no mesh face normal to gravity "
            << "at floorHeight " << floorHeight_ << " m (tolerance "
            << tolerance_ << " m)" << exit(FatalError);
    }
    Info<< type() << ' ' << name() << ": " << n << " floor faces at height "
        << floorHeight_ << " m" << endl;
}


void Foam::functionObjects::curtainDrift::writeFileHeader(Ostream& os)
{
    if (landingPatches_.empty())
    {
        writeHeader(os, "Curtain drift along the gas flow at the floor plane");
        writeHeaderValue(os, "floorHeight", floorHeight_);
    }
    else
    {
        writeHeader(os, "Curtain drift along the gas flow where the solids land");
        writeHeaderValue(os, "landingPatches", landingPatches_);
    }
    writeHeaderValue(os, "flowDirection", flowDir_);
    writeHeaderValue(os, "releasePatch", releasePatch_);
    writeCommented(os, "Time");
    forAll(solids_->names(), i)
    {
        const word& c = solids_->names()[i];
        writeTabbed(os, "drift_" + c);
        writeTabbed(os, "captured_" + c);
        if (lone_)
        {
            writeTabbed(os, "loneDrift_" + c);
        }
    }
    writeTabbed(os, "drift_bulk");
    writeTabbed(os, "captured_bulk");
    os  << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::curtainDrift::curtainDrift
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, dict),
    floorHeight_(0),
    flowDir_(1, 0, 0),
    tolerance_(1e-4),
    lone_(false),
    loneGasVelocity_(0)
{
    read(dict);
    writeFileHeader(file());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::curtainDrift::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);

    solids_.reset(new curtainSolids(mesh_));
    drag_.clear();
    drag_.setSize(solids_->size());
    forAll(drag_, i)
    {
        drag_.set(i, particleDragModel::New(solids_->drag(i)));
    }

    if (dict.found("releasePatch") == dict.found("releasePatches"))
    {
        FatalIOErrorInFunction(dict)
            << type() << ' ' << name() << ": give exactly one of "
            << "'releasePatch' (a patch) or 'releasePatches' (patch names or "
            << "regular expressions)" << exit(FatalIOError);
    }
    if (dict.found("releasePatch"))
    {
        releasePatch_ = dict.get<word>("releasePatch");
        const label id = mesh_.boundaryMesh().findPatchID(releasePatch_);
        if (id < 0)
        {
            FatalIOErrorInFunction(dict)
                << type() << ' ' << name() << ": releasePatch '" << releasePatch_
                << "' is not a patch of the mesh " << mesh_.boundaryMesh().names()
                << exit(FatalIOError);
        }
        releaseIDs_ = labelList(1, id);
    }
    else
    {
        const wordRes rp(dict.get<wordRes>("releasePatches"));
        releaseIDs_ = mesh_.boundaryMesh().patchSet(rp, false).sortedToc();
        if (releaseIDs_.empty())
        {
            FatalIOErrorInFunction(dict)
                << type() << ' ' << name() << ": releasePatches " << rp
                << " match no patch of the mesh " << mesh_.boundaryMesh().names()
                << exit(FatalIOError);
        }
        OStringStream os;
        os << rp;
        releasePatch_ = word::validate(os.str());
    }

    landingPatches_.clear();
    if (dict.found("landingPatches"))
    {
        if (dict.found("floorHeight"))
        {
            FatalIOErrorInFunction(dict)
                << type() << ' ' << name() << ": give 'floorHeight' (a plane) "
                << "or 'landingPatches', not both" << exit(FatalIOError);
        }
        landingPatches_ = dict.get<wordRes>("landingPatches");
        floorHeight_ = -GREAT;     // what leaves by lostPatches is all lost
    }
    else
    {
        floorHeight_ = dict.get<scalar>("floorHeight");
    }
    periodic_ = dict.getOrDefault<bool>("periodic", false);
    if (periodic_ && landingPatches_.empty())
    {
        FatalIOErrorInFunction(dict)
            << type() << ' ' << name() << ": 'periodic yes' measures the "
            << "drift of curtains landing on walls: it needs 'landingPatches'"
            << exit(FatalIOError);
    }
    flowDir_ = dict.get<vector>("flowDirection");
    if (mag(flowDir_) < SMALL)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'flowDirection' is a zero vector" << exit(FatalIOError);
    }
    flowDir_ /= mag(flowDir_);
    tolerance_ = dict.getOrDefault<scalar>("tolerance", 1e-4);

    binWidth_ = 0;
    lostPatches_.clear();
    if (dict.found("landing"))
    {
        const dictionary& ld = dict.subDict("landing");
        binWidth_ = ld.get<scalar>("binWidth");
        if (!(binWidth_ > 0))
        {
            FatalIOErrorInFunction(ld)
                << type() << ' ' << name() << ": landing/binWidth = " << binWidth_
                << " outside the allowed range (0 inf) m" << exit(FatalIOError);
        }
        const wordList lost(ld.get<wordList>("lostPatches"));
        DynamicList<label> ids;
        for (const word& pn : lost)
        {
            const label id = mesh_.boundaryMesh().findPatchID(pn);
            if (id < 0)
            {
                FatalIOErrorInFunction(ld)
                    << type() << ' ' << name() << ": landing/lostPatches: '" << pn
                    << "' is not a patch of the mesh " << mesh_.boundaryMesh().names()
                    << exit(FatalIOError);
            }
            ids.append(id);
        }
        lostPatches_.transfer(ids);
    }

    lone_ = dict.isDict("loneParticle");
    if (lone_ && !landingPatches_.empty())
    {
        FatalIOErrorInFunction(dict)
            << type() << ' ' << name() << ": loneParticle needs a floorHeight; "
            << "it is not available with landingPatches" << exit(FatalIOError);
    }
    if (lone_)
    {
        loneGasVelocity_ = dict.subDict("loneParticle").get<scalar>("gasVelocity");
        if (!(loneGasVelocity_ >= 0))
        {
            FatalIOErrorInFunction(dict)
                << "loneParticle: entry 'gasVelocity' = " << loneGasVelocity_
                << " outside the allowed range [0 inf) m/s"
                << exit(FatalIOError);
        }
    }

    selectFloorFaces();

    return true;
}


bool Foam::functionObjects::curtainDrift::execute()
{
    return true;
}


void Foam::functionObjects::curtainDrift::writeLanding() const
{
    const vector u(up());
    const surfaceVectorField& Cf = mesh_.Cf();

    // the bins span the floor faces' extent along the flow
    scalar xMin = GREAT, xMax = -GREAT;
    for (const label f : internalFaces_)
    {
        xMin = min(xMin, Cf[f] & flowDir_);
        xMax = max(xMax, Cf[f] & flowDir_);
    }
    for (const labelPair& pf : boundaryFaces_)
    {
        const scalar x = Cf.boundaryField()[pf.first()][pf.second()] & flowDir_;
        xMin = min(xMin, x);
        xMax = max(xMax, x);
    }
    reduce(xMin, minOp<scalar>());
    reduce(xMax, maxOp<scalar>());
    const label b0 = label(std::floor(xMin/binWidth_));
    const label nBins = label(std::floor(xMax/binWidth_)) - b0 + 1;

    const label n = solids_->size();
    List<scalarList> landed(n, scalarList(nBins, Zero)), landedX(n, scalarList(nBins, Zero));
    scalarList lost(n, Zero), inflow(n, Zero), inflowX(n, Zero);
    forAll(solids_->names(), i)
    {
        const word& c = solids_->names()[i];
        const scalar rhop = solids_->rho(i);
        const surfaceScalarField& alphaPhi =
            lookupObject<surfaceScalarField>(IOobject::groupName("alphaPhi", c));
        const auto bin = [&](const scalar x)
        {
            return min(max(label(std::floor(x/binWidth_)) - b0, label(0)), nBins - 1);
        };
        forAll(internalFaces_, k)
        {
            const label f = internalFaces_[k];
            const scalar x = Cf[f] & flowDir_;
            const scalar md = rhop*alphaPhi[f]*internalSign_[k];
            landed[i][bin(x)] += md;
            landedX[i][bin(x)] += md*x;
        }
        forAll(boundaryFaces_, k)
        {
            const label patchi = boundaryFaces_[k].first();
            const label f = boundaryFaces_[k].second();
            const scalar x = Cf.boundaryField()[patchi][f] & flowDir_;
            const scalar md = landed_(rhop*alphaPhi.boundaryField()[patchi][f]*boundarySign_[k]);
            landed[i][bin(x)] += md;
            landedX[i][bin(x)] += md*x;
        }
        for (const label patchi : lostPatches_)
        {
            const scalarField& pPhi = alphaPhi.boundaryField()[patchi];
            const vectorField& pCf = Cf.boundaryField()[patchi];
            forAll(pPhi, f)
            {
                if ((pCf[f] & u) > floorHeight_ && pPhi[f] > 0)
                {
                    lost[i] += rhop*pPhi[f];
                }
            }
        }
        for (const label slotID : releaseIDs_)
        {
            const scalarField& slotPhi = alphaPhi.boundaryField()[slotID];
            const vectorField& slotCf = Cf.boundaryField()[slotID];
            forAll(slotPhi, f)
            {
                // inflow only: a release patch of one class may be where
                // another lands
                const scalar phiIn = min(slotPhi[f], scalar(0));
                inflow[i] -= rhop*phiIn;
                inflowX[i] -= rhop*phiIn*(slotCf[f] & flowDir_);
            }
        }
        reduce(landed[i], sumOp<scalarList>());
        reduce(landedX[i], sumOp<scalarList>());
        reduce(lost[i], sumOp<scalar>());
        reduce(inflow[i], sumOp<scalar>());
        reduce(inflowX[i], sumOp<scalar>());
    }

    if (Pstream::master())
    {
        const fileName dir = baseTimeDir();
        mkDir(dir);
        OFstream os(dir/"landing.csv");
        os.precision(10);
        // x_centre_m: the mass centre of what crossed in the bin (nan if nothing)
        os  << "class,x_low_m,x_high_m,mass_flow_kg_s,fraction_of_inflow,x_centre_m" << nl;
        forAll(solids_->names(), i)
        {
            const word& c = solids_->names()[i];
            const scalar in = inflow[i] > VSMALL ? inflow[i] : NaN;
            os  << c << ",slot,slot," << inflow[i] << ",1," << inflowX[i]/in << nl;
            forAll(landed[i], b)
            {
                os  << c << ',' << (b0 + b)*binWidth_ << ',' << (b0 + b + 1)*binWidth_
                    << ',' << landed[i][b] << ',' << landed[i][b]/in << ','
                    << (mag(landed[i][b]) > VSMALL ? landedX[i][b]/landed[i][b] : NaN) << nl;
            }
            os  << c << ",lost,lost," << lost[i] << ',' << lost[i]/in << ",nan" << nl;
        }
        if (!os.good())
        {
            FatalErrorInFunction
                << type() << ' ' << name() << ": cannot write " << os.name()
                << exit(FatalError);
        }
    }
}


bool Foam::functionObjects::curtainDrift::write()
{
    const vector u(up());
    const surfaceVectorField& Cf = mesh_.Cf();

    const label n = solids_->size();
    scalarList drift(n, Zero), captured(n, Zero), loneDrift(n, Zero);
    scalar bulkFloor = 0, bulkFloorX = 0, bulkIn = 0, bulkInX = 0, bulkAxialFlux = 0;

    forAll(solids_->names(), i)
    {
        const word& c = solids_->names()[i];
        const scalar rhop = solids_->rho(i);
        const surfaceScalarField& alphaPhi =
            lookupObject<surfaceScalarField>(IOobject::groupName("alphaPhi", c));
        const volVectorField& Up =
            lookupObject<volVectorField>(IOobject::groupName("U", c));

        // Floor plane
        scalar m = 0, mx = 0;
        forAll(internalFaces_, k)
        {
            const label f = internalFaces_[k];
            const scalar md = rhop*alphaPhi[f]*internalSign_[k];
            m += md;
            mx += md*(Cf[f] & flowDir_);
        }
        forAll(boundaryFaces_, k)
        {
            const label patchi = boundaryFaces_[k].first();
            const label f = boundaryFaces_[k].second();
            const scalar md =
                landed_(rhop*alphaPhi.boundaryField()[patchi][f]*boundarySign_[k]);
            m += md;
            mx += md*(Cf.boundaryField()[patchi][f] & flowDir_);
        }

        // Release slot: inflow is a negative flux
        scalar mIn = 0, mInX = 0, mInH = 0, mInW = 0;
        for (const label slotID : releaseIDs_)
        {
            const scalarField& slotPhi = alphaPhi.boundaryField()[slotID];
            const vectorField& slotU = Up.boundaryField()[slotID];
            const vectorField& slotCf = Cf.boundaryField()[slotID];
            forAll(slotPhi, f)
            {
                const scalar md = -rhop*min(slotPhi[f], scalar(0));
                mIn += md;
                mInX += md*(slotCf[f] & flowDir_);
                mInH += md*(slotCf[f] & u);
                mInW += md*(-(slotU[f] & u));
            }
        }

        // Periodic segment: a landing position does not tell how far a
        // particle went (it may have crossed the periodic pair). At a steady
        // state each cell's solids outflow equals its inflow, so the sum
        // over faces of the flux times the axial step between the cell
        // centres it joins is the axial moment of what lands less that of
        // what is released (both at their cells' centres): the class's
        // inflow times its mean displacement, across the periodic pair too
        // (the step there is the transformed centre-to-centre vector; the
        // pair's two sides and the processor sides are each counted half).
        scalar axialFlux = 0;
        if (periodic_)
        {
            const tmp<surfaceVectorField> tdelta(mesh_.delta());
            const surfaceVectorField& delta = tdelta();
            axialFlux = rhop*sum(alphaPhi.primitiveField()*(delta.primitiveField() & flowDir_));
            forAll(mesh_.boundary(), patchi)
            {
                if (mesh_.boundary()[patchi].coupled())
                {
                    axialFlux += 0.5*rhop*sum
                    (
                        alphaPhi.boundaryField()[patchi]
                       *(delta.boundaryField()[patchi] & flowDir_)
                    );
                }
            }
            reduce(axialFlux, sumOp<scalar>());
        }

        reduce(m, sumOp<scalar>());
        reduce(mx, sumOp<scalar>());
        reduce(mIn, sumOp<scalar>());
        reduce(mInX, sumOp<scalar>());
        reduce(mInH, sumOp<scalar>());
        reduce(mInW, sumOp<scalar>());

        if (mIn <= 0)
        {
            WarningInFunction
                << type() << ' ' << name() << ": no inflow of " << c
                << " through " << releasePatch_ << endl;
            drift[i] = NaN;
            captured[i] = 0;
            loneDrift[i] = NaN;
            continue;
        }

        const scalar xRel = mInX/mIn;
        // A class of which (almost) nothing reaches the floor has no drift:
        // nan, not the mean position of round-off (tests/foam/curtainLimits)
        drift[i] = m > minCaptured*mIn ? mx/m - xRel : NaN;
        captured[i] = m/mIn;
        bulkFloor += m;
        bulkFloorX += mx;
        bulkIn += mIn;
        bulkInX += mInX;
        if (periodic_)
        {
            drift[i] = axialFlux/mIn;
            bulkAxialFlux += axialFlux;
        }

        if (lone_)
        {
            const scalar H = mInH/mIn - floorHeight_;
            particleDrag::Particle p;
            p.diameter = solids_->d(i);
            p.density = rhop;
            particleDrag::Gas gas;
            gas.density = solids_->rhoGas();
            gas.viscosity = solids_->muGas();
            particleDrag::FallIntegration opts;
            opts.constantK = false;
            opts.verticalDrag = true;
            opts.releaseVelocity = max(mInW/mIn, scalar(0));
            try
            {
                loneDrift[i] = particleDrag::integrateFall
                (
                    drag_[i].law(), p, gas, loneGasVelocity_, H, 0, opts
                ).advance;
            }
            catch (const std::exception& e)
            {
                FatalErrorInFunction
                    << type() << ' ' << name() << ": lone particle of class "
                    << c << ": " << e.what() << exit(FatalError);
            }
        }
    }

    if (binWidth_ > 0 && time_.writeTime())
    {
        writeLanding();
    }

    const scalar bulkDrift =
        periodic_
      ? (bulkIn > VSMALL ? bulkAxialFlux/bulkIn : NaN)
      : (bulkFloor > VSMALL && bulkIn > VSMALL)
      ? bulkFloorX/bulkFloor - bulkInX/bulkIn
      : NaN;
    const scalar bulkCaptured = bulkIn > VSMALL ? bulkFloor/bulkIn : 0;

    Info<< type() << ' ' << name() << " write:" << nl;
    forAll(solids_->names(), i)
    {
        Info<< "    " << solids_->names()[i] << ": drift " << drift[i]
            << " m, captured " << captured[i];
        if (lone_)
        {
            Info<< ", lone particle " << loneDrift[i] << " m";
        }
        Info<< nl;
    }
    Info<< "    bulk: drift " << bulkDrift << " m, captured " << bulkCaptured
        << nl << endl;

    // published for runTimeControl conditions (steadyWindow)
    forAll(solids_->names(), i)
    {
        setResult("drift_" + solids_->names()[i], drift[i]);
        setResult("captured_" + solids_->names()[i], captured[i]);
    }
    setResult("drift_bulk", bulkDrift);
    setResult("captured_bulk", bulkCaptured);

    if (Pstream::master())
    {
        OFstream& os = file();
        writeCurrentTime(os);
        forAll(drift, i)
        {
            os  << tab << drift[i] << tab << captured[i];
            if (lone_)
            {
                os  << tab << loneDrift[i];
            }
        }
        os  << tab << bulkDrift << tab << bulkCaptured << endl;
    }

    return true;
}


// ************************************************************************* //
