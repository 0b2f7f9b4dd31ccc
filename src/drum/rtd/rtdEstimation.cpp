#include "drum/rtd/rtdEstimation.hpp"
#include "drum/numerics/constants.hpp"

#include "drum/io/inputError.hpp"
#include "drum/rtd/rtdSimulation.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace drum
{

namespace
{

//- Residuals r = model(x) - measured with a finite-difference Jacobian that
//  is central where both neighbours are feasible and one-sided where the
//  optimum presses against a constraint the model enforces itself (Lee's
//  C_F + C_B <= 1 is one: the Invicta fits end there, Lee 2008 Table 7.2)
class ResidualCost : public ceres::CostFunction
{
public:
    ResidualCost(const PredictionModel& model, const std::vector<double>& measured, int p)
    :
        model_(model), measured_(measured), p_(p)
    {
        mutable_parameter_block_sizes()->push_back(p);
        set_num_residuals(int(measured.size()));
    }

    bool Evaluate(double const* const* x, double* r, double** jac) const override
    {
        std::vector<double> v(x[0], x[0] + p_);
        std::vector<double> y0;
        if (!eval(v, y0)) return false;
        const std::size_t m = measured_.size();
        for (std::size_t i = 0; i < m; ++i) r[i] = y0[i] - measured_[i];
        if (jac == nullptr || jac[0] == nullptr) return true;
        for (int k = 0; k < p_; ++k)
        {
            const double h = 1e-6*std::max(std::abs(v[k]), 1e-3);
            std::vector<double> vp = v, vm = v, yp, ym;
            vp[k] += h;
            vm[k] -= h;
            const bool okp = eval(vp, yp), okm = eval(vm, ym);
            for (std::size_t i = 0; i < m; ++i)
            {
                double d;
                if (okp && okm) d = (yp[i] - ym[i])/(2*h);
                else if (okp) d = (yp[i] - y0[i])/h;
                else if (okm) d = (y0[i] - ym[i])/h;
                else return false;
                jac[0][i*p_ + k] = d;
            }
        }
        return true;
    }

private:
    bool eval(const std::vector<double>& v, std::vector<double>& y) const
    {
        try
        {
            y = model_(v);
        }
        catch (const InputError&)
        {
            return false;   // infeasible parameter set: Ceres shrinks the step
        }
        for (double e : y)
        {
            if (!std::isfinite(e)) return false;
        }
        return y.size() == measured_.size();
    }

    const PredictionModel& model_;
    const std::vector<double>& measured_;
    int p_;
};

double normalQuantile(double p)
{
    // Acklam's rational approximation refined by one Newton step
    const double a[] = {-3.969683028665376e+01, 2.209460984245205e+02, -2.759285104469687e+02,
                        1.383577518672690e+02, -3.066479806614716e+01, 2.506628277459239e+00};
    const double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02,
                        6.680131188771972e+01, -1.328068155288572e+01};
    const double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                        -2.549732539343734e+00, 4.374664141464968e+00, 2.938163982698783e+00};
    const double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                        3.754408661907416e+00};
    double x;
    if (p < 0.02425)
    {
        const double q = std::sqrt(-2*std::log(p));
        x = (((((c[0]*q + c[1])*q + c[2])*q + c[3])*q + c[4])*q + c[5])/((((d[0]*q + d[1])*q + d[2])*q + d[3])*q + 1);
    }
    else if (p <= 1 - 0.02425)
    {
        const double q = p - 0.5, r = q*q;
        x = (((((a[0]*r + a[1])*r + a[2])*r + a[3])*r + a[4])*r + a[5])*q/(((((b[0]*r + b[1])*r + b[2])*r + b[3])*r + b[4])*r + 1);
    }
    else
    {
        const double q = std::sqrt(-2*std::log(1 - p));
        x = -(((((c[0]*q + c[1])*q + c[2])*q + c[3])*q + c[4])*q + c[5])/((((d[0]*q + d[1])*q + d[2])*q + d[3])*q + 1);
    }
    const double e = 0.5*std::erfc(-x/std::sqrt(2.0)) - p;
    const double u = e*std::sqrt(2*pi)*std::exp(x*x/2);
    return x - u/(1 + x*u/2);
}

} // namespace


double studentTQuantile(const double alpha, const int dof)
{
    if (dof < 1 || !(alpha > 0 && alpha < 1))
    {
        throw InputError("", "t quantile", "need dof >= 1 and 0 < alpha < 1");
    }
    // Cornish-Fisher expansion of t in z (Abramowitz & Stegun 26.7.5)
    const double z = normalQuantile(1.0 - alpha/2.0);
    const double n = dof;
    const double z2 = z*z;
    return z + (z2 + 1)*z/(4*n)
        + ((5*z2 + 16)*z2 + 3)*z/(96*n*n)
        + (((3*z2 + 19)*z2 + 17)*z2 - 15)*z/(384*n*n*n)
        + ((((79*z2 + 776)*z2 + 1482)*z2 - 1920)*z2 - 945)*z/(92160*n*n*n*n);
}


FitResult fitLeastSquares
(
    const PredictionModel& model,
    const std::vector<double>& measured,
    const std::vector<FitParameter>& params,
    const FitOptions& opt
)
{
    const int p = int(params.size());
    const int m = int(measured.size());
    if (p < 1 || m <= p)
    {
        throw InputError("", "estimation", "need at least one free parameter and more data points than parameters");
    }
    FitResult res;
    res.nData = m;
    std::vector<double> x(p);
    for (int k = 0; k < p; ++k)
    {
        const FitParameter& q = params[k];
        if (!(q.lower <= q.initial && q.initial <= q.upper))
        {
            throw InputError("", "estimation parameter " + q.name,
                "initial value " + std::to_string(q.initial) + " outside its bounds ["
              + std::to_string(q.lower) + ", " + std::to_string(q.upper) + "]");
        }
        res.names.push_back(q.name);
        x[k] = q.initial;
    }
    res.initial = x;

    auto* cost = new ResidualCost(model, measured, p);

    ceres::Problem problem;
    problem.AddResidualBlock(cost, nullptr, x.data());
    for (int k = 0; k < p; ++k)
    {
        if (std::isfinite(params[k].lower)) problem.SetParameterLowerBound(x.data(), k, params[k].lower);
        if (std::isfinite(params[k].upper)) problem.SetParameterUpperBound(x.data(), k, params[k].upper);
    }

    ceres::Solver::Options so;
    so.linear_solver_type = ceres::DENSE_QR;
    so.max_num_iterations = opt.maxIterations;
    so.function_tolerance = opt.functionTolerance;
    so.parameter_tolerance = opt.parameterTolerance;
    so.logging_type = ceres::SILENT;
    so.minimizer_progress_to_stdout = false;
    ceres::Solver::Summary summary;
    ceres::Solve(so, &problem, &summary);

    res.values = x;
    res.sse = 2.0*summary.final_cost;
    res.converged = summary.termination_type == ceres::CONVERGENCE;
    res.iterations = int(summary.iterations.size());
    res.message = summary.message;
    if (!summary.IsSolutionUsable())
    {
        throw InputError("", "estimation", "least squares failed: " + summary.message);
    }

    // Jacobian at the optimum
    double c = 0;
    ceres::CRSMatrix jac;
    problem.Evaluate(ceres::Problem::EvaluateOptions(), &c, nullptr, nullptr, &jac);
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(m, p);
    for (int r = 0; r < jac.num_rows; ++r)
    {
        for (int k = jac.rows[r]; k < jac.rows[r + 1]; ++k)
        {
            J(r, jac.cols[k]) = jac.values[k];
        }
    }
    // Parameters on a bound are held there: the covariance is that of the
    // free ones (their CI is conditional on the active bounds)
    std::vector<int> freeIdx;
    res.atBound.assign(p, false);
    for (int k = 0; k < p; ++k)
    {
        const double tol = 1e-6*std::max(1.0, std::abs(res.values[k]));
        res.atBound[k] = std::abs(res.values[k] - params[k].lower) < tol
                      || std::abs(res.values[k] - params[k].upper) < tol;
        if (!res.atBound[k]) freeIdx.push_back(k);
    }
    const int pf = int(freeIdx.size());
    const double s2 = res.sse/(m - p);
    const double t = studentTQuantile(0.05, m - p);
    res.standardErrors.assign(p, std::numeric_limits<double>::quiet_NaN());
    res.correlation = Eigen::MatrixXd::Constant(p, p, std::numeric_limits<double>::quiet_NaN());
    if (pf > 0)
    {
        Eigen::MatrixXd Jf(m, pf);
        for (int k = 0; k < pf; ++k) Jf.col(k) = J.col(freeIdx[k]);
        const Eigen::MatrixXd JtJ = Jf.transpose()*Jf;
        const Eigen::FullPivLU<Eigen::MatrixXd> lu(JtJ);
        if (lu.isInvertible())
        {
            const Eigen::MatrixXd cov = s2*lu.inverse();
            for (int k = 0; k < pf; ++k)
            {
                res.standardErrors[freeIdx[k]] = std::sqrt(std::max(cov(k, k), 0.0));
                for (int l = 0; l < pf; ++l)
                {
                    res.correlation(freeIdx[k], freeIdx[l]) = cov(k, l)/std::sqrt(cov(k, k)*cov(l, l));
                }
            }
        }
        else
        {
            for (int k : freeIdx) res.standardErrors[k] = std::numeric_limits<double>::infinity();
        }
    }
    for (int k = 0; k < p; ++k)
    {
        res.ciLow.push_back(res.values[k] - t*res.standardErrors[k]);
        res.ciHigh.push_back(res.values[k] + t*res.standardErrors[k]);
    }
    return res;
}


std::vector<FitResult> multiStartFit
(
    const PredictionModel& model,
    const std::vector<double>& measured,
    const std::vector<FitParameter>& params,
    const int nStarts,
    const FitOptions& opt
)
{
    static const int primes[] = {2, 3, 5, 7, 11, 13, 17, 19};
    auto halton = [](int i, int base)
    {
        double f = 1, r = 0;
        for (; i > 0; i /= base)
        {
            f /= base;
            r += f*(i % base);
        }
        return r;
    };
    std::vector<FitResult> runs;
    for (int s = 0; s < std::max(1, nStarts); ++s)
    {
        std::vector<FitParameter> start = params;
        if (s > 0)
        {
            for (std::size_t k = 0; k < start.size(); ++k)
            {
                const double lo = std::isfinite(start[k].lower) ? start[k].lower : 0.0;
                // Open-ended bounds (t_kiln <= 1e30 in Lee's estimation entity)
                // are sampled up to 4x the initial value
                const double hi = std::isfinite(start[k].upper) && start[k].upper < 1e6*std::max(1.0, std::abs(start[k].initial))
                  ? start[k].upper : lo + 4.0*std::abs(start[k].initial);
                start[k].initial = lo + (hi - lo)*(0.02 + 0.96*halton(s, primes[k % 8]));
            }
        }
        try
        {
            runs.push_back(fitLeastSquares(model, measured, start, opt));
        }
        catch (const InputError&)
        {
            // infeasible start (e.g. C_F + C_B > 1): dropped
        }
    }
    std::sort(runs.begin(), runs.end(), [](const FitResult& a, const FitResult& b) { return a.sse < b.sse; });
    return runs;
}


std::vector<double> transformForObjective(const std::vector<double>& E, const RtdObjective& o)
{
    if (!o.logarithmic)
    {
        return E;
    }
    requirePositive(o.offset, "log objective offset (1/h)");
    std::vector<double> out;
    out.reserve(E.size());
    for (const double e : E)
    {
        out.push_back(std::log(std::max(e, 0.0) + o.offset));
    }
    return out;
}

} // namespace drum
