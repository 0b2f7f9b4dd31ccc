/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "solidsMassBalance.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"
#include "surfaceFields.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(solidsMassBalance, 0);
    addToRunTimeSelectionTable(functionObject, solidsMassBalance, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::solidsMassBalance::rates
(
    const label i,
    scalar& in,
    scalar& out
) const
{
    const surfaceScalarField& alphaPhi = lookupObject<surfaceScalarField>
    (
        IOobject::groupName("alphaPhi", solids_->names()[i])
    );
    const scalar rhop = solids_->rho(i);
    in = 0;
    out = 0;
    forAll(alphaPhi.boundaryField(), patchi)
    {
        const fvsPatchScalarField& pf = alphaPhi.boundaryField()[patchi];
        if (pf.coupled())
        {
            continue;
        }
        forAll(pf, facei)
        {
            if (pf[facei] < 0)
            {
                in -= rhop*pf[facei];
            }
            else
            {
                out += rhop*pf[facei];
            }
        }
    }
    reduce(in, sumOp<scalar>());
    reduce(out, sumOp<scalar>());
}


Foam::scalar Foam::functionObjects::solidsMassBalance::mass
(
    const label i,
    const bool old
) const
{
    const volScalarField& alpha = lookupObject<volScalarField>
    (
        IOobject::groupName("alpha", solids_->names()[i])
    );
    const scalarField& a =
        old ? alpha.oldTime().primitiveField() : alpha.primitiveField();
    return solids_->rho(i)*gSum(a*mesh_.V().field());
}


void Foam::functionObjects::solidsMassBalance::writeFileHeader(Ostream& os)
{
    writeHeader(os, "Solids mass balance [kg/s, kg]");
    writeCommented(os, "Time");
    forAll(solids_->names(), i)
    {
        const word& c = solids_->names()[i];
        writeTabbed(os, "in_" + c);
        writeTabbed(os, "out_" + c);
        writeTabbed(os, "mass_" + c);
    }
    writeTabbed(os, "in");
    writeTabbed(os, "out");
    writeTabbed(os, "mass");
    writeTabbed(os, "steadyImbalance");
    writeTabbed(os, "cumIn");
    writeTabbed(os, "cumOut");
    writeTabbed(os, "accumulated");
    writeTabbed(os, "relImbalance");
    os  << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::solidsMassBalance::solidsMassBalance
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, dict),
    started_(false),
    lastTimeIndex_(-1)
{
    read(dict);
    writeFileHeader(file());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::solidsMassBalance::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);
    solids_.reset(new curtainSolids(mesh_));
    M0_.setSize(solids_->size(), Zero);
    cumIn_.setSize(solids_->size(), Zero);
    cumOut_.setSize(solids_->size(), Zero);
    started_ = false;
    return true;
}


bool Foam::functionObjects::solidsMassBalance::execute()
{
    if (time_.timeIndex() == lastTimeIndex_)
    {
        return true;
    }
    lastTimeIndex_ = time_.timeIndex();

    const scalar dt = time_.deltaTValue();
    forAll(solids_->names(), i)
    {
        if (!started_)
        {
            // The state before the first step of this run
            M0_[i] = mass(i, true);
        }
        scalar in, out;
        rates(i, in, out);
        cumIn_[i] += dt*in;
        cumOut_[i] += dt*out;
    }
    started_ = true;
    return true;
}


bool Foam::functionObjects::solidsMassBalance::write()
{
    scalar inT = 0, outT = 0, MT = 0, cumInT = 0, cumOutT = 0, M0T = 0;
    List<FixedList<scalar, 3>> rows(solids_->size());
    forAll(solids_->names(), i)
    {
        scalar in, out;
        rates(i, in, out);
        const scalar M = mass(i);
        rows[i][0] = in;
        rows[i][1] = out;
        rows[i][2] = M;
        inT += in;
        outT += out;
        MT += M;
        cumInT += cumIn_[i];
        cumOutT += cumOut_[i];
        M0T += M0_[i];
    }
    const scalar steady = inT > VSMALL ? (inT - outT)/inT : 0;
    const scalar accumulated = MT - M0T;
    const scalar imbalance = accumulated - (cumInT - cumOutT);
    const scalar rel = cumInT > VSMALL ? imbalance/cumInT : 0;

    Info<< type() << ' ' << name() << " write:" << nl
        << "    solids in " << inT << " kg/s, out " << outT
        << " kg/s, in domain " << MT << " kg, (in - out)/in " << steady << nl
        << "    since start: in " << cumInT << " kg, out " << cumOutT
        << " kg, accumulated " << accumulated << " kg, imbalance "
        << imbalance << " kg (" << rel << " of the inflow)" << nl << endl;

    if (Pstream::master())
    {
        OFstream& os = file();
        writeCurrentTime(os);
        forAll(rows, i)
        {
            os  << tab << rows[i][0] << tab << rows[i][1] << tab << rows[i][2];
        }
        os  << tab << inT << tab << outT << tab << MT << tab << steady
            << tab << cumInT << tab << cumOutT << tab << accumulated
            << tab << rel << endl;
    }
    return true;
}


// ************************************************************************* //
