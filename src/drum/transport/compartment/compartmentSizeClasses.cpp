#include "drum/transport/compartment/compartmentSizeClasses.hpp"
#include "drum/numerics/constants.hpp"

#include "drum/io/inputError.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace drum
{

namespace
{

void checkClasses(const CompartmentNetwork& net, const std::vector<SizeClassSplits>& classes)
{
    if (classes.empty())
    {
        throw InputError("", "size classes", "at least one class needed");
    }
    const std::size_t n = net.nSlices();
    double sum = 0;
    for (std::size_t k = 0; k < classes.size(); ++k)
    {
        const SizeClassSplits& c = classes[k];
        const std::string at = " of size class " + std::to_string(k + 1);
        requireInRange(c.feedShare, 0.0, 1.0, "feed share" + at);
        sum += c.feedShare;
        if (c.forward.size() != n || c.back.size() != n)
        {
            throw InputError("", "size classes", "one C_F and one C_B per slice needed" + at);
        }
        for (std::size_t i = 0; i < n; ++i)
        {
            requireInRange(c.forward[i], 0.0, 1.0, "C_F" + at);
            requireInRange(c.back[i], 0.0, 1.0, "C_B" + at);
            if (c.forward[i] + c.back[i] > 1.0 + 1e-12)
            {
                throw InputError("", "model.slices", "C_F + C_B" + at + " exceeds 1 in slice " + std::to_string(i + 1)
                    + ": its mean fall jumps past the next slice (Lee's nearest-neighbour rule, Fig. 3.4); use fewer slices");
            }
        }
    }
    if (std::abs(sum - 1.0) > 1e-9)
    {
        throw InputError("", "size classes", "feed shares sum to " + std::to_string(sum) + ", not 1");
    }
}


CompartmentSteadyState zeroState(int n)
{
    CompartmentSteadyState st;
    for (Eigen::VectorXd* v : {&st.passiveMass, &st.activeMass, &st.kilnMass, &st.releaseFlow,
                               &st.kilnFlow, &st.forwardFlow, &st.backFlow, &st.returnFlow})
    {
        v->setZero(n);
    }
    return st;
}

} // namespace


SizeClassSteadyState sizeClassSteadyState
(
    const CompartmentNetwork& net,
    const std::vector<SizeClassSplits>& classes
)
{
    checkClasses(net, classes);
    const int n = net.nSlices();
    const std::size_t nk = classes.size();
    SizeClassSteadyState out;
    out.total = zeroState(n);
    out.classes.assign(nk, zeroState(n));

    std::vector<double> backFromNext(nk, 0.0);   // F_b,k of A_{i+1}, landing in P_i
    double nextDepth = 0;
    for (int i = n - 1; i >= 0; --i)
    {
        const CompartmentSlice& s = net.slices()[i];
        std::vector<double> target(nk);
        for (std::size_t k = 0; k < nk; ++k)
        {
            target[k] = classes[k].feedShare*net.feedRate() + backFromNext[k];
        }
        const auto release = [&](double m) { return std::min(m, s.designLoad)/s.passiveTime; };
        const auto kiln = [&](double m) { return net.kilnFlow(i, std::max(m - s.designLoad, 0.0), nextDepth); };
        // sum_k x_k(M): above 1 while M is too small to pass every class's flow
        const auto shares = [&](double m)
        {
            const double r = release(m), f = kiln(m);
            double sum = 0;
            for (std::size_t k = 0; k < nk; ++k)
            {
                if (target[k] <= 0) continue;
                const double out = f + classes[k].forward[i]*r;
                if (!(out > 0)) return std::numeric_limits<double>::infinity();
                sum += target[k]/out;
            }
            return sum;
        };
        // the largest passive mass worth trying: a half-full rolling bed passes
        // its most; Lee's t_kiln law has no limit; no kilning stops at M_des
        double mMax = s.designLoad;
        if (s.saemanKiln)
        {
            mMax += s.saemanKiln->bulkDensity*s.length*pi*std::pow(s.saemanKiln->drumDiameter, 2)/8;
        }
        else if (std::isfinite(net.kilnTime()))
        {
            mMax = std::numeric_limits<double>::max();
        }
        double lo = 0, hi = std::min(s.designLoad, mMax);
        while (shares(hi) > 1 && hi < mMax)
        {
            lo = hi;
            hi = std::min(mMax, 2*hi);      // from M_des: doubling
        }
        if (shares(hi) > 1)
        {
            throw InputError("", "slice " + std::to_string(i + 1),
                "no steady state with these size classes: the slice cannot pass its feed (the classes' "
                "curtains and its kilning at most pass " + std::to_string(1/shares(hi)) + " of it)");
        }
        for (int it = 0; it < 300 && hi - lo > 1e-14*hi; ++it)
        {
            const double mid = 0.5*(lo + hi);
            (shares(mid) > 1 ? lo : hi) = mid;
        }
        const double mp = hi;
        const double r = release(mp), f = kiln(mp);
        const double sum = shares(mp);
        for (std::size_t k = 0; k < nk; ++k)
        {
            CompartmentSteadyState& c = out.classes[k];
            const double x = target[k] > 0 ? target[k]/(f + classes[k].forward[i]*r)/sum : 0.0;
            c.passiveMass(i) = x*mp;
            c.kilnMass(i) = x*std::max(mp - s.designLoad, 0.0);
            c.releaseFlow(i) = x*r;
            c.kilnFlow(i) = x*f;
            c.activeMass(i) = x*r*s.activeTime;
            c.forwardFlow(i) = classes[k].forward[i]*x*r;
            c.backFlow(i) = classes[k].back[i]*x*r;
            c.returnFlow(i) = (1.0 - classes[k].forward[i] - classes[k].back[i])*x*r;
            backFromNext[k] = c.backFlow(i);
            out.total.passiveMass(i) += c.passiveMass(i);
            out.total.kilnMass(i) += c.kilnMass(i);
            out.total.releaseFlow(i) += c.releaseFlow(i);
            out.total.kilnFlow(i) += c.kilnFlow(i);
            out.total.activeMass(i) += c.activeMass(i);
            out.total.forwardFlow(i) += c.forwardFlow(i);
            out.total.backFlow(i) += c.backFlow(i);
            out.total.returnFlow(i) += c.returnFlow(i);
        }
        nextDepth = net.kilnBedDepth(i, out.total.kilnMass(i));
    }
    return out;
}


TracerSystem sizeClassTracerSystem
(
    const CompartmentNetwork& net,
    const SizeClassSteadyState& state,
    const std::vector<SizeClassSplits>& classes
)
{
    checkClasses(net, classes);
    const Eigen::Index m = 2*net.nSlices();
    const Eigen::Index size = m*Eigen::Index(classes.size());
    TracerSystem sys;
    sys.b = Eigen::VectorXd::Zero(size);
    sys.c = Eigen::RowVectorXd::Zero(size);
    std::vector<Eigen::Triplet<double>> trip;
    for (std::size_t k = 0; k < classes.size(); ++k)
    {
        const Eigen::Index off = m*Eigen::Index(k);
        const TracerSystem one = net.tracerSystem(state.classes.at(k));
        for (int j = 0; j < one.K.outerSize(); ++j)
        {
            for (Eigen::SparseMatrix<double>::InnerIterator it(one.K, j); it; ++it)
            {
                trip.emplace_back(off + it.row(), off + it.col(), it.value());
            }
        }
        sys.b.segment(off, m) = classes[k].feedShare*one.b;
        sys.c.segment(off, m) = one.c;
    }
    sys.K.resize(size, size);
    sys.K.setFromTriplets(trip.begin(), trip.end());
    sys.K.makeCompressed();
    return sys;
}

} // namespace drum
