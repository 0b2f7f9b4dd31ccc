#include "particleDrag/dragLaw.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace particleDrag
{

namespace
{

constexpr double inf = std::numeric_limits<double>::infinity();

void checkRe(double Re)
{
    if (!(Re >= 0.0) || !std::isfinite(Re))
    {
        std::ostringstream os;
        os << "particle Reynolds number " << Re << " outside [0, inf)";
        throw std::invalid_argument(os.str());
    }
}

void checkAlphaC(double alphaC)
{
    if (!(alphaC > 0.0 && alphaC <= 1.0))
    {
        std::ostringstream os;
        os << "gas volume fraction alphaC = " << alphaC << " outside (0, 1]";
        throw std::invalid_argument(os.str());
    }
}

// Schiller-Naumann Cd*Re (finite at Re = 0)
double schillerNaumannCdRe(double Re)
{
    // Sherritt 1991 Eq 9 (Re < 0.2) and Eq 10, no cut-off at Re = 1000
    return Re < 0.2 ? 24.0 : 24.0*(1.0 + 0.15*std::pow(Re, 0.687));
}

// Haider-Levenspiel Cd*Re
double haiderLevenspielCdRe(double Re, double phi)
{
    // Lee 2008 Eq 6.1 in the form of Haider & Levenspiel (1989) Eq 10:
    //   Cd = 24/Re (1 + A Re^B) + C Re/(Re + D)
    // The coefficient 12.2584 of D is the original paper's; Lee's print
    // (12.5284) transposes two digits (see src/particleDrag/README.md).
    const double A = std::exp(2.3288 - 6.4581*phi + 2.4486*phi*phi);
    const double B = 0.0964 + 0.5565*phi;
    const double C =
        std::exp(4.905 - 13.8944*phi + 18.4222*phi*phi - 10.2599*phi*phi*phi);
    const double D =
        std::exp(1.4681 + 12.2584*phi - 20.7322*phi*phi + 15.8855*phi*phi*phi);
    return 24.0*(1.0 + A*std::pow(Re, B)) + C*Re*Re/(Re + D);
}

// Lee 2008 Eq 6.6 Cd*Re
double leeSugarCdRe(double Re)
{
    return 68.0*(1.0 + 0.004*std::pow(Re, 0.99));
}

// Wen & Yu (1966) Cd*Re, on the superficial Re, including the voidage
// function alphaC^-2.65 divided by the alphaC carried by K (OpenFOAM's
// WenYu: Cd = 24/Res (1 + 0.15 Res^0.687) alphaC^-1.65, Res = alphaC Re)
double wenYuCdRe(double Re, double alphaC)
{
    const double Res = alphaC*Re;
    const double CdsRes =
        Res < 1000.0 ? 24.0*(1.0 + 0.15*std::pow(Res, 0.687)) : 0.44*Res;
    return CdsRes/alphaC*std::pow(alphaC, -1.65);
}

// Gidaspow (1994): Ergun below alphaC = 0.8, Wen-Yu above. Ergun written as
// an equivalent Cd for K = 3/4 Cd rho_c alphaD |U_r|/d:
//   K_Ergun = 150 alphaD^2 mu/(alphaC d^2) + 1.75 alphaD rho_c |U_r|/d
//   => Cd Re = 200 alphaD/alphaC + 7/3 Re
double gidaspowCdRe(double Re, double alphaC)
{
    if (alphaC >= 0.8)
    {
        return wenYuCdRe(Re, alphaC);
    }
    const double alphaD = 1.0 - alphaC;
    return 200.0*alphaD/alphaC + 7.0/3.0*Re;
}

} // namespace


double schillerNaumannCd(double Re)
{
    checkRe(Re);
    return Re > 0 ? schillerNaumannCdRe(Re)/Re : inf;
}

double haiderLevenspielCd(double Re, double sphericity)
{
    DragLaw law{DragLawType::HaiderLevenspiel, sphericity};
    return law.Cd(Re);
}

double leeSugarCd(double Re)
{
    checkRe(Re);
    return Re > 0 ? leeSugarCdRe(Re)/Re : inf;
}


double DragLaw::CdRe(double Re, double alphaC) const
{
    checkRe(Re);
    checkAlphaC(alphaC);
    switch (type)
    {
        case DragLawType::SchillerNaumann:
            return schillerNaumannCdRe(Re);
        case DragLawType::HaiderLevenspiel:
            check();
            return haiderLevenspielCdRe(Re, sphericity);
        case DragLawType::LeeSugar:
            return leeSugarCdRe(Re);
        case DragLawType::WenYu:
            return wenYuCdRe(Re, alphaC);
        case DragLawType::Gidaspow:
            return gidaspowCdRe(Re, alphaC);
    }
    throw std::logic_error("particleDrag: unhandled drag law");
}

double DragLaw::Cd(double Re, double alphaC) const
{
    const double cdre = CdRe(Re, alphaC);
    return Re > 0 ? cdre/Re : inf;
}

void DragLaw::check() const
{
    if (!(sphericity > 0.0 && sphericity <= 1.0))
    {
        std::ostringstream os;
        os << "sphericity " << sphericity << " outside (0, 1]";
        throw std::invalid_argument(os.str());
    }
}

std::string DragLaw::name() const
{
    return dragLawNames()[static_cast<std::size_t>(type)];
}

std::vector<std::string> dragLawNames()
{
    return {"SchillerNaumann", "HaiderLevenspiel", "LeeSugar", "WenYu", "Gidaspow"};
}

DragLaw dragLawFromName(const std::string& name, double sphericity)
{
    const auto names = dragLawNames();
    for (std::size_t i = 0; i < names.size(); ++i)
    {
        if (names[i] == name)
        {
            DragLaw law{static_cast<DragLawType>(i), sphericity};
            law.check();
            return law;
        }
    }
    std::ostringstream os;
    os << "unknown drag law '" << name << "'; valid names are:";
    for (const auto& n : names)
    {
        os << ' ' << n;
    }
    throw std::invalid_argument(os.str());
}

} // namespace particleDrag
