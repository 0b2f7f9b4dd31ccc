/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "steadyWindow.H"
#include "addToRunTimeSelectionTable.H"
#include "Time.H"
#include "wordRes.H"
#include "exactText.H"

#include <cmath>

namespace Foam
{
namespace functionObjects
{
namespace runTimeControls
{
    defineTypeNameAndDebug(steadyWindow, 0);
    addToRunTimeSelectionTable(runTimeCondition, steadyWindow, dictionary);
}
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::runTimeControls::steadyWindow::storeState()
{
    conditionDict().set("firstTime", exactText::write(firstTime_));
    storeSamples();
}


void Foam::functionObjects::runTimeControls::steadyWindow::restoreState()
{
    const dictionary& d = conditionDict();
    if (!d.found("times"))
    {
        return;
    }
    firstTime_ = exactText::read(d.get<string>("firstTime"), "steadyWindow " + name_);
    if (!restoreSamples())
    {
        // the field list changed since the state was written: start over
        firstTime_ = -1;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::runTimeControls::steadyWindow::steadyWindow
(
    const word& name,
    const objectRegistry& obr,
    const dictionary& dict,
    stateFunctionObject& state
)
:
    sampledCondition(typeName, name, obr, dict, state),
    gates_(),
    gateMin_(dict.getOrDefault<scalar>("gateMin", 0)),
    window_(dict.get<scalar>("window")),
    tolerance_(dict.get<scalar>("tolerance")),
    absTolerance_(dict.getOrDefault<scalar>("absTolerance", 0)),
    startTime_(dict.getOrDefault<scalar>("startTime", -GREAT)),
    requireChecked_(dict.getOrDefault<bool>("requireChecked", false)),
    firstTime_(-1)
{
    refuseUnknown
    (
        dict,
        {"gates", "gateMin", "window", "tolerance", "absTolerance", "startTime", "requireChecked"}
    );
    if (!(window_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "steadyWindow " << name << ": entry 'window' = " << window_
            << " outside the allowed range (0, inf)" << exit(FatalIOError);
    }
    if (!(tolerance_ >= 0) || !(absTolerance_ >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "steadyWindow " << name << ": entries 'tolerance' = "
            << tolerance_ << " and 'absTolerance' = " << absTolerance_
            << " must be in [0, inf)" << exit(FatalIOError);
    }
    if (dict.found("gates"))
    {
        const dictionary& g = dict.subDict("gates");
        for (const word& key : g.toc())
        {
            if (!fieldNames_.found(key))
            {
                FatalIOErrorInFunction(g)
                    << "steadyWindow " << name << ": gate for '" << key
                    << "', which is not in 'fields' " << fieldNames_
                    << exit(FatalIOError);
            }
            gates_.set(key, g.get<word>(key));
        }
    }

    restoreState();
}


// * * * * * * * * * * * * * * Public Member Functions * * * * * * * * * * * //

bool Foam::functionObjects::runTimeControls::steadyWindow::apply()
{
    if (!active_)
    {
        return true;
    }

    const scalar t = obr_.time().value();
    const scalar eps = 1e-9*max(scalar(1), mag(t));

    // a sample of this time already taken (a restart re-applies nothing,
    // but runTimeControl may be executed twice at the final time)
    forgetRepeat(t, eps);

    List<scalar> now;
    if (!sampleNow(now))
    {
        return false;
    }

    if (firstTime_ < 0)
    {
        firstTime_ = t;
    }
    append(t, now);

    // keep the samples of the window [t - window, t]
    label drop = 0;
    while (drop < times_.size() && times_[drop] < t - window_ - eps)
    {
        ++drop;
    }
    if (drop)
    {
        DynamicList<scalar> kept(SubList<scalar>(times_, times_.size() - drop, drop));
        times_.transfer(kept);
        for (auto& v : values_)
        {
            DynamicList<scalar> keptV(SubList<scalar>(v, v.size() - drop, drop));
            v.transfer(keptV);
        }
    }
    storeState();

    const bool covered = t - firstTime_ >= window_ - eps && times_.size() >= 3;
    bool satisfied = covered && t >= startTime_ - eps;

    scalar worst = 0;
    word worstField;
    label nChecked = 0;
    forAll(fieldNames_, fieldi)
    {
        const word& f = fieldNames_[fieldi];
        if (gates_.found(f))
        {
            scalar gate = 0;
            if (!result(gates_[f], gate))
            {
                FatalErrorInFunction
                    << "steadyWindow " << name_ << ": function object "
                    << functionObjectName_ << " has no result '" << gates_[f]
                    << "' (gate of " << f << ")" << exit(FatalError);
            }
            if (!(gate >= gateMin_))
            {
                continue;
            }
        }
        ++nChecked;
        const DynamicList<scalar>& v = values_[fieldi];
        scalar lo = GREAT, hi = -GREAT;
        bool finite = true;
        for (const scalar x : v)
        {
            finite = finite && std::isfinite(x);
            lo = min(lo, x);
            hi = max(hi, x);
        }
        const scalar allowed = max(tolerance_*mag(v.last()), absTolerance_);
        const scalar ratio = finite ? (hi - lo)/max(allowed, VSMALL) : GREAT;
        if (ratio > worst)
        {
            worst = ratio;
            worstField = f;
        }
        if (!finite || hi - lo > allowed)
        {
            satisfied = false;
        }
    }

    if (requireChecked_ && nChecked == 0)
    {
        satisfied = false;
    }

    if (log)
    {
        Info<< "    " << type() << ": " << name_ << ": " << times_.size()
            << " samples over " << (t - times_.first())
            << " of window " << window_;
        if (worstField.size())
        {
            Info<< "; largest spread " << worst << " x allowed ("
                << worstField << ")";
        }
        else if (nChecked == 0)
        {
            Info<< "; every field gated out";
        }
        Info<< (satisfied ? "; steady" : "") << nl;
    }

    return satisfied;
}


void Foam::functionObjects::runTimeControls::steadyWindow::write()
{
    storeState();
}


// ************************************************************************* //
