/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "loneParticle.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

#include "particleDrag/loneParticleFall.hpp"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(loneParticle, 0);
    addToRunTimeSelectionTable(functionObject, loneParticle, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::functionObjects::loneParticle::readChecked
(
    const dictionary& dict,
    const word& key,
    const scalar lo,
    const scalar hi,
    const bool openLo,
    const word& range
)
{
    const scalar value = dict.get<scalar>(key);
    const bool ok = (openLo ? value > lo : value >= lo) && value < hi;
    if (!ok)
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' = " << value
            << " outside the allowed range " << range
            << exit(FatalIOError);
    }
    return value;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::loneParticle::loneParticle
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    timeFunctionObject(name, runTime),
    writeFile(runTime, name, typeName, dict),
    rhoGas_(0),
    muGas_(0),
    rhoParticle_(0),
    gasVelocity_(0),
    fallHeight_(0),
    incline_(0),
    written_(false)
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::loneParticle::read(const dictionary& dict)
{
    timeFunctionObject::read(dict);
    writeFile::read(dict);

    drag_ = particleDragModel::New(dict.subDict("drag"));

    rhoGas_ = readChecked(dict, "rhoGas", 0, GREAT, true, "(0 inf)");
    muGas_ = readChecked(dict, "muGas", 0, GREAT, true, "(0 inf)");
    rhoParticle_ = readChecked(dict, "rhoParticle", rhoGas_, GREAT, true, "(rhoGas inf)");
    gasVelocity_ = readChecked(dict, "gasVelocity", 0, GREAT, false, "[0 inf)");
    fallHeight_ = readChecked(dict, "fallHeight", 0, GREAT, true, "(0 inf)");
    incline_ = readChecked(dict, "incline", -90, 90, true, "(-90 90) deg");
    if (incline_ <= -90)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'incline' = " << incline_
            << " outside the allowed range (-90 90) deg" << exit(FatalIOError);
    }

    diameters_ = dict.get<scalarList>("diameters");
    if (diameters_.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'diameters' is empty: give at least one diameter [m]"
            << exit(FatalIOError);
    }
    forAll(diameters_, i)
    {
        if (!(diameters_[i] > 0))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'diameters' element " << i << " = " << diameters_[i]
                << " outside the allowed range (0 inf) m"
                << exit(FatalIOError);
        }
    }

    written_ = false;
    return true;
}


bool Foam::functionObjects::loneParticle::execute()
{
    return true;
}


bool Foam::functionObjects::loneParticle::write()
{
    if (written_)
    {
        return true;
    }
    written_ = true;

    const particleDrag::DragLaw& law = drag_->law();
    particleDrag::Gas gas;
    gas.density = rhoGas_;
    gas.viscosity = muGas_;
    const scalar alpha = incline_*constant::mathematical::pi/180.0;

    Info<< type() << ' ' << name() << ": lone particles, drag "
        << word(law.name()) << ", V_g " << gasVelocity_ << " m/s, fall "
        << fallHeight_ << " m" << nl;

    if (Pstream::master())
    {
        OFstream& os = file();
        writeHeader(os, "Lone-particle fall (Sherritt 1991 Eqs 12-19)");
        writeCommented(os, "d_m");
        writeTabbed(os, "Re");
        writeTabbed(os, "Cd");
        writeTabbed(os, "K_per_m");
        writeTabbed(os, "terminalVelocity_m_s");
        writeTabbed(os, "fallTime_s");
        writeTabbed(os, "drift_m");
        writeTabbed(os, "driftVariableCd_m");
        os  << nl;
    }

    forAll(diameters_, i)
    {
        particleDrag::Particle p;
        p.diameter = diameters_[i];
        p.density = rhoParticle_;

        const scalar Re = rhoGas_*gasVelocity_*p.diameter/muGas_;
        const scalar Cd = drag_->Cd(Re);
        const scalar K = gasVelocity_ > 0
            ? particleDrag::dragParameter(law, p, gas, gasVelocity_) : GREAT;
        const scalar vt = particleDrag::terminalVelocity(law, p, gas);
        const scalar tf = particleDrag::fallTime(fallHeight_);
        const scalar drift = particleDrag::loneParticleAdvance
        (
            law, p, gas, gasVelocity_, fallHeight_, alpha
        );
        particleDrag::FallIntegration opts;
        opts.constantK = false;
        const scalar driftVar = particleDrag::integrateFall
        (
            law, p, gas, gasVelocity_, fallHeight_, alpha, opts
        ).advance;

        Info<< "    d " << p.diameter << " m: Re " << Re << ", Cd " << Cd
            << ", terminal velocity " << vt << " m/s, drift " << drift
            << " m (variable Cd " << driftVar << " m)" << nl;

        if (Pstream::master())
        {
            OFstream& os = file();
            os  << p.diameter << tab << Re << tab << Cd << tab << K << tab
                << vt << tab << tf << tab << drift << tab << driftVar << nl;
        }
    }
    Info<< endl;

    return true;
}


// ************************************************************************* //
