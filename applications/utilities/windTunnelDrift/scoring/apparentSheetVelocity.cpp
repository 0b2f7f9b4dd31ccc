#include "scoring/apparentSheetVelocity.hpp"

#include "drum/io/inputError.hpp"
#include "particleDrag/loneParticleFall.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <sstream>

namespace drum
{

namespace
{

//- sqrt(x_i) (delta_i - delta_i(V)) of the fitted classes: Eq 141's terms
struct Eq141Residuals
{
    std::vector<particleDrag::Particle> particles;
    std::vector<double> weight;    //!< sqrt(x_i)
    std::vector<double> advance;   //!< delta_i, m
    particleDrag::Gas gas;
    double height;

    bool operator()(const double* const v, double* r) const
    {
        for (std::size_t i = 0; i < particles.size(); ++i)
        {
            r[i] = weight[i]*(advance[i]
                - particleDrag::loneParticleAdvance(particleDrag::DragLaw{}, particles[i], gas, v[0], height));
        }
        return true;
    }
};

} // namespace


double apparentSheetVelocity
(
    const WindTunnelTest& t,
    const WindTunnelMaterial& m,
    const std::vector<double>& classAdvance,
    const particleDrag::Gas& air,
    const ApparentVcBounds& bounds
)
{
    const std::string where = "test " + std::to_string(t.test);
    if (classAdvance.size() != m.classes.size())
    {
        throw InputError("", where, "Eq 141 needs one advance per size class of " + m.name);
    }
    if (m.classes.size() < 3)
    {
        throw InputError("", where, "Eq 141 leaves out the two smallest classes: " + m.name + " has "
                         + std::to_string(m.classes.size()) + ", at least 3 are needed");
    }
    // the classes from the third smallest up (Sherritt left out the two smallest)
    std::vector<std::size_t> order(m.classes.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
        [&](std::size_t a, std::size_t b) { return m.classes[a].diameter < m.classes[b].diameter; });
    auto res = std::make_unique<Eq141Residuals>(Eq141Residuals{{}, {}, {}, air, t.fallHeight});
    for (std::size_t k = 2; k < order.size(); ++k)
    {
        const std::size_t i = order[k];
        if (!std::isfinite(classAdvance[i]))
        {
            throw InputError("", where, "the advance of class " + std::to_string(i) + " is not finite");
        }
        res->particles.push_back({m.classes[i].diameter, m.particleDensity});
        res->weight.push_back(std::sqrt(m.classes[i].massFraction));
        res->advance.push_back(classAdvance[i]);
    }
    const double lo = bounds.lowest*t.airVelocity, hi = bounds.highest*t.airVelocity;
    double v = 0.5*t.airVelocity;   // start inside: the tunnel's V_c/V_g lie near it
    const int n = static_cast<int>(res->particles.size());
    ceres::Problem problem;
    problem.AddResidualBlock(
        new ceres::NumericDiffCostFunction<Eq141Residuals, ceres::CENTRAL, ceres::DYNAMIC, 1>(
            res.release(), ceres::TAKE_OWNERSHIP, n),
        nullptr, &v);
    problem.SetParameterLowerBound(&v, 0, lo);
    problem.SetParameterUpperBound(&v, 0, hi);
    ceres::Solver::Options so;
    so.linear_solver_type = ceres::DENSE_QR;
    so.logging_type = ceres::SILENT;
    so.function_tolerance = 1e-14;
    so.parameter_tolerance = 1e-12;
    so.gradient_tolerance = 1e-16;
    so.max_num_iterations = 200;
    ceres::Solver::Summary summary;
    ceres::Solve(so, &problem, &summary);
    if (summary.termination_type != ceres::CONVERGENCE || v <= lo*(1 + 1e-6) || v >= hi*(1 - 1e-6))
    {
        std::ostringstream os;
        os << "Eq 141 found no apparent in-sheet velocity inside [" << bounds.lowest << ", " << bounds.highest
           << "] V_g (ended at " << v << " m/s: " << summary.message << ")";
        throw InputError("", where, os.str());
    }
    return v;
}


} // namespace drum
