#include "drum/drift/autoDrift.hpp"

#include "drum/io/inputError.hpp"

#include <cmath>
#include <sstream>

namespace drum
{

AutoDrift::AutoDrift
(
    std::shared_ptr<const DriftTable> table,
    std::shared_ptr<const DriftModel> insideModel,
    std::shared_ptr<const PorousSheetDrift> reduced,
    std::shared_ptr<const DriftModel> isolated,
    AutoDriftOptions options,
    std::shared_ptr<const DriftModel> outsideModel
)
:
    table_(std::move(table)),
    inside_(std::move(insideModel)),
    reduced_(std::move(reduced)),
    isolated_(std::move(isolated)),
    outside_(outsideModel ? std::move(outsideModel) : reduced_),
    options_(options),
    counters_(std::make_shared<Counters>())
{
    if (!reduced_ || !isolated_ || (table_ && !inside_))
    {
        throw InputError("", "model.drift", "auto: the reduced and isolated models (and, with a table, its model) are required");
    }
    requireInRange(options_.diluteRatio, 0.5, 1.0, "drift.auto.diluteRatio");
    requireInRange(options_.fixedAxisTolerance, 0.0, 1.0, "drift.auto.fixedAxisTolerance");
}


AutoDrift::Choice AutoDrift::choose(const DriftQuery& q, std::string* why, int* axis) const
{
    if (axis) *axis = -1;
    const double ratio = reduced_->velocityRatio(q);
    if (ratio >= options_.diluteRatio)
    {
        if (why)
        {
            std::ostringstream os;
            os << "dilute curtain: porousSheet V_c/V_g = " << ratio << " >= " << options_.diluteRatio;
            *why = os.str();
        }
        return dilute;
    }
    if (!table_)
    {
        if (why) *why = "no drift table given";
        return outside;
    }
    const std::array<double, driftAxisCount> x{{q.gasVelocity, q.spillRate, q.fallHeight,
                                                q.flightLength, q.particleDensity, q.particleDiameter}};
    for (int a = 0; a < driftAxisCount; ++a)
    {
        const auto& nodes = table_->nodes(a);
        double lo = nodes.front(), hi = nodes.back();
        if (nodes.size() == 1)
        {
            lo *= 1 - options_.fixedAxisTolerance;
            hi *= 1 + options_.fixedAxisTolerance;
        }
        if (a == fallHeightAxis)
        {
            lo = 0;     // the table's exact anchor below its smallest height
        }
        // the swept range within the table's node tolerance (a query at a node
        // computed in other units, 582e-6 as 582*1e-6, is on it)
        const bool in = nodes.size() == 1 ? x[a] >= lo && x[a] <= hi
                      : a == fallHeightAxis ? x[a] >= 0 && table_->inRange(a, std::max(x[a], nodes.front()))
                      : table_->inRange(a, x[a]);
        if (!in)
        {
            if (why)
            {
                std::ostringstream os;
                os << driftAxisName(a) << " = " << x[a] << " outside the table's ["
                   << lo << ", " << hi << "]" << (nodes.size() == 1 ? " (fixed axis +- tolerance)" : "");
                *why = os.str();
            }
            if (axis) *axis = a;
            return outside;
        }
    }
    if (why) *why = "inside the table's swept range";
    return inside;
}


std::string AutoDrift::modelName(Choice c) const
{
    switch (c)
    {
        case dilute: return isolated_->name();
        case inside: return inside_ ? inside_->name() : "(none)";
        case outside: return outside_->name();
    }
    return "?";
}


double AutoDrift::displacement(const DriftQuery& q) const
{
    std::string why;
    int axis = -1;
    const Choice c = choose(q, &why, &axis);
    ++counters_->n[c];
    if (axis >= 0) ++counters_->outsideOn[axis];
    if (c == outside && !counters_->outsideNoted.exchange(true))
    {
        counters_->firstOutside = why;
    }
    switch (c)
    {
        case dilute: return isolated_->displacement(q);
        case inside: return inside_->displacement(q);
        case outside: break;
    }
    return outside_->displacement(q);
}


std::string AutoDrift::summary() const
{
    const long total = count(dilute) + count(inside) + count(outside);
    std::ostringstream os;
    os << "auto drift: " << total << " queries: "
       << count(dilute) << " " << modelName(dilute) << " (dilute curtains, porousSheet V_c/V_g >= "
       << options_.diluteRatio << "), "
       << count(inside) << " " << modelName(inside) << " (inside the CFD table"
       << (table_ ? " " + table_->file().filename().string() : std::string(": none given")) << "), "
       << count(outside) << " " << modelName(outside) << " (outside the table";
    if (count(outside) > 0 && counters_->outsideNoted.load())
    {
        os << "; by the first axis out:";
        for (int a = 0; a < driftAxisCount; ++a)
        {
            if (const long k = counters_->outsideOn[a].load()) os << " " << driftAxisName(a) << " " << k;
        }
        os << "; first: " << counters_->firstOutside
           << "; for CFD accuracy there, run curtainCase at those conditions or widen the "
              "buildDriftTable grid";
    }
    os << ")";
    return os.str();
}

} // namespace drum
