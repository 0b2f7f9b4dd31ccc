// particleDrag: single-particle drag laws shared by the curtain solver
// (OpenFOAM side) and the drum model (CMake side).
//
// One source of truth: every drag coefficient used anywhere in the project is
// computed here. The header is kept C++11-clean because OpenFOAM v1912 code
// includes it.
#ifndef PARTICLEDRAG_DRAGLAW_HPP
#define PARTICLEDRAG_DRAGLAW_HPP

#include <string>
#include <vector>

namespace particleDrag
{

//- The drag correlations the project knows.
enum class DragLawType
{
    SchillerNaumann,    //!< Sherritt 1991 Eqs 9-10 (no upper Re cut-off, as in ADVANCE.C)
    HaiderLevenspiel,   //!< Haider & Levenspiel 1989 (Lee 2008 Eq 6.1), needs sphericity
    LeeSugar,           //!< Lee 2008 Eq 6.6, raw sugar crystals
    WenYu,              //!< Wen & Yu 1966: Schiller-Naumann at alphaC*Re times alphaC^-1.65
    Gidaspow            //!< Gidaspow 1994: Wen-Yu for alphaC >= 0.8, Ergun below
};

//- A drag law: which correlation, and the shape parameter some need.
//  A value type: cheap to copy, no state beyond its parameters.
struct DragLaw
{
    DragLawType type = DragLawType::SchillerNaumann;

    //- Sphericity (0, 1], used by HaiderLevenspiel only
    double sphericity = 1.0;

    //- Drag coefficient of a particle.
    //  Re     : particle Reynolds number rho_c |U_r| d / mu_c, based on the
    //           superficial slip, Re >= 0
    //  alphaC : continuous-phase (gas) volume fraction, (0, 1]; 1 for a lone
    //           particle. Laws without a swarm correction ignore it.
    //  The returned Cd is defined so that the drag force per unit volume of
    //  mixture is  K |U_r| with  K = 3/4 Cd rho_c alphaD |U_r| / d.
    //  At Re -> 0 it behaves like 24/Re; Cd(0) is +inf.
    double Cd(double Re, double alphaC = 1.0) const;

    //- Cd*Re, finite at Re = 0 (the form a solver needs where slip vanishes)
    double CdRe(double Re, double alphaC = 1.0) const;

    //- Validate parameters; throws std::invalid_argument naming the problem
    void check() const;

    //- The name used in dictionaries ("SchillerNaumann", ...)
    std::string name() const;
};

//- All dictionary names, in declaration order
std::vector<std::string> dragLawNames();

//- Construct from a dictionary name; throws std::invalid_argument listing
//  the valid names when the name is unknown
DragLaw dragLawFromName(const std::string& name, double sphericity = 1.0);


// Plain correlations, for readers who want the formula by its name.
// All take Re >= 0 and return Cd (Re = 0 gives +inf).

//- Schiller & Naumann (1933), as coded by Sherritt 1991 (Eqs 9-10):
//  Cd = 24/Re for Re < 0.2, else 24/Re (1 + 0.15 Re^0.687), no cut-off
double schillerNaumannCd(double Re);

//- Haider & Levenspiel (1989), Lee 2008 Eq 6.1, sphericity in (0, 1]
double haiderLevenspielCd(double Re, double sphericity);

//- Lee 2008 Eq 6.6 ("modified Schiller-Naumann", raw sugar, Re 70-300):
//  Cd = 68/Re (1 + 0.004 Re^0.99)
double leeSugarCd(double Re);

} // namespace particleDrag

#endif
