/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "curtainInletFvPatchScalarField.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"
#include "particleDrag/releaseLayer.hpp"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

namespace
{

Foam::scalar readInRange
(
    const Foam::dictionary& dict,
    const Foam::word& key,
    const Foam::scalar lo,
    const Foam::scalar hi,
    const Foam::word& units
)
{
    using namespace Foam;
    const scalar v = dict.get<scalar>(key);
    if (!(v > lo && v <= hi))
    {
        FatalIOErrorInFunction(dict)
            << "curtainInlet: entry '" << key << "' = " << v << ' ' << units
            << " outside the allowed range (" << lo << ", " << hi << "] "
            << units << exit(FatalIOError);
    }
    return v;
}

}


void Foam::curtainInletFvPatchScalarField::readEntries(const dictionary& dict)
{
    spillRate_ = readInRange(dict, "spillRate", 0, particleDrag::maxSpillRate, "kg/(m s)");
    thickness_ = readInRange(dict, "thickness", 0, 1, "m");
    rhoParticle_ = readInRange(dict, "rhoParticle", 0, 1e5, "kg/m3");
    alphaMax_ = dict.getOrDefault<scalar>("alphaMax", 0.62);
    if (!(alphaMax_ > 0 && alphaMax_ < 1))
    {
        FatalIOErrorInFunction(dict)
            << "curtainInlet: entry 'alphaMax' = " << alphaMax_
            << " outside the allowed range (0 1)" << exit(FatalIOError);
    }
    UName_ = dict.getOrDefault<word>("U", word::null);

    const bool one = dict.found("massFraction");
    const bool many = dict.isDict("massFractions");
    if (one == many)
    {
        FatalIOErrorInFunction(dict)
            << "curtainInlet: give exactly one of 'massFraction' (a single "
            << "class) or 'massFractions' { <class> <fraction>; ... }"
            << exit(FatalIOError);
    }
    if (one)
    {
        massFraction_ = dict.get<scalar>("massFraction");
        if (!(massFraction_ > 0 && massFraction_ <= 1))
        {
            FatalIOErrorInFunction(dict)
                << "curtainInlet: entry 'massFraction' = " << massFraction_
                << " outside the allowed range (0 1]" << exit(FatalIOError);
        }
    }
    else
    {
        massFractions_ = dict.subDict("massFractions");
        scalar sum = 0;
        for (const entry& e : massFractions_)
        {
            const scalar x = e.get<scalar>();
            if (!(x >= 0 && x <= 1))
            {
                FatalIOErrorInFunction(dict)
                    << "curtainInlet: massFractions entry '" << e.keyword()
                    << "' = " << x << " outside the allowed range [0 1]"
                    << exit(FatalIOError);
            }
            sum += x;
        }
        if (mag(sum - 1) > 1e-3)
        {
            FatalIOErrorInFunction(dict)
                << "curtainInlet: massFractions sum to " << sum
                << ", not 1 (tolerance 1e-3)" << exit(FatalIOError);
        }
        massFraction_ = -1;
    }
}


Foam::scalar Foam::curtainInletFvPatchScalarField::classMassFraction() const
{
    if (massFraction_ >= 0)
    {
        return massFraction_;
    }
    const word cls = internalField().group();
    if (!massFractions_.found(cls))
    {
        FatalErrorInFunction
            << "curtainInlet on patch " << patch().name() << " of field "
            << internalField().name() << ": no entry for class '" << cls
            << "' in massFractions " << massFractions_.toc()
            << exit(FatalError);
    }
    return massFractions_.get<scalar>(cls);
}


void Foam::curtainInletFvPatchScalarField::checkResolution()
{
    if (resolutionChecked_)
    {
        return;
    }
    resolutionChecked_ = true;

    // Bounding box of the slot and the widest face along each axis
    const pointField& pts = patch().patch().localPoints();
    const faceList& faces = patch().patch().localFaces();
    vector lo(vector::uniform(GREAT)), hi(vector::uniform(-GREAT));
    vector widest(Zero);
    for (const face& f : faces)
    {
        vector flo(vector::uniform(GREAT)), fhi(vector::uniform(-GREAT));
        for (const label pi : f)
        {
            flo = min(flo, pts[pi]);
            fhi = max(fhi, pts[pi]);
        }
        lo = min(lo, flo);
        hi = max(hi, fhi);
        widest = max(widest, fhi - flo);
    }
    reduce(lo, minOp<vector>());
    reduce(hi, maxOp<vector>());
    reduce(widest, maxOp<vector>());

    // The thinnest non-degenerate extent of a solved direction (not the
    // empty direction of a 2D mesh) is across the layer
    const vector extent(hi - lo);
    const scalar tol = 1e-9*mag(extent);
    const Vector<label>& solved = patch().boundaryMesh().mesh().geometricD();
    label across = -1;
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if
        (
            solved[d] > 0 && extent[d] > tol
         && (across < 0 || extent[d] < extent[across])
        )
        {
            across = d;
        }
    }
    if (across < 0 || widest[across] <= tol)
    {
        return;
    }
    const scalar nCells = extent[across]/widest[across];

    // What is resolved enough depends on the solids transport (windTunnel
    // mesh study, 2/4/8 cells across the half sheet): with a higher-order
    // correction (MULESCorr or deferredCorr) 2 cells are within 2.5 % of 8;
    // with implicit upwind alone 2 cells over-predict by about 30 % and 1 by
    // about 2x
    const fvMesh& mesh = patch().boundaryMesh().mesh();
    const dictionary& solvers = mesh.solutionDict().subOrEmptyDict("solvers");
    const dictionary alphaControls
    (
        solvers.found(internalField().name())
      ? solvers.subDict(internalField().name())
      : dictionary::null
    );
    const bool mules =
        alphaControls.getOrDefault<Switch>("MULESCorr", false)
     || alphaControls.getOrDefault<Switch>("deferredCorr", false);
    const scalar needed = mules ? 2 : 4;
    if (nCells < needed - 1e-6)
    {
        WarningInFunction
            << "curtainInlet on patch " << patch().name() << " of field "
            << internalField().name() << ": the slot is resolved by only "
            << nCells << " cell(s) across its " << extent[across]
            << " m thickness; the curtain is under-resolved and its drift "
            << (
                   mules
                 ? "over-predicted (2 cells across a half sheet are within "
                   "2.5 % of 8 with a higher-order correction, MULESCorr or "
                   "deferredCorr; fewer were not measured). "
                   "Use 2 or more."
                 : "over-predicted (about +30 % at 2 cells across a half "
                   "sheet, about 2x at 1 cell, with upwind solids transport; "
                   "MULESCorr or deferredCorr needs 2). Use 4 or more."
               )
            << endl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::curtainInletFvPatchScalarField::curtainInletFvPatchScalarField
(
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF
)
:
    fixedValueFvPatchScalarField(p, iF),
    spillRate_(0),
    thickness_(0),
    rhoParticle_(0),
    massFraction_(1),
    massFractions_(),
    alphaMax_(0.62),
    UName_()
{}


Foam::curtainInletFvPatchScalarField::curtainInletFvPatchScalarField
(
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF,
    const dictionary& dict
)
:
    fixedValueFvPatchScalarField(p, iF, dict, false),
    spillRate_(0),
    thickness_(0),
    rhoParticle_(0),
    massFraction_(1),
    massFractions_(),
    alphaMax_(0.62),
    UName_()
{
    readEntries(dict);
    if (dict.found("value"))
    {
        fvPatchScalarField::operator=(scalarField("value", dict, p.size()));
    }
    else
    {
        fvPatchScalarField::operator=(Zero);
    }
}


Foam::curtainInletFvPatchScalarField::curtainInletFvPatchScalarField
(
    const curtainInletFvPatchScalarField& ptf,
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    fixedValueFvPatchScalarField(ptf, p, iF, mapper),
    spillRate_(ptf.spillRate_),
    thickness_(ptf.thickness_),
    rhoParticle_(ptf.rhoParticle_),
    massFraction_(ptf.massFraction_),
    massFractions_(ptf.massFractions_),
    alphaMax_(ptf.alphaMax_),
    UName_(ptf.UName_)
{}


Foam::curtainInletFvPatchScalarField::curtainInletFvPatchScalarField
(
    const curtainInletFvPatchScalarField& ptf
)
:
    fixedValueFvPatchScalarField(ptf),
    spillRate_(ptf.spillRate_),
    thickness_(ptf.thickness_),
    rhoParticle_(ptf.rhoParticle_),
    massFraction_(ptf.massFraction_),
    massFractions_(ptf.massFractions_),
    alphaMax_(ptf.alphaMax_),
    UName_(ptf.UName_)
{}


Foam::curtainInletFvPatchScalarField::curtainInletFvPatchScalarField
(
    const curtainInletFvPatchScalarField& ptf,
    const DimensionedField<scalar, volMesh>& iF
)
:
    fixedValueFvPatchScalarField(ptf, iF),
    spillRate_(ptf.spillRate_),
    thickness_(ptf.thickness_),
    rhoParticle_(ptf.rhoParticle_),
    massFraction_(ptf.massFraction_),
    massFractions_(ptf.massFractions_),
    alphaMax_(ptf.alphaMax_),
    UName_(ptf.UName_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::curtainInletFvPatchScalarField::updateCoeffs()
{
    if (updated())
    {
        return;
    }

    checkResolution();

    const word UName =
        UName_.empty()
      ? IOobject::groupName("U", internalField().group())
      : UName_;

    if (!db().foundObject<volVectorField>(UName))
    {
        FatalErrorInFunction
            << "curtainInlet on patch " << patch().name() << " of field "
            << internalField().name() << ": velocity field " << UName
            << " not found (set entry 'U')" << exit(FatalError);
    }

    const fvPatchVectorField& Up =
        patch().lookupPatchField<volVectorField, vector>(UName);

    // Inward normal velocity: the release velocity
    const scalarField Un(-(Up & patch().nf()));
    if (gMin(Un) <= 0)
    {
        FatalErrorInFunction
            << "curtainInlet on patch " << patch().name() << " of field "
            << internalField().name() << ": the release velocity " << UName
            << " must point into the domain on every face (min inward "
            << "component " << gMin(Un) << " m/s)" << exit(FatalError);
    }

    const scalar x = classMassFraction();
    // S/(rho_p b v) per face (particleDrag::slotSolidsFraction, in this order of operations)
    const scalarField alpha(x*spillRate_/(rhoParticle_*thickness_*Un));

    const scalar aMax = gMax(alpha);
    if (aMax > alphaMax_)
    {
        FatalErrorInFunction
            << "curtainInlet on patch " << patch().name() << " of field "
            << internalField().name() << ": spill rate " << spillRate_
            << " kg/(m s) x mass fraction " << x << " through a "
            << thickness_ << " m layer at " << gMin(Un)
            << " m/s gives a solids fraction " << aMax
            << " above alphaMax " << alphaMax_
            << ": lower the spill rate or raise the thickness or the "
            << "release velocity" << exit(FatalError);
    }

    operator==(alpha);

    fixedValueFvPatchScalarField::updateCoeffs();
}


void Foam::curtainInletFvPatchScalarField::write(Ostream& os) const
{
    fvPatchScalarField::write(os);
    os.writeEntry("spillRate", spillRate_);
    os.writeEntry("thickness", thickness_);
    os.writeEntry("rhoParticle", rhoParticle_);
    if (massFraction_ >= 0)
    {
        os.writeEntry("massFraction", massFraction_);
    }
    else
    {
        os.beginBlock("massFractions");
        massFractions_.write(os, false);
        os.endBlock();
    }
    os.writeEntry("alphaMax", alphaMax_);
    if (!UName_.empty())
    {
        os.writeEntry("U", UName_);
    }
    writeEntry("value", os);
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField
    (
        fvPatchScalarField,
        curtainInletFvPatchScalarField
    );
}

// ************************************************************************* //
