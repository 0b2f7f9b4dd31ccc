// Least-squares estimation of model parameters from a measured tracer curve
// (what Lee 2008 §5.2/Ch. 7 did in gPROMS with a constant-variance
// maximum-likelihood objective, which is least squares on E(t)).
// Ceres (trust-region Levenberg-Marquardt, central-difference Jacobian,
// box bounds); confidence intervals from the Jacobian at the optimum,
// cov = s^2 (J^T J)^-1 with s^2 = SSE/(m - p), and Student-t quantiles.
// Multi-start from points spread over the bounds shows how much the
// answer depends on the starting guess.
//
// Built as its own library, drumRtdFit, so the drum library does not link Ceres.
#ifndef DRUM_RTD_RTDESTIMATION_HPP
#define DRUM_RTD_RTDESTIMATION_HPP


#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

namespace drum
{

struct FitParameter
{
    std::string name;
    double initial;
    double lower;
    double upper;
};

//- Model predictions at the (fixed) measurement points for a parameter
//  vector. May throw InputError for an infeasible parameter set; the
//  optimiser then rejects the step.
using PredictionModel = std::function<std::vector<double>(const std::vector<double>&)>;

struct FitResult
{
    std::vector<std::string> names;
    std::vector<double> initial;
    std::vector<double> values;
    std::vector<double> standardErrors;     //!< from s^2 (J^T J)^-1; inf if not identifiable, NaN at a bound
    std::vector<bool> atBound;              //!< ended on a bound (held there for the covariance)
    std::vector<double> ciLow, ciHigh;      //!< 95 % (Student t, m - p dof)
    Eigen::MatrixXd correlation;            //!< parameter correlation matrix
    double sse = 0;
    int nData = 0;
    bool converged = false;
    int iterations = 0;
    std::string message;
};

struct FitOptions
{
    int maxIterations = 200;
    double functionTolerance = 1e-10;
    double parameterTolerance = 1e-10;
};

FitResult fitLeastSquares
(
    const PredictionModel& model,
    const std::vector<double>& measured,
    const std::vector<FitParameter>& parameters,
    const FitOptions& options = {}
);

//- Runs from the given start plus nStarts - 1 quasi-random starts over the
//  bounds (Halton points; an infinite upper bound is replaced by 4x the
//  initial value). Results sorted by SSE, best first; runs whose start was
//  infeasible are dropped.
std::vector<FitResult> multiStartFit
(
    const PredictionModel& model,
    const std::vector<double>& measured,
    const std::vector<FitParameter>& parameters,
    int nStarts,
    const FitOptions& options = {}
);

//- Two-sided Student-t quantile t_{1 - alpha/2, dof} (Hill 1970 expansion)
double studentTQuantile(double alpha, int dof);

//- How model and data are compared
struct RtdObjective
{
    //- false: residuals of E in 1/h (Lee's constant variance). true:
    //  residuals of ln(E + offset), which weights the tail like the peak
    bool logarithmic = false;
    double offset = 0.01;   //!< 1/h
};

//- Measured E (1/h) as the objective compares it
std::vector<double> transformForObjective(const std::vector<double>& E, const RtdObjective& objective);

} // namespace drum

#endif
