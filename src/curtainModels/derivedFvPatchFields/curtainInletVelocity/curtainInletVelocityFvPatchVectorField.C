/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "curtainInletVelocityFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::curtainInletVelocityFvPatchVectorField::
curtainInletVelocityFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF
)
:
    fixedValueFvPatchVectorField(p, iF),
    releaseVelocity_(0)
{}


Foam::curtainInletVelocityFvPatchVectorField::
curtainInletVelocityFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const dictionary& dict
)
:
    fixedValueFvPatchVectorField(p, iF, dict, false),
    releaseVelocity_(dict.get<scalar>("releaseVelocity"))
{
    if (!(releaseVelocity_ > 0 && releaseVelocity_ <= 100))
    {
        FatalIOErrorInFunction(dict)
            << "curtainInletVelocity: entry 'releaseVelocity' = "
            << releaseVelocity_ << " m/s outside the allowed range (0, 100] m/s"
            << exit(FatalIOError);
    }
    fvPatchVectorField::operator=(-releaseVelocity_*p.nf());
}


Foam::curtainInletVelocityFvPatchVectorField::
curtainInletVelocityFvPatchVectorField
(
    const curtainInletVelocityFvPatchVectorField& ptf,
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    fixedValueFvPatchVectorField(ptf, p, iF, mapper),
    releaseVelocity_(ptf.releaseVelocity_)
{}


Foam::curtainInletVelocityFvPatchVectorField::
curtainInletVelocityFvPatchVectorField
(
    const curtainInletVelocityFvPatchVectorField& ptf
)
:
    fixedValueFvPatchVectorField(ptf),
    releaseVelocity_(ptf.releaseVelocity_)
{}


Foam::curtainInletVelocityFvPatchVectorField::
curtainInletVelocityFvPatchVectorField
(
    const curtainInletVelocityFvPatchVectorField& ptf,
    const DimensionedField<vector, volMesh>& iF
)
:
    fixedValueFvPatchVectorField(ptf, iF),
    releaseVelocity_(ptf.releaseVelocity_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::curtainInletVelocityFvPatchVectorField::updateCoeffs()
{
    if (updated())
    {
        return;
    }
    operator==(-releaseVelocity_*patch().nf());
    fixedValueFvPatchVectorField::updateCoeffs();
}


void Foam::curtainInletVelocityFvPatchVectorField::write(Ostream& os) const
{
    fvPatchVectorField::write(os);
    os.writeEntry("releaseVelocity", releaseVelocity_);
    writeEntry("value", os);
}


namespace Foam
{
    makePatchTypeField
    (
        fvPatchVectorField,
        curtainInletVelocityFvPatchVectorField
    );
}

// ************************************************************************* //
