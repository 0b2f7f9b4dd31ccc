/*---------------------------------------------------------------------------*\
  flightedDryer: OpenFOAM library for falling curtains in flighted dryers
\*---------------------------------------------------------------------------*/

#include "turbulentDispersionModel.H"
#include "refuseUnknownEntries.H"

namespace Foam
{
    defineTypeNameAndDebug(turbulentDispersionModel, 0);
    defineRunTimeSelectionTable(turbulentDispersionModel, dictionary);
}


Foam::turbulentDispersionModel::turbulentDispersionModel(const dictionary& dict)
:
    dict_(dict)
{}


void Foam::turbulentDispersionModel::checkEntries(const wordList& allowed) const
{
    refuseUnknownEntries
    (
        dict_, allowed, "of turbulentDispersion (type " + dict_.get<word>("type") + ")", "type"
    );
}


Foam::scalar Foam::turbulentDispersionModel::coeff
(
    const word& entry,
    scalar deflt,
    scalar lo,
    scalar hi,
    bool loOpen
) const
{
    const scalar v = dict_.getOrDefault<scalar>(entry, deflt);
    if (!((loOpen ? v > lo : v >= lo) && v <= hi))
    {
        FatalIOErrorInFunction(dict_)
            << "Entry '" << entry << "' = " << v << " of turbulentDispersion outside the allowed range "
            << (loOpen ? "(" : "[") << lo << " " << hi << "]" << exit(FatalIOError);
    }
    return v;
}


Foam::autoPtr<Foam::turbulentDispersionModel>
Foam::turbulentDispersionModel::New(const dictionary& curtainProperties)
{
    dictionary dict;
    if (curtainProperties.isDict("turbulentDispersion"))
    {
        dict = curtainProperties.subDict("turbulentDispersion");
    }
    else
    {
        dict.name() = curtainProperties.name() + ".turbulentDispersion";
        dict.add("type", word("none"));
    }
    const word modelType(dict.get<word>("type"));
    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);
    if (!cstrIter.found())
    {
        string valid;
        for (const word& t : dictionaryConstructorTablePtr_->sortedToc())
        {
            valid += (valid.empty() ? "" : ", ") + t;
        }
        FatalIOErrorInFunction(dict)
            << "Entry 'type' = " << modelType << " of turbulentDispersion: valid types are "
            << valid.c_str() << exit(FatalIOError);
    }
    return autoPtr<turbulentDispersionModel>(cstrIter()(dict));
}
