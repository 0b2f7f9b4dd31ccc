// Dynamic (kinetic) angle of repose relations, each with its source:
//  - Schofield & Glikin (1962) kinetic angle, in the form and angle
//    convention of Sherritt 1991 Eq 6-7 (Sherritt 1991 §2.2, checked
//    there: spread 4.58 deg at Fr = 0.04). Lee 2008 prints it as Eq 2.1 with
//    psi in another convention; we use Sherritt's transcription.
//  - Britton et al. (2006) raw-sugar moisture relation, Lee 2008 Eq 7.2, and
//    the moisture profile along the dryer, Eq 7.3.
//  - Lee 2008 Table 5.5 measured in-flight angles (mean and SD per rig run)
//    and Table 5.6 surface-layer velocities, from lee_unloading_experiments.csv.
#ifndef DRUM_FLIGHTS_ANGLEOFREPOSE_HPP
#define DRUM_FLIGHTS_ANGLEOFREPOSE_HPP

#include <filesystem>
#include <string>
#include <vector>

namespace drum
{

//- Fr = R omega^2 / g (Sherritt 1991 Eq 7, = D omega^2 / 2g)
double drumFroudeNumber(double drumRadius, double speedRpm, double gravity = 9.81);

//- Sherritt's theta [deg] of a flight tip from Lee's tip angle from the drum
//  bottom (both in the direction of rotation): theta = 0 where the tip crosses
//  the centreline going down, 180 where it crosses going up
double sherrittThetaDeg(double tipAngleFromBottomDeg);

//- Kinetic angle of repose [deg] (Schofield & Glikin 1962; Sherritt 1991 Eq 6):
//  phi = atan[(mu - Fr (cos th - mu sin th)) / (1 + Fr (mu cos th + sin th))]
double schofieldGlikinAngleDeg(double mu, double froude, double thetaDeg);

//- Britton et al. raw sugar, Lee 2008 Eq 7.2: phi [deg] = 1222.2 w + 34.5,
//  w [kg/kg]; InputError unless 0 <= w < (90 - 34.5)/1222.2
double brittonMoistureAngleDeg(double moisture, const std::string& entry = "material.moisture");

//- Lee 2008 Eq 7.3: w_i = w_in exp(ln(w_out/w_in) (i-1)/(N-1)), i = 1..N
double moistureProfile(int i, int n, double wInlet, double wOutlet);

//- One row of Lee 2008 Tables 5.4-5.6 (lee_unloading_experiments.csv)
struct LeeRigExperiment
{
    int experiment = 0;
    int repeat = 0;
    std::string flight;        //!< alternative, half_scale, full_scale
    bool abrasiveTip = false;
    std::string material;      //!< filter_sand, zeolite, river_sand
    double speedRpm = 0.0;     //!< Table 5.4 (the data README: use it over Table 5.5)
    double phiMeanDeg = 0.0;   //!< Table 5.5
    double phiSdDeg = 0.0;
    double layerVelocityMean = 0.0;  //!< Table 5.6 [m/s] (0 when not measured)
    double layerVelocitySd = 0.0;
};

//- Read lee_unloading_experiments.csv; InputError on a malformed file
std::vector<LeeRigExperiment> readLeeRigExperiments(const std::filesystem::path& csv);

} // namespace drum

#endif
