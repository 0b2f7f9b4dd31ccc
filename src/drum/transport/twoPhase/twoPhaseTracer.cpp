#include "drum/transport/twoPhase/twoPhaseTracer.hpp"

#include "drum/io/inputError.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace drum
{

namespace
{

// Profile quantities at a distance from the discharge (linear between points)
struct Local
{
    double H, H1, Q, F2;
    std::vector<double> A, xd;
};

Local interpolate(const std::vector<TwoPhaseProfilePoint>& p, double s)
{
    std::size_t k = 0;
    while (k + 2 < p.size() && p[k + 1].distanceFromDischarge < s)
    {
        ++k;
    }
    const auto& a = p[k];
    const auto& b = p[std::min(k + 1, p.size() - 1)];
    const double span = b.distanceFromDischarge - a.distanceFromDischarge;
    const double w = span > 0 ? std::clamp((s - a.distanceFromDischarge)/span, 0.0, 1.0) : 0.0;
    auto mix = [w](double x, double y) { return (1 - w)*x + w*y; };
    Local l;
    l.H = mix(a.holdup, b.holdup);
    l.H1 = mix(a.airborneHoldup, b.airborneHoldup);
    l.Q = mix(a.circulation, b.circulation);
    l.F2 = mix(a.denseFlow, b.denseFlow);
    for (std::size_t i = 0; i < a.airborneCapacity.size(); ++i)
    {
        l.A.push_back(mix(a.airborneCapacity[i], b.airborneCapacity[i]));
        l.xd.push_back(mix(a.holdupFractions[i], b.holdupFractions[i]));
    }
    return l;
}

// Rate-matrix builder: flows in kg/s from compartment masses in kg
struct Builder
{
    std::vector<Eigen::Triplet<double>> t;
    Eigen::VectorXd diag;
    Eigen::RowVectorXd out;
    Eigen::VectorXd mass;

    explicit Builder(Eigen::Index n) : diag(Eigen::VectorXd::Zero(n)), out(Eigen::RowVectorXd::Zero(n)), mass(n) {}

    // flow [kg/s] of material (and tracer) from compartment `from` to `to`
    // (to < 0: leaves the drum)
    void flow(Eigen::Index from, Eigen::Index to, double f)
    {
        if (!(f > 0))
        {
            return;
        }
        const double r = f/mass(from);
        diag(from) -= r;
        if (to < 0)
        {
            out(from) += r;
        }
        else if (to != from)
        {
            t.emplace_back(to, from, r);
        }
        else
        {
            diag(from) += r;
        }
    }
};

} // namespace


TwoPhaseTracerNetwork twoPhaseTracerNetwork
(
    const TwoPhaseModel& model,
    const TwoPhaseResult& result,
    const TwoPhaseTracerOptions& options
)
{
    const TwoPhaseCase& c = model.input();
    const std::string& file = c.name;
    const double L = c.drum.length;
    const double rhoB = c.material.bulkDensity;

    std::vector<TwoPhaseProfilePoint> profile = result.profile;
    if (profile.empty())
    {
        const TwoPhaseState s = model.atDischargeAngle(result.dischargeAngle);
        profile = {model.profilePoint(s, 0.0), model.profilePoint(s, L)};
    }
    std::sort(profile.begin(), profile.end(),
        [](const auto& a, const auto& b) { return a.distanceFromDischarge < b.distanceFromDischarge; });

    // feed fractions as the model normalises them
    std::vector<double> xf = c.material.massFractions;
    double sum = 0;
    for (double x : xf) sum += x;
    for (double& x : xf) x /= sum;
    const std::size_t nk = xf.size();

    TwoPhaseTracerNetwork net;
    net.feedFractions = xf;

    // Slices: L over the feed-weighted mean advance per fall at the feed end
    const Local feedEnd = interpolate(profile, L);
    for (std::size_t k = 0; k < nk; ++k)
    {
        net.meanAdvance.push_back(feedEnd.Q > 0 ? feedEnd.A[k]/feedEnd.Q : 0.0);
    }
    if (options.slices > 0)
    {
        net.slices = options.slices;
    }
    else
    {
        double delta = 0;
        for (std::size_t k = 0; k < nk; ++k) delta += xf[k]*std::abs(net.meanAdvance[k]);
        const double n = delta > 0 ? L/delta : double(options.maxSlices);
        net.slices = int(std::lround(std::clamp(n, double(options.minSlices), double(options.maxSlices))));
        net.slicesClamped = n < options.minSlices || n > options.maxSlices;
    }
    if (net.slices < 1 || net.slices > 100000)
    {
        throw InputError(file, "rtd.slices", "must be in [1, 100000]");
    }
    requireInRange(options.denseDispersion, 0.0, 1.0, "model.denseDispersion D_z [m2/s]", file);
    const int N = net.slices;
    const double dz = L/N;
    net.sliceLength = dz;

    // Local data per slice (slice 0 at the feed end)
    std::vector<Local> loc;
    for (int i = 0; i < N; ++i)
    {
        const double s = L - (i + 0.5)*dz;
        loc.push_back(interpolate(profile, s));
        const Local& l = loc.back();
        if (!(l.H > 0) || !(l.H1 >= 0) || !(l.H1 < l.H) || !(l.Q >= 0))
        {
            std::ostringstream os;
            os << "the two-phase solution at " << s << " m from the discharge has H " << l.H
               << " m3/m, H_1 " << l.H1 << " m3/m, circulation " << l.Q << " kg/(s m): no tracer network";
            throw InputError(file, "rtd", os.str());
        }
    }

    double numSum = 0;
    double effSum = 0;
    int dispCount = 0;
    const Eigen::Index nState = 2*N;
    // the combined system holds the classes present in the feed only
    Eigen::Index used = 0;
    for (double x : xf) used += x > 0 ? 1 : 0;
    std::vector<Eigen::Triplet<double>> all;
    Eigen::VectorXd allDiag = Eigen::VectorXd::Zero(nState*used);
    Eigen::RowVectorXd allOut = Eigen::RowVectorXd::Zero(nState*used);
    Eigen::VectorXd allB = Eigen::VectorXd::Zero(nState*used);
    Eigen::Index block = 0;

    for (std::size_t k = 0; k < nk; ++k)
    {
        TracerSystem sys;
        if (!(xf[k] > 0))
        {
            net.classSystems.push_back(sys);
            continue;
        }
        Builder b(nState);
        auto dense = [](int i) { return Eigen::Index(2*i); };
        auto air = [](int i) { return Eigen::Index(2*i + 1); };
        for (int i = 0; i < N; ++i)
        {
            const Local& l = loc[i];
            b.mass(dense(i)) = l.xd[k]*(l.H - l.H1)*rhoB*dz;
            b.mass(air(i)) = l.xd[k]*l.H1*rhoB*dz;
            if (!(b.mass(dense(i)) > 0))
            {
                std::ostringstream os;
                os << "size class " << k << " has holdup fraction x_d = " << l.xd[k]
                   << " in slice " << i << ": no tracer network";
                throw InputError(file, "rtd", os.str());
            }
        }
        for (int i = 0; i < N; ++i)
        {
            const Local& l = loc[i];
            const double q = l.xd[k]*l.Q*dz;               // into the curtains, kg/s
            const double delta = l.Q > 0 ? l.A[k]/l.Q : 0.0;  // mean advance per fall, m
            const double jumps = delta/dz;
            const int j0 = int(std::floor(jumps));
            const double f = jumps - j0;
            // where the falls land: slice i + j0 (1 - f) and i + j0 + 1 (f)
            auto land = [&](int target) -> Eigen::Index
            {
                if (target >= N) return -1;           // past the discharge end
                return dense(std::max(target, 0));    // before the feed end: stays in slice 0
            };
            const bool airborne = b.mass(air(i)) > 1e-12*b.mass(dense(i));
            if (airborne)
            {
                b.flow(dense(i), air(i), q);
                b.flow(air(i), land(i + j0), (1 - f)*q);
                b.flow(air(i), land(i + j0 + 1), f*q);
            }
            else
            {
                b.flow(dense(i), land(i + j0), (1 - f)*q);
                b.flow(dense(i), land(i + j0 + 1), f*q);
                // an empty airborne compartment receives nothing; a unit
                // rate into the dense compartment keeps K regular (a zero
                // column would make it singular) and conserves any tracer
                b.diag(air(i)) -= 1.0;
                b.t.emplace_back(dense(i), air(i), 1.0);
            }
            // dense flow (size independent velocity, Eq 52), upwind
            const double F2k = l.xd[k]*l.F2;
            if (F2k >= 0)
            {
                b.flow(dense(i), i + 1 < N ? dense(i + 1) : -1, F2k);
            }
            else
            {
                b.flow(dense(i), dense(std::max(i - 1, 0)), -F2k);
            }
            // dense-phase dispersion between i and i+1 (Sherritt 2001 Eq 27)
            if (options.denseDispersion > 0 && i + 1 < N)
            {
                const double Md = 0.5*(b.mass(dense(i)) + b.mass(dense(i + 1)));  // kg per slice
                const double u2 = std::abs(l.F2)/((l.H - l.H1)*rhoB);             // m/s
                const double numerical = 0.5*u2*dz;
                const double D = options.subtractNumericalDispersion
                    ? std::max(0.0, options.denseDispersion - numerical) : options.denseDispersion;
                numSum += numerical;
                effSum += D;
                ++dispCount;
                const double G = D*Md/(dz*dz);  // kg/s exchanged each way
                b.flow(dense(i), dense(i + 1), G);
                b.flow(dense(i + 1), dense(i), G);
            }
        }
        sys.K.resize(nState, nState);
        auto trip = b.t;
        for (Eigen::Index j = 0; j < nState; ++j)
        {
            trip.emplace_back(j, j, b.diag(j));
        }
        sys.K.setFromTriplets(trip.begin(), trip.end());
        sys.b = Eigen::VectorXd::Zero(nState);
        sys.b(dense(0)) = 1.0;
        sys.c = b.out;
        net.classSystems.push_back(sys);

        const Eigen::Index off = block++*nState;
        for (const auto& e : b.t)
        {
            all.emplace_back(e.row() + off, e.col() + off, e.value());
        }
        allDiag.segment(off, nState) = b.diag;
        allOut.segment(off, nState) = b.out;
        allB(off + dense(0)) = xf[k];
    }
    for (Eigen::Index j = 0; j < allDiag.size(); ++j)
    {
        all.emplace_back(j, j, allDiag(j));
    }
    net.system.K.resize(allDiag.size(), allDiag.size());
    net.system.K.setFromTriplets(all.begin(), all.end());
    net.system.b = allB;
    net.system.c = allOut;
    if (dispCount > 0)
    {
        net.numericalDenseDispersion = numSum/dispCount;
        net.effectiveDenseDispersion = effSum/dispCount;
    }
    return net;
}

} // namespace drum
