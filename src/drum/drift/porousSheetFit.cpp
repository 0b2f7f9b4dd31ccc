#include "drum/drift/porousSheetFit.hpp"

#include "drum/io/inputError.hpp"

#include <ceres/ceres.h>

#include <cmath>
#include <sstream>

namespace drum
{

namespace
{

struct LnResidual
{
    double N, lnVc;
    template<class T>
    bool operator()(const T* p, T* r) const
    {
        // p = (ln a, ln b): ln model = -b ln(1 + a N)
        r[0] = T(lnVc) + exp(p[1])*log(T(1.0) + exp(p[0])*T(N));
        return true;
    }
};

//- The curtain of every case of a table: the sweep's class mass fractions
//  over the diameter nodes (header "fixed: ... class_mass_fractions=w1,...");
//  0 without them
double tableSauterDiameter(const DriftTable& table)
{
    const std::optional<std::string> fractions = table.fixedSetting("class_mass_fractions");
    if (!fractions) return 0;
    std::vector<double> w;
    std::istringstream ws(*fractions);
    std::string v;
    while (std::getline(ws, v, ',')) w.push_back(std::stod(v));
    const auto& d = table.nodes(diameterAxis);
    if (w.size() != d.size())
    {
        throw InputError(table.file().string(), "header fixed class_mass_fractions",
            "needs one fraction per diameter node (" + std::to_string(d.size()) + ")");
    }
    return sauterDiameter(d, w);
}

} // namespace


PorousSheetFit fitPorousSheet(const DriftTable& table, const particleDrag::Gas& gas, const particleDrag::DragLaw& law)
{
    return fitPorousSheet(std::vector<const DriftTable*>{&table}, gas, law);
}


PorousSheetFit fitPorousSheet
(
    const std::vector<const DriftTable*>& tables,
    const particleDrag::Gas& gas,
    const particleDrag::DragLaw& law
)
{
    if (tables.empty()) throw InputError("", "tables", "porousSheet fit needs at least one table");
    std::vector<LnResidual> data;
    std::vector<double> d32s;
    for (const DriftTable* tp : tables)
    {
        const DriftTable& table = *tp;
        const double d32 = tableSauterDiameter(table);
        d32s.push_back(d32);
        for (const auto& row : table.rows())
        {
            DriftQuery q;
            q.gasVelocity = row.x[gasVelocityAxis];
            q.spillRate = row.x[spillRateAxis];
            q.fallHeight = row.x[fallHeightAxis];
            q.flightLength = row.x[flightLengthAxis];
            q.particleDensity = row.x[densityAxis];
            q.particleDiameter = row.x[diameterAxis];
            if (!(q.gasVelocity > 0 && q.fallHeight > 0 && q.spillRate > 0 && row.v.vcOverVg > 0)) continue;
            if (d32 > 0) q.particleDiameter = d32;
            data.push_back({porousSheetDragNumber(q, gas, law), std::log(row.v.vcOverVg)});
        }
    }
    // items joined with sep
    const auto joined = [](const std::vector<std::string>& items, const std::string& sep)
    {
        std::string out;
        for (const auto& i : items) out += (out.empty() ? "" : sep) + i;
        return out;
    };
    std::vector<std::string> names;
    for (const DriftTable* t : tables) names.push_back(t->file().string());
    const std::string files = joined(names, ",");
    if (data.size() < 3)
    {
        throw InputError(files, "rows", "porousSheet fit needs at least 3 rows with V_g, y, S and "
            "vc_over_vg > 0; the table has " + std::to_string(data.size()));
    }
    // Start: b = 1/2 (screen with bypass), a from the median N (aN ~ 1)
    std::vector<double> Ns;
    for (const auto& d : data) Ns.push_back(d.N);
    std::nth_element(Ns.begin(), Ns.begin() + Ns.size()/2, Ns.end());
    const double Nmed = Ns[Ns.size()/2] > 0 ? Ns[Ns.size()/2] : 1.0;
    double p[2] = {std::log(1/Nmed), std::log(0.5)};

    ceres::Problem problem;
    for (const auto& d : data)
    {
        problem.AddResidualBlock(new ceres::AutoDiffCostFunction<LnResidual, 1, 2>(new LnResidual(d)), nullptr, p);
    }
    problem.SetParameterLowerBound(p, 0, -30);
    problem.SetParameterUpperBound(p, 0, 30);
    problem.SetParameterLowerBound(p, 1, std::log(1e-3));
    problem.SetParameterUpperBound(p, 1, std::log(20.0));
    ceres::Solver::Options so;
    so.linear_solver_type = ceres::DENSE_QR;
    so.max_num_iterations = 200;
    so.logging_type = ceres::SILENT;
    ceres::Solver::Summary summary;
    ceres::Solve(so, &problem, &summary);

    PorousSheetFit fit;
    fit.converged = summary.termination_type == ceres::CONVERGENCE;
    fit.rows = int(data.size());
    fit.constants.a = std::exp(p[0]);
    fit.constants.b = std::exp(p[1]);
    double s2 = 0;
    for (const auto& d : data)
    {
        double r;
        d(p, &r);
        s2 += r*r;
    }
    fit.rmsLn = std::sqrt(s2/data.size());
    auto& pv = fit.constants.provenance;
    pv["fittedTo"] = files;
    for (const char* key : {"generator", "mesh", "cases", "dictionary"})
    {
        std::vector<std::string> v;
        for (const DriftTable* t : tables)
        {
            if (t->header().count(key)) v.push_back(t->header().at(key));
        }
        if (!v.empty()) pv[std::string("table_") + key] = joined(v, " | ");
    }
    pv["rows"] = std::to_string(fit.rows);
    std::vector<std::string> dtext;
    for (double d32 : d32s)
    {
        dtext.push_back(d32 > 0 ? "table Sauter diameter " + std::to_string(d32) + " m"
                                : "per class (no class_mass_fractions in the table header)");
    }
    pv["curtainDiameter"] = joined(dtext, " | ");
    std::ostringstream os;
    os.precision(4);
    os << fit.rmsLn;
    pv["rmsLnResidual"] = os.str();
    pv["converged"] = fit.converged ? "true" : "false";
    std::ostringstream g;
    g << "density " << gas.density << " kg/m3, viscosity " << gas.viscosity << " Pa s, drag " << law.name();
    pv["gas"] = g.str();
    return fit;
}

} // namespace drum
