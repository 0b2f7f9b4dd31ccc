/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "batchMeans.H"
#include "addToRunTimeSelectionTable.H"
#include "Time.H"

#include <cmath>

namespace Foam
{
namespace functionObjects
{
namespace runTimeControls
{
    defineTypeNameAndDebug(batchMeans, 0);
    addToRunTimeSelectionTable(runTimeCondition, batchMeans, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::runTimeControls::batchMeans::batchMeans
(
    const word& name,
    const objectRegistry& obr,
    const dictionary& dict,
    stateFunctionObject& state
)
:
    sampledCondition(typeName, name, obr, dict, state),
    batch_(dict.get<scalar>("batch")),
    minBatches_(dict.get<label>("minBatches")),
    tolerance_(dict.get<scalar>("tolerance")),
    absTolerance_(dict.getOrDefault<scalar>("absTolerance", 0)),
    startTime_(dict.getOrDefault<scalar>("startTime", -GREAT))
{
    refuseUnknown(dict, {"batch", "minBatches", "tolerance", "absTolerance", "startTime"});
    if (!(batch_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "batchMeans " << name << ": entry 'batch' = " << batch_
            << " outside the allowed range (0, inf)" << exit(FatalIOError);
    }
    if (minBatches_ < 2)
    {
        FatalIOErrorInFunction(dict)
            << "batchMeans " << name << ": entry 'minBatches' = " << minBatches_
            << " outside the allowed range [2, inf) (a standard error needs"
            << " two batches)" << exit(FatalIOError);
    }
    if (!(tolerance_ >= 0) || !(absTolerance_ >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "batchMeans " << name << ": entries 'tolerance' = "
            << tolerance_ << " and 'absTolerance' = " << absTolerance_
            << " must be in [0, inf)" << exit(FatalIOError);
    }

    restoreSamples();
}


// * * * * * * * * * * * * * * Public Member Functions * * * * * * * * * * * //

bool Foam::functionObjects::runTimeControls::batchMeans::apply()
{
    if (!active_)
    {
        return true;
    }

    const scalar t = obr_.time().value();
    const scalar eps = 1e-9*max(scalar(1), mag(t));

    // a sample of this time already taken (runTimeControl may be executed
    // twice at the final time)
    forgetRepeat(t, eps);
    if (t <= startTime_ + eps)
    {
        return false;
    }

    List<scalar> now;
    if (!sampleNow(now))
    {
        return false;
    }
    append(t, now);
    storeSamples();

    // the last nb whole batches, counted back from t: samples in (t - nb b, t]
    const label nb = label(std::floor((t - startTime_ + eps)/batch_));
    const scalar from = t - nb*batch_;
    // batch means of every field, in time order
    List<List<scalar>> m(fieldNames_.size(), List<scalar>(max(nb, label(0)), Zero));
    bool complete = nb >= 2;
    bool finite = true;
    forAll(fieldNames_, fieldi)
    {
        List<label> count(max(nb, label(0)), 0);
        forAll(times_, i)
        {
            if (times_[i] <= from + eps)
            {
                continue;
            }
            const label j = min(nb - 1, label(std::floor((times_[i] - from - eps)/batch_)));
            m[fieldi][j] += values_[fieldi][i];
            ++count[j];
            finite = finite && std::isfinite(values_[fieldi][i]);
        }
        forAll(count, j)
        {
            if (count[j])
            {
                m[fieldi][j] /= count[j];
            }
            else
            {
                complete = false;
            }
        }
    }
    // the start-up transient: the first d batches are dropped, d <= nb/2 the
    // MSER truncation (White 1997: least sum (m_j - mean)^2/(n - d)^2 over
    // the batches kept), the largest d of the fields (one window for all)
    label drop = 0;
    if (complete)
    {
        forAll(fieldNames_, fieldi)
        {
            scalar best = GREAT;
            label bestD = 0;
            for (label d = 0; d <= nb/2; ++d)
            {
                const label n = nb - d;
                scalar mean = 0;
                for (label j = d; j < nb; ++j) mean += m[fieldi][j];
                mean /= n;
                scalar ss = 0;
                for (label j = d; j < nb; ++j) ss += sqr(m[fieldi][j] - mean);
                const scalar z = ss/sqr(scalar(n));
                if (z < best)
                {
                    best = z;
                    bestD = d;
                }
            }
            drop = max(drop, bestD);
        }
    }
    const label kept = nb - drop;
    const scalar windowStart = from + drop*batch_;
    bool satisfied = complete && finite && kept >= minBatches_;
    scalar worst = 0;
    word worstField;
    List<scalar> means(fieldNames_.size(), GREAT), ses(fieldNames_.size(), GREAT);
    if (complete && kept >= 2)
    {
        forAll(fieldNames_, fieldi)
        {
            scalar mean = 0;
            for (label j = drop; j < nb; ++j) mean += m[fieldi][j];
            mean /= kept;
            scalar ss = 0;
            for (label j = drop; j < nb; ++j) ss += sqr(m[fieldi][j] - mean);
            const scalar se = std::sqrt(ss/(kept*(kept - 1)));
            means[fieldi] = mean;
            ses[fieldi] = se;
            const scalar allowed = max(tolerance_*mag(mean), absTolerance_);
            const scalar ratio = finite ? se/max(allowed, VSMALL) : GREAT;
            if (ratio > worst)
            {
                worst = ratio;
                worstField = fieldNames_[fieldi];
            }
            if (!finite || !(se <= allowed))
            {
                satisfied = false;
            }
        }
    }
    else
    {
        satisfied = false;
    }

    // the window, for whatever reads the run: the same samples
    state_.setResult(name_ + "_windowStart", windowStart);
    state_.setResult(name_ + "_batches", scalar(kept));
    state_.setResult(name_ + "_known", scalar(satisfied ? 1 : 0));
    forAll(fieldNames_, fieldi)
    {
        state_.setResult(name_ + "_" + fieldNames_[fieldi] + "_mean", means[fieldi]);
        state_.setResult(name_ + "_" + fieldNames_[fieldi] + "_se", ses[fieldi]);
    }

    if (log)
    {
        Info<< "    " << type() << ": " << name_ << ": " << nb
            << " batches of " << batch_ << " from " << from << ", the first "
            << drop << " dropped (start-up)";
        if (worstField.size())
        {
            Info<< "; largest standard error " << worst << " x allowed ("
                << worstField << ")";
        }
        Info<< (satisfied ? "; mean known" : "") << nl;
    }

    return satisfied;
}


void Foam::functionObjects::runTimeControls::batchMeans::write()
{
    storeSamples();
}


// ************************************************************************* //
