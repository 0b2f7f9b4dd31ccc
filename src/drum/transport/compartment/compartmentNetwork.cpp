#include "drum/transport/compartment/compartmentNetwork.hpp"

#include "drum/io/inputError.hpp"

#include <cmath>
#include <limits>
#include <string>

namespace drum
{

CompartmentNetwork::CompartmentNetwork
(
    std::vector<CompartmentSlice> slices,
    const double feedRate,
    const double kilnTime
)
:
    slices_(std::move(slices)),
    feedRate_(feedRate),
    kilnTime_(kilnTime)
{
    if (slices_.empty())
    {
        throw InputError("", "slices", "the network needs at least one slice");
    }
    requirePositive(feedRate_, "feed rate (kg/s)");
    if (!(kilnTime_ > 0))
    {
        throw InputError("", "t_kiln", "kilning time must be > 0 s (may be infinite)");
    }
    for (std::size_t i = 0; i < slices_.size(); ++i)
    {
        const CompartmentSlice& s = slices_[i];
        const std::string at = " of slice " + std::to_string(i + 1);
        requirePositive(s.designLoad, "design load" + at + " (kg)");
        requirePositive(s.passiveTime, "passive time" + at + " (s)");
        requirePositive(s.activeTime, "active (fall) time" + at + " (s)");
        if (s.saemanKiln)
        {
            requirePositive(s.length, "slice length" + at + " (m, for its rolling bed)");
        }
        requireInRange(s.forwardFraction, 0.0, 1.0, "forward fraction C_F" + at);
        requireInRange(s.backFraction, 0.0, 1.0, "backmix fraction C_B" + at);
        if (s.forwardFraction + s.backFraction > 1.0 + 1e-12)
        {
            throw InputError("", "C_F + C_B" + at,
                "C_F + C_B = " + std::to_string(s.forwardFraction + s.backFraction)
              + " exceeds 1 (the return fraction C_R = 1 - C_F - C_B must be >= 0)");
        }
    }
}


namespace
{

// Depth of a slice's rolling bed (0 without one), for the next slice upstream's bed slope
double kilnBedDepth(const CompartmentSlice& s, double kilnMass)
{
    if (!s.saemanKiln || !(kilnMass > 0)) return 0;
    const double D = s.saemanKiln->drumDiameter;
    return bedDepth(D, fillAngle(D, kilnMass/(s.saemanKiln->bulkDensity*s.length)));
}

} // namespace


CompartmentSteadyState CompartmentNetwork::steadyState() const
{
    const int n = nSlices();
    CompartmentSteadyState st;
    st.passiveMass.setZero(n);
    st.activeMass.setZero(n);
    st.kilnMass.setZero(n);
    st.releaseFlow.setZero(n);
    st.kilnFlow.setZero(n);
    st.forwardFlow.setZero(n);
    st.backFlow.setZero(n);
    st.returnFlow.setZero(n);

    const bool kilns = std::isfinite(kilnTime_);
    double backFromNext = 0;    // F_b of A_{i+1}, which lands in P_i
    double nextDepth = 0;       // bed depth of slice i+1 (none past the discharge end)
    for (int i = n - 1; i >= 0; --i)
    {
        const CompartmentSlice& s = slices_[i];
        // Net flow across the downstream boundary of slice i equals the feed:
        // F_k,i + C_F,i Q_i = F + F_b,i+1, with Q_i = F_a,i the curtain flow
        const double target = feedRate_ + backFromNext;
        const double linearMax = s.forwardFraction*s.designLoad/s.passiveTime;
        double mp;
        if (s.forwardFraction > 0 && target <= linearMax)
        {
            mp = target*s.passiveTime/s.forwardFraction;
        }
        else if (s.saemanKiln)
        {
            mp = s.designLoad + (s.saemanKiln->slopeFromProfile
                ? saemanKilnMass(*s.saemanKiln, s.length, target - linearMax, nextDepth)
                : saemanKilnMass(*s.saemanKiln, s.length, target - linearMax));
        }
        else if (kilns)
        {
            mp = s.designLoad + (target - linearMax)*kilnTime_;
        }
        else
        {
            throw InputError("", "slice " + std::to_string(i + 1),
                "no steady state: without kilning the slice passes at most "
              + std::to_string(linearMax) + " kg/s but must pass "
              + std::to_string(target) + " kg/s");
        }
        const double release = std::min(mp, s.designLoad)/s.passiveTime;  // Eq 3.2
        st.passiveMass(i) = mp;
        st.kilnMass(i) = std::max(mp - s.designLoad, 0.0);
        st.kilnFlow(i) = s.saemanKiln ? std::max(target - linearMax, 0.0)   // the bed carries the rest
                       : kilns ? st.kilnMass(i)/kilnTime_ : 0.0;
        st.releaseFlow(i) = release;
        // Active balance at steady state: M_a/t_a = F_a
        st.activeMass(i) = release*s.activeTime;
        st.forwardFlow(i) = s.forwardFraction*release;
        st.backFlow(i) = s.backFraction*release;
        st.returnFlow(i) = (1.0 - s.forwardFraction - s.backFraction)*release;
        backFromNext = st.backFlow(i);
        nextDepth = drum::kilnBedDepth(s, st.kilnMass(i));
    }
    return st;
}


Eigen::VectorXd CompartmentNetwork::massRates(const Eigen::VectorXd& m) const
{
    const int n = nSlices();
    if (m.size() != 2*n)
    {
        throw InputError("", "masses", "expected " + std::to_string(2*n) + " compartment masses");
    }
    Eigen::VectorXd dm = Eigen::VectorXd::Zero(2*n);
    dm(passiveIndex(0)) += feedRate_;
    for (int i = 0; i < n; ++i)
    {
        const CompartmentSlice& s = slices_[i];
        const double mp = m(passiveIndex(i));
        const double ma = m(activeIndex(i));
        // Passive v4.0: F_a = m_pas/t_pas, F_k_out = m_kiln/t_kiln
        const double fa = std::min(mp, s.designLoad)/s.passiveTime;
        const double kilnMass = std::max(mp - s.designLoad, 0.0);
        const double next = i + 1 < n && s.saemanKiln && s.saemanKiln->slopeFromProfile
            ? kilnBedDepth(i + 1, std::max(m(passiveIndex(i + 1)) - slices_[i + 1].designLoad, 0.0)) : 0.0;
        const double fk = kilnFlow(i, kilnMass, next);
        // Active v4.0: F_x + F_r + F_b = m/t_act
        const double out = ma/s.activeTime;
        const double fx = s.forwardFraction*out;
        const double fb = s.backFraction*out;
        const double fr = out - fx - fb;

        dm(passiveIndex(i)) += fr - fa - fk;
        dm(activeIndex(i)) += fa - out;
        if (i + 1 < n)
        {
            dm(passiveIndex(i + 1)) += fk + fx;
        }
        dm(passiveIndex(i > 0 ? i - 1 : 0)) += fb;
    }
    return dm;
}


double CompartmentNetwork::kilnFlow(const int i, const double kilnMass, const double nextDepth) const
{
    const CompartmentSlice& s = slices_.at(i);
    if (s.saemanKiln && s.saemanKiln->slopeFromProfile)
    {
        return saemanKilnFlow(*s.saemanKiln, s.length, kilnMass, nextDepth);
    }
    if (s.saemanKiln)
    {
        return saemanKilnFlow(*s.saemanKiln, s.length, kilnMass);
    }
    return std::isfinite(kilnTime_) ? kilnMass/kilnTime_ : 0.0;
}


double CompartmentNetwork::kilnBedDepth(const int i, const double kilnMass) const
{
    return drum::kilnBedDepth(slices_.at(i), kilnMass);
}


TracerSystem CompartmentNetwork::tracerSystem(const CompartmentSteadyState& st) const
{
    const int n = nSlices();
    const int size = 2*n;
    std::vector<Eigen::Triplet<double>> trip;
    trip.reserve(8*n);
    TracerSystem sys;
    sys.b = Eigen::VectorXd::Zero(size);
    sys.c = Eigen::RowVectorXd::Zero(size);
    sys.b(passiveIndex(0)) = 1.0;   // tracer enters with the feed into P_1

    // A flow F leaving compartment j at concentration x_j = y_j/M_j moves
    // tracer at rate (F/M_j) y_j (Lee's $(m x) balances)
    auto link = [&](int from, int to, double flow, double mass)
    {
        if (flow <= 0)
        {
            return;
        }
        const double k = flow/mass;
        trip.emplace_back(from, from, -k);
        if (to >= 0)
        {
            trip.emplace_back(to, from, k);
        }
        else
        {
            sys.c(from) += k;   // to the product
        }
    };

    for (int i = 0; i < n; ++i)
    {
        const int p = passiveIndex(i);
        const int a = activeIndex(i);
        const double mp = st.passiveMass(i);
        const double ma = st.activeMass(i);
        const int next = i + 1 < n ? passiveIndex(i + 1) : -1;
        link(p, a, st.releaseFlow(i), mp);
        link(p, next, st.kilnFlow(i), mp);
        link(a, p, st.returnFlow(i), ma);
        link(a, next, st.forwardFlow(i), ma);
        link(a, passiveIndex(i > 0 ? i - 1 : 0), st.backFlow(i), ma);
    }
    sys.K.resize(size, size);
    sys.K.setFromTriplets(trip.begin(), trip.end());
    sys.K.makeCompressed();
    return sys;
}


TracerSystem CompartmentNetwork::tracerSystem
(
    const CompartmentSteadyState& st,
    const StagnantExchange& z
) const
{
    TracerSystem base = tracerSystem(st);
    if (z.massRatio == 0)
    {
        return base;
    }
    requireInRange(z.massRatio, 0.0, 1e3, "stagnant mass ratio");
    requirePositive(z.exchangeTime, "stagnant exchange time (s)");
    const int n = nSlices();
    const int m = 2*n;
    std::vector<Eigen::Triplet<double>> trip;
    for (int k = 0; k < base.K.outerSize(); ++k)
    {
        for (Eigen::SparseMatrix<double>::InnerIterator it(base.K, k); it; ++it)
        {
            trip.emplace_back(it.row(), it.col(), it.value());
        }
    }
    for (int i = 0; i < n; ++i)
    {
        const double mp = st.passiveMass(i);
        const double ms = z.massRatio*mp;
        const double f = ms/z.exchangeTime;
        const int p = passiveIndex(i), s = m + i;
        trip.emplace_back(p, p, -f/mp);
        trip.emplace_back(s, p, f/mp);
        trip.emplace_back(s, s, -f/ms);
        trip.emplace_back(p, s, f/ms);
    }
    TracerSystem sys;
    sys.K.resize(m + n, m + n);
    sys.K.setFromTriplets(trip.begin(), trip.end());
    sys.K.makeCompressed();
    sys.b = Eigen::VectorXd::Zero(m + n);
    sys.b.head(m) = base.b;
    sys.c = Eigen::RowVectorXd::Zero(m + n);
    sys.c.head(m) = base.c;
    return sys;
}

} // namespace drum
