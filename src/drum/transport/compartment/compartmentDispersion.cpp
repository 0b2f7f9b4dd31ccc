#include "drum/transport/compartment/compartmentDispersion.hpp"

#include "drum/io/inputError.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace drum
{

namespace
{
const std::string entry = "model.denseDispersion";
} // namespace


std::string toString(const DispersionBed bed)
{
    return bed == DispersionBed::kiln ? "kiln" : "passive";
}


DispersionBed parseDispersionBed(const std::string& word, const std::string& name, const std::string& file)
{
    if (word == "kiln") return DispersionBed::kiln;
    if (word == "passive") return DispersionBed::passive;
    throw InputError(file, name, "unknown value '" + word + "'; allowed: kiln, passive");
}


Eigen::VectorXd dispersionBedMass(const CompartmentSteadyState& st, const DispersionBed bed)
{
    return bed == DispersionBed::kiln ? st.kilnMass : st.passiveMass;
}


TracerSystem withPassiveDispersion
(
    const TracerSystem& sys,
    const CompartmentSteadyState& st,
    const PassiveDispersion& d,
    PassiveDispersionSummary* summary,
    const std::string& file
)
{
    const int n = int(st.passiveMass.size());
    if (summary) *summary = PassiveDispersionSummary{};
    if (d.coefficient.empty())
    {
        return sys;
    }
    if (d.coefficient.size() != 1 && int(d.coefficient.size()) != n)
    {
        throw InputError(file, entry, "needs one D_z or one per slice (" + std::to_string(n) + "), got "
            + std::to_string(d.coefficient.size()));
    }
    for (double D : d.coefficient)
    {
        requireInRange(D, 0.0, 1.0, entry + " D_z [m2/s]", file);
    }
    if (!(d.sliceLength > 0) || !std::isfinite(d.sliceLength))
    {
        throw InputError(file, entry, "slice length must be > 0 m");
    }
    if (sys.size() < 2*n)
    {
        throw InputError(file, entry, "tracer system smaller than the 2 N slice states");
    }
    auto Dof = [&](int i) { return d.coefficient.size() == 1 ? d.coefficient[0] : d.coefficient[i]; };
    const Eigen::VectorXd Mb = dispersionBedMass(st, d.bed);
    const double dz = d.sliceLength;

    std::vector<Eigen::Triplet<double>> trip;
    for (int k = 0; k < sys.K.outerSize(); ++k)
    {
        for (Eigen::SparseMatrix<double>::InnerIterator it(sys.K, k); it; ++it)
        {
            trip.emplace_back(it.row(), it.col(), it.value());
        }
    }
    PassiveDispersionSummary s;
    int numCount = 0;
    for (int i = 0; i + 1 < n; ++i)
    {
        const bool left = Mb(i) > 0, right = Mb(i + 1) > 0;
        if (!left && !right)
        {
            continue;
        }
        // D_z at the face: mean over the sides that have a bed
        const double D = left && right ? 0.5*(Dof(i) + Dof(i + 1)) : left ? Dof(i) : Dof(i + 1);
        const double Mface = 0.5*(Mb(i) + Mb(i + 1));   // bed mass per slice at the face, kg
        // upwind part of the bed flow P_i -> P_i+1: u_b dz/2, u_b = F_k dz/M_b
        double numerical = 0;
        if (left && st.kilnFlow(i) > 0)
        {
            numerical = 0.5*st.kilnFlow(i)*dz*dz/Mb(i);
            ++numCount;
        }
        const double added = d.subtractNumerical ? std::max(0.0, D - numerical) : D;
        ++s.boundaries;
        s.meanCoefficient += D;
        s.meanNumerical += numerical;
        s.meanAdded += added;
        s.numericalExceeds += numerical > D ? 1 : 0;
        // Sherritt 2001 Eq 27, second difference: G = D M_b/dz^2 kg/s each way
        const double G = added*Mface/(dz*dz);
        if (!(G > 0))
        {
            continue;
        }
        const int p = CompartmentNetwork::passiveIndex(i), q = CompartmentNetwork::passiveIndex(i + 1);
        const double kp = G/st.passiveMass(i), kq = G/st.passiveMass(i + 1);
        trip.emplace_back(p, p, -kp);
        trip.emplace_back(q, p, kp);
        trip.emplace_back(q, q, -kq);
        trip.emplace_back(p, q, kq);
    }
    if (s.boundaries > 0)
    {
        s.meanCoefficient /= s.boundaries;
        s.meanAdded /= s.boundaries;
    }
    if (numCount > 0)
    {
        s.meanNumerical /= numCount;
    }
    if (summary) *summary = s;

    TracerSystem out;
    out.K.resize(sys.size(), sys.size());
    out.K.setFromTriplets(trip.begin(), trip.end());
    out.K.makeCompressed();
    out.b = sys.b;
    out.c = sys.c;
    return out;
}


PassiveSherritt2001 sherritt2001PassiveDispersion
(
    const CompartmentSteadyState& st,
    const DispersionBed bed,
    const PassiveDispersionDrum& drum,
    const std::string& file
)
{
    requirePositive(drum.bulkDensity, "dispersion: bulk density [kg/m3]", file);
    requirePositive(drum.sliceLength, "dispersion: slice length [m]", file);
    AxialDispersionInput in;
    in.drumDiameter = drum.drumDiameter;
    in.speed = drum.speed;
    in.particleDiameter = drum.particleDiameter;
    // the drum-level departures (regime, diameter, particle size) do not
    // depend on X: take them from one evaluation at a fill inside the range
    in.fill = 0.1;
    PassiveSherritt2001 r;
    r.reference = sherritt2001AxialDispersion(in, file);
    r.warnings = r.reference.warnings;

    const Eigen::VectorXd Mb = dispersionBedMass(st, bed);
    const int n = int(Mb.size());
    int clamped = 0, above = 0;
    r.coefficient.assign(n, 0.0);
    r.fill.assign(n, 0.0);
    for (int i = 0; i < n; ++i)
    {
        r.fill[i] = bedFillFraction(Mb(i)/(drum.bulkDensity*drum.sliceLength), drum.drumDiameter);
        if (!(Mb(i) > 0))
        {
            continue;
        }
        in.fill = r.fill[i];
        const AxialDispersionResult ri = sherritt2001AxialDispersion(in, file);
        r.coefficient[i] = ri.Dz;
        clamped += ri.fillUsed > in.fill ? 1 : 0;
        above += in.fill >= 0.5 ? 1 : 0;
        if (r.bedSlices++ == 0)
        {
            r.minFill = r.maxFill = in.fill;
            r.minDz = r.maxDz = ri.Dz;
        }
        r.minFill = std::min(r.minFill, in.fill);
        r.maxFill = std::max(r.maxFill, in.fill);
        r.minDz = std::min(r.minDz, ri.Dz);
        r.maxDz = std::max(r.maxDz, ri.Dz);
    }
    if (r.bedSlices == 0)
    {
        throw InputError(file, entry, "sherritt2001: no slice has a " + toString(bed)
            + " bed (every passive cell at or below its design load); use model.dispersionBed: passive or none");
    }
    if (clamped > 0)
    {
        r.warnings.push_back("bed fill X below 0.03 in " + std::to_string(clamped) + " of "
            + std::to_string(r.bedSlices) + " slices: clamped to 0.03 (D_z ~ X^d diverges)");
    }
    if (above > 0)
    {
        r.warnings.push_back("bed fill X >= 0.5 in " + std::to_string(above) + " slices: outside the regression (X < 0.5)");
    }
    std::ostringstream os;
    os << "Sherritt 2001 Eq 51 (" << bedRegimeName(r.reference.regime) << ", n/n_c " << r.reference.speedRatio
       << ", " << toString(bed) << " bed in " << r.bedSlices << " of " << n << " slices, X " << r.minFill
       << "-" << r.maxFill << ", d_p " << drum.particleDiameter*1e6 << " um): D_z " << r.minDz << "-" << r.maxDz
       << " m2/s";
    r.note = os.str();
    return r;
}

} // namespace drum
