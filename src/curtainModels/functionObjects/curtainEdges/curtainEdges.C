/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "curtainEdges.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"
#include "uniformDimensionedFields.H"
#include "gravityMeshObject.H"

#include <limits>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(curtainEdges, 0);
    addToRunTimeSelectionTable(functionObject, curtainEdges, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::curtainEdges::curtainEdges
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, dict),
    flowDir_(1, 0, 0),
    alphaEdge_(curtainSolids::alphaEdgeDefault)
{
    read(dict);
    OFstream& os = file();
    writeHeader(os, "Curtain edges at solids fraction alphaEdge");
    writeHeaderValue(os, "alphaEdge", alphaEdge_);
    writeCommented(os, "Time");
    writeTabbed(os, "height");
    writeTabbed(os, "leading");
    writeTabbed(os, "trailing");
    writeTabbed(os, "lateralMin");
    writeTabbed(os, "lateralMax");
    os  << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::curtainEdges::read(const dictionary& dict)
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
    heights_ = dict.get<scalarList>("heights");
    if (heights_.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'heights' is empty" << exit(FatalIOError);
    }

    const uniformDimensionedVectorField& g = meshObjects::gravity::New(time_);
    const vector up(-g.value()/max(mag(g.value()), VSMALL));

    const pointField& pts = mesh_.points();
    const labelListList& cp = mesh_.cellPoints();
    cellLo_.setSize(mesh_.nCells());
    cellHi_.setSize(mesh_.nCells());
    forAll(cp, celli)
    {
        scalar lo = GREAT, hi = -GREAT;
        for (const label pi : cp[celli])
        {
            const scalar h = pts[pi] & up;
            lo = min(lo, h);
            hi = max(hi, h);
        }
        cellLo_[celli] = lo;
        cellHi_[celli] = hi;
    }
    return true;
}


bool Foam::functionObjects::curtainEdges::execute()
{
    return true;
}


bool Foam::functionObjects::curtainEdges::write()
{
    scalarField alphas(mesh_.nCells(), Zero);
    forAll(solids_->names(), i)
    {
        alphas += lookupObject<volScalarField>
        (
            IOobject::groupName("alpha", solids_->names()[i])
        ).primitiveField();
    }

    const uniformDimensionedVectorField& g = meshObjects::gravity::New(time_);
    const vector up(-g.value()/max(mag(g.value()), VSMALL));
    vector lateral(flowDir_ ^ up);
    lateral /= max(mag(lateral), VSMALL);

    const vectorField& C = mesh_.C().primitiveField();
    const scalar NaN = std::numeric_limits<scalar>::quiet_NaN();

    Info<< type() << ' ' << name() << " write:" << nl;
    forAll(heights_, k)
    {
        const scalar h = heights_[k];
        scalar lead = GREAT, trail = -GREAT, latMin = GREAT, latMax = -GREAT;
        forAll(C, celli)
        {
            if
            (
                alphas[celli] >= alphaEdge_
             && cellLo_[celli] <= h && h < cellHi_[celli]
            )
            {
                const scalar x = C[celli] & flowDir_;
                const scalar z = C[celli] & lateral;
                lead = min(lead, x);
                trail = max(trail, x);
                latMin = min(latMin, z);
                latMax = max(latMax, z);
            }
        }
        reduce(lead, minOp<scalar>());
        reduce(trail, maxOp<scalar>());
        reduce(latMin, minOp<scalar>());
        reduce(latMax, maxOp<scalar>());
        const bool found = trail >= lead;

        Info<< "    height " << h << " m: ";
        if (found)
        {
            Info<< "leading " << lead << ", trailing " << trail
                << ", lateral " << latMin << " to " << latMax << nl;
        }
        else
        {
            Info<< "no solids above " << alphaEdge_ << nl;
        }

        if (Pstream::master())
        {
            OFstream& os = file();
            writeCurrentTime(os);
            os  << tab << h;
            if (found)
            {
                os  << tab << lead << tab << trail << tab << latMin << tab
                    << latMax << endl;
            }
            else
            {
                os  << tab << NaN << tab << NaN << tab << NaN << tab << NaN
                    << endl;
            }
        }
    }
    Info<< endl;
    return true;
}


// ************************************************************************* //
