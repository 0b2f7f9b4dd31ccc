/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "sampledCondition.H"
#include "exactText.H"


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::runTimeControls::sampledCondition::sampledCondition
(
    const word& kind,
    const word& name,
    const objectRegistry& obr,
    const dictionary& dict,
    stateFunctionObject& state
)
:
    runTimeCondition(name, obr, dict, state),
    kind_(kind),
    functionObjectName_(dict.get<word>("functionObject")),
    fieldNames_(dict.get<wordList>("fields")),
    times_(),
    values_(fieldNames_.size())
{
    if (fieldNames_.empty())
    {
        FatalIOErrorInFunction(dict)
            << kind_ << " " << name << ": entry 'fields' is empty"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::runTimeControls::sampledCondition::refuseUnknown
(
    const dictionary& dict,
    const wordList& own
) const
{
    // A misspelt entry would silently be ignored: refuse it
    wordList allowed({"type", "functionObject", "fields"});
    allowed.append(own);
    allowed.append(wordList({"groupID", "active", "log"}));
    for (const word& key : dict.toc())
    {
        if (!allowed.found(key))
        {
            FatalIOErrorInFunction(dict)
                << kind_ << " " << name_ << ": unknown entry '" << key
                << "'; allowed entries: " << allowed << exit(FatalIOError);
        }
    }
}


bool Foam::functionObjects::runTimeControls::sampledCondition::result
(
    const word& entry,
    scalar& value
) const
{
    return state_.getObjectResult<scalar>(functionObjectName_, entry, value);
}


void Foam::functionObjects::runTimeControls::sampledCondition::forgetRepeat
(
    const scalar t,
    const scalar eps
)
{
    if (times_.size() && mag(times_.last() - t) <= eps)
    {
        times_.remove();
        for (auto& v : values_)
        {
            v.remove();
        }
    }
}


bool Foam::functionObjects::runTimeControls::sampledCondition::sampleNow
(
    List<scalar>& now
) const
{
    now.setSize(fieldNames_.size());
    forAll(fieldNames_, fieldi)
    {
        if (!result(fieldNames_[fieldi], now[fieldi]))
        {
            WarningInFunction
                << kind_ << " " << name_ << ": function object "
                << functionObjectName_ << " has published no result '"
                << fieldNames_[fieldi] << "' (yet)" << endl;
            return false;
        }
    }
    return true;
}


void Foam::functionObjects::runTimeControls::sampledCondition::append
(
    const scalar t,
    const List<scalar>& now
)
{
    times_.append(t);
    forAll(fieldNames_, fieldi)
    {
        values_[fieldi].append(now[fieldi]);
    }
}


void Foam::functionObjects::runTimeControls::sampledCondition::storeSamples()
{
    dictionary& d = conditionDict();
    List<string> t(times_.size());
    forAll(times_, i)
    {
        t[i] = exactText::write(times_[i]);
    }
    d.set("times", t);
    forAll(fieldNames_, fieldi)
    {
        List<string> v(values_[fieldi].size());
        forAll(v, i)
        {
            v[i] = exactText::write(values_[fieldi][i]);
        }
        d.set(fieldNames_[fieldi], v);
    }
}


bool Foam::functionObjects::runTimeControls::sampledCondition::restoreSamples()
{
    const dictionary& d = conditionDict();
    if (!d.found("times"))
    {
        return false;
    }
    const word owner(kind_ + " " + name_);
    times_.clear();
    for (const string& s : d.get<List<string>>("times"))
    {
        times_.append(exactText::read(s, owner));
    }
    forAll(fieldNames_, fieldi)
    {
        values_[fieldi].clear();
        if (!d.found(fieldNames_[fieldi]))
        {
            // the field list changed since the state was written: start over
            times_.clear();
            for (auto& v : values_)
            {
                v.clear();
            }
            return false;
        }
        for (const string& s : d.get<List<string>>(fieldNames_[fieldi]))
        {
            values_[fieldi].append(exactText::read(s, owner));
        }
        if (values_[fieldi].size() != times_.size())
        {
            FatalErrorInFunction
                << owner << ": the stored state has " << values_[fieldi].size()
                << " values of " << fieldNames_[fieldi] << " for "
                << times_.size() << " sample times" << exit(FatalError);
        }
    }
    return true;
}


// ************************************************************************* //
