// drumSegmentMesh: the cross-section of a flighted drum with every flight
// (and the kilning bed) cut out, extruded along the drum axis over one flight
// stagger and meshed with gmsh (its C++ API), from the same flight dictionary
// flightUnloading reads. Writes DIR/drumSegment.msh (MSH 2.2, for
// gmshToFoam) and DIR/flights.csv (each flight's root angle, tip, the name of
// its release patch and, from Lee's unloading model, the spill rate and layer
// thickness it releases at that angle). See README.md.
//
// Usage: drumSegmentMesh -dict FILE -length L [-out DIR] [-level coarse|medium|fine]
//                        [-plateThickness T] [-releaseWidth W]
#include "drum/flights/flightDictionary.hpp"
#include "drum/flights/unloadingModel.hpp"
#include "drum/io/inputError.hpp"
#include "drum/io/resultsFolder.hpp"
#include "drum/numerics/constants.hpp"

#include <gmsh.h>

#include <Eigen/Dense>

#include <algorithm>
#include <set>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using Eigen::Vector2d;

namespace
{

const char* const usageText =
    "Usage: drumSegmentMesh -dict FILE -length L [-out DIR] [-level coarse|medium|fine]\n"
    "                       [-plateThickness T] [-releaseWidth W]\n"
    "  -dict FILE          flight dictionary (YAML, as flightUnloading's)\n"
    "  -length L           axial length of the segment, m, (0, 100]: one flight stagger\n"
    "  -out DIR            output folder (default drumSegment; not the current folder)\n"
    "  -level L            mesh level (default coarse)\n"
    "  -plateThickness T   thickness of the flight plates, m, [0.002, 0.1] (default 0.02)\n"
    "  -releaseWidth W     width of each flight's release patch (tipNN) on the back face at the\n"
    "                      lip, m, [0.005, 0.5] and below half the tip section (default 0.04)\n";

struct Level
{
    std::string name;
    double farCells;    //!< cells across the drum diameter away from the flights
    double nearCells;   //!< at the flights the cell size is the plate thickness over this
    int axialLayers;    //!< layers along the segment
};

const std::vector<Level> levels = {
    {"coarse", 30, 0.5, 6}, {"medium", 45, 0.8, 9}, {"fine", 60, 1.2, 12}};

struct Options
{
    fs::path dict, out = "drumSegment";
    double length = 0;
    Level level = levels[0];
    double plate = 0.02;
    double release = 0.04;
};

double number(const std::string& opt, const char* text, double lo, double hi, bool loOpen)
{
    char* end = nullptr;
    const double v = std::strtod(text, &end);
    if (end == text || *end != '\0' || !std::isfinite(v) || (loOpen ? !(v > lo) : !(v >= lo)) || !(v <= hi))
    {
        std::ostringstream os;
        os << "'" << text << "' is not in the allowed range " << (loOpen ? "(" : "[") << lo << ", " << hi << "]";
        throw drum::InputError("", opt, os.str());
    }
    return v;
}

Options parse(int argc, char* argv[])
{
    Options o;
    bool haveLength = false;
    std::set<std::string> given;
    for (int i = 1; i < argc; ++i)
    {
        const std::string a = argv[i];
        if (a == "-help" || a == "-h")
        {
            std::cout << usageText;
            std::exit(0);
        }
        if (!given.insert(a).second)
        {
            throw drum::InputError("", a, "given twice: give it once");
        }
        if (i + 1 >= argc)
        {
            throw drum::InputError("", a, "needs a value (see -help)");
        }
        const char* v = argv[++i];
        if (a == "-dict") o.dict = v;
        else if (a == "-out") o.out = v;
        else if (a == "-length") { o.length = number(a, v, 0, 100, true); haveLength = true; }
        else if (a == "-plateThickness") o.plate = number(a, v, 0.002, 0.1, false);
        else if (a == "-releaseWidth") o.release = number(a, v, 0.005, 0.5, false);
        else if (a == "-level")
        {
            const auto l = std::find_if(levels.begin(), levels.end(), [&](const Level& x) { return x.name == v; });
            if (l == levels.end()) throw drum::InputError("", a, std::string("'") + v + "': allowed coarse, medium, fine");
            o.level = *l;
        }
        else throw drum::InputError("", a, "unknown option (see -help)");
    }
    if (o.dict.empty()) throw drum::InputError("", "-dict", "missing (see -help)");
    if (!haveLength) throw drum::InputError("", "-length", "missing: the segment's axial length, one flight stagger (see -help)");
    return o;
}

//- The normal of a flight section's direction d on the side of `back`
Vector2d backNormal(const Vector2d& d, const Vector2d& back)
{
    Vector2d n(-d.y(), d.x());
    return n.dot(back) < 0 ? Vector2d(-n) : n;
}

//- The two-section flight root -> elbow -> tip as one plate of thickness t
//  behind its leading face (on the side of `back`), the root pushed `beyond`
//  into the wall; the back face's bend is where the two offset lines meet.
//  The back face has a point w from the plate's end: the lip segment between
//  them is where the flight's curtain is released (its normal points away
//  from the material, down past the lip on the rising side and at the top)
std::vector<Vector2d> plateCorners(const Vector2d& root, const Vector2d& elbow, const Vector2d& tip,
                                   const Vector2d& back, double t, double beyond, double w)
{
    const Vector2d d1 = (elbow - root).normalized(), d2 = (tip - elbow).normalized();
    const Vector2d n1 = backNormal(d1, back), n2 = backNormal(d2, back);
    // root + t n1 + a d1 = tip + t n2 + b d2
    Eigen::Matrix2d m;
    m << d1.x(), -d2.x(), d1.y(), -d2.y();
    const Vector2d ab = m.colPivHouseholderQr().solve(tip + t*n2 - root - t*n1);
    const Vector2d bend = root + t*n1 + ab(0)*d1;
    const Vector2d a = root - beyond*d1;
    return {a, elbow, tip, Vector2d(tip + t*n2), Vector2d(tip + t*n2 - w*d2), bend, Vector2d(a + t*n1)};
}

int flightPlate(const Vector2d& root, const Vector2d& elbow, const Vector2d& tip, const Vector2d& back,
                double t, double beyond, double w)
{
    std::vector<int> pts;
    for (const Vector2d& x : plateCorners(root, elbow, tip, back, t, beyond, w))
    {
        pts.push_back(gmsh::model::occ::addPoint(x.x(), x.y(), 0));
    }
    std::vector<int> lines;
    for (std::size_t k = 0; k < pts.size(); ++k) lines.push_back(gmsh::model::occ::addLine(pts[k], pts[(k + 1) % pts.size()]));
    return gmsh::model::occ::addPlaneSurface({gmsh::model::occ::addCurveLoop(lines)});
}

gmsh::vectorpair inBox(int dim, const Vector2d& lo, const Vector2d& hi, double z0, double z1)
{
    gmsh::vectorpair out;
    gmsh::model::getEntitiesInBoundingBox(lo.x(), lo.y(), z0, hi.x(), hi.y(), z1, out, dim);
    return out;
}

} // namespace


int main(int argc, char* argv[])
{
    bool gmshUp = false;
    try
    {
        const Options o = parse(argc, argv);
        drum::FlightCase c = drum::readFlightDictionary(o.dict);
        const drum::LeeFlight flight(c.geometry, c.phiDeg, o.dict.string());
        const double R = c.geometry.drumRadius;
        const int nf = c.geometry.nFlights;
        const double t = o.plate;
        if (c.settings.bedDepth > 0)
        {
            // a bed surface passing a flight plate's corner closer than a quarter of
            // the plate's thickness leaves sliver cells there: the level is moved
            // (by steps of a tenth of the thickness, at most two thicknesses) until
            // it is clear of every corner, for the unloading and the mesh alike
            std::vector<double> ys;
            for (int j = 0; j < nf; ++j)
            {
                const double psi = std::fmod(c.snapshotAngleDeg + j*360.0/nf, 360.0);
                const Vector2d back = -Vector2d(std::cos(psi*drum::deg), std::sin(psi*drum::deg));
                for (const Vector2d& x : plateCorners(flight.rootPosition(psi), flight.elbowPosition(psi),
                                                      flight.tipPosition(psi), back, t, 2*t, o.release))
                {
                    ys.push_back(x.y());
                }
            }
            const auto clear = [&](double depth)
            {
                for (double y : ys) if (std::abs(-R + depth - y) < 0.25*t) return false;
                return true;
            };
            const double given = c.settings.bedDepth;
            double depth = given;
            for (int k = 1; !clear(depth); ++k)
            {
                if (k > 40)
                {
                    std::ostringstream os;
                    os << given << " m: no level within " << 2*t << " m of it is clear of the flights' corners";
                    throw drum::InputError(o.dict.string(), "drum.bedDepth", os.str());
                }
                depth = given + (k % 2 ? 1 : -1)*((k + 1)/2)*0.1*t;
            }
            if (depth != given)
            {
                std::cout << "drumSegmentMesh: bed level moved from " << given << " m to " << depth
                          << " m: clear of the flights' corners by a quarter plate thickness\n";
                c.settings.bedDepth = depth;
            }
        }
        const drum::UnloadingModel model(flight, c.settings, o.dict.string());
        if (t > 0.5*std::min(c.geometry.baseLength, c.geometry.tipLength))
        {
            throw drum::InputError("", "-plateThickness", "thicker than half the shorter flight section");
        }
        const double w = o.release;
        if (w > 0.5*c.geometry.tipLength - t)
        {
            std::ostringstream os;
            os << w << " m: wider than half the tip section less the plate thickness ("
               << 0.5*c.geometry.tipLength - t << " m)";
            throw drum::InputError("", "-releaseWidth", os.str());
        }
        const double bed = c.settings.bedDepth;

        const fs::path whole = drum::ownOutputFolder(o.out, "-out");

        gmsh::initialize();
        gmshUp = true;
        gmsh::option::setNumber("General.Terminal", 0);
        gmsh::model::add("drumSegment");
        const int disk = gmsh::model::occ::addDisk(0, 0, 0, R, R);

        // the flights at the snapshot: root angles psi_j = snapshot + j 360/N_F
        struct Flight { double psi; Vector2d root, elbow, tip, lip0, lip1; bool visible; };
        std::vector<Flight> flights;
        gmsh::vectorpair tools;
        for (int j = 0; j < nf; ++j)
        {
            Flight f;
            f.psi = std::fmod(c.snapshotAngleDeg + j*360.0/nf, 360.0);
            f.root = flight.rootPosition(f.psi);
            f.elbow = flight.elbowPosition(f.psi);
            f.tip = flight.tipPosition(f.psi);
            const Vector2d back = -Vector2d(std::cos(f.psi*drum::deg), std::sin(f.psi*drum::deg));
            const Vector2d d = (f.tip - f.elbow).normalized();
            f.lip0 = f.tip + t*backNormal(d, back);   // the release segment on the back face
            f.lip1 = f.lip0 - w*d;
            // a flight wholly inside the bed leaves nothing to mesh around
            f.visible = !(bed > 0 && std::max(f.tip.y(), f.elbow.y()) < -R + bed);
            flights.push_back(f);
            tools.push_back({2, flightPlate(f.root, f.elbow, f.tip, back, t, 2*t, w)});
        }
        if (bed > 0)
        {
            // the kilning bed's horizontal surface at -R + bedDepth (as flightUnloading's)
            tools.push_back({2, gmsh::model::occ::addRectangle(-R - 1, -R - 1, 0, 2*R + 2, bed + 1)});
        }
        gmsh::vectorpair section;
        std::vector<gmsh::vectorpair> map;
        gmsh::model::occ::cut({{2, disk}}, tools, section, map);
        gmsh::model::occ::synchronize();
        if (section.empty())
        {
            throw drum::InputError("", "flights", "nothing of the cross-section is left to mesh");
        }

        // sizes: fine at the flights, coarse in the open drum
        const double far = 2*R/o.level.farCells;
        const double near = std::min(far, t/o.level.nearCells);
        std::vector<double> flightCurves;
        {
            gmsh::vectorpair curves;
            gmsh::model::getBoundary(section, curves, true, false, false);
            for (const auto& [dim, tag] : curves)
            {
                double x0, y0, z0, x1, y1, z1;
                gmsh::model::getBoundingBox(1, std::abs(tag), x0, y0, z0, x1, y1, z1);
                // the drum wall's arcs reach the radius; flight edges lie inside it
                const double rmax = std::max({std::hypot(x0, y0), std::hypot(x1, y1), std::hypot(x0, y1), std::hypot(x1, y0)});
                if (rmax < R - 0.5*t) flightCurves.push_back(std::abs(tag));
            }
        }
        const int dist = gmsh::model::mesh::field::add("Distance");
        gmsh::model::mesh::field::setNumbers(dist, "CurvesList", flightCurves);
        gmsh::model::mesh::field::setNumber(dist, "NumPointsPerCurve", 50);
        const int thr = gmsh::model::mesh::field::add("Threshold");
        gmsh::model::mesh::field::setNumber(thr, "InField", dist);
        gmsh::model::mesh::field::setNumber(thr, "SizeMin", near);
        gmsh::model::mesh::field::setNumber(thr, "SizeMax", far);
        gmsh::model::mesh::field::setNumber(thr, "DistMin", 2*t);
        gmsh::model::mesh::field::setNumber(thr, "DistMax", 0.1*R);
        gmsh::model::mesh::field::setAsBackgroundMesh(thr);
        gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
        gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
        gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);

        // extrude along the axis: prisms in layers
        gmsh::vectorpair extruded;
        gmsh::model::occ::extrude(section, 0, 0, o.length, extruded, {o.level.axialLayers}, {}, true);
        gmsh::model::occ::synchronize();

        // patches: inlet (z = 0), outlet (z = L), each flight's release segment, the rest wall
        const double eps = 1e-6*R;
        const Vector2d lo(-R - 1, -R - 1), hi(R + 1, R + 1);
        std::vector<int> inlet, outlet, walls;
        for (const auto& [d, tag] : inBox(2, lo, hi, -eps, eps)) inlet.push_back(tag);
        for (const auto& [d, tag] : inBox(2, lo, hi, o.length - eps, o.length + eps)) outlet.push_back(tag);
        std::vector<std::vector<int>> tipFaces(nf);
        std::vector<int> used(inlet);
        used.insert(used.end(), outlet.begin(), outlet.end());
        for (int j = 0; j < nf; ++j)
        {
            if (!flights[j].visible) continue;
            // the extruded lip segment is the one surface inside its bounding box
            const Vector2d& p = flights[j].lip0;
            const Vector2d& q = flights[j].lip1;
            const Vector2d tol(1e-3*t, 1e-3*t);
            for (const auto& [d, tag] : inBox(2, Vector2d(p.cwiseMin(q) - tol), Vector2d(p.cwiseMax(q) + tol), -eps, o.length + eps))
            {
                tipFaces[j].push_back(tag);
                used.push_back(tag);
            }
        }
        gmsh::vectorpair all;
        gmsh::model::getEntities(all, 2);
        for (const auto& [d, tag] : all)
        {
            if (std::find(used.begin(), used.end(), tag) == used.end()) walls.push_back(tag);
        }
        gmsh::vectorpair volumes;
        gmsh::model::getEntities(volumes, 3);
        std::vector<int> vol;
        for (const auto& [d, tag] : volumes) vol.push_back(tag);
        gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, vol), "fluid");
        gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, inlet), "inlet");
        gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, outlet), "outlet");
        gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, walls), "wall");
        std::vector<std::string> tipPatch(nf);
        for (int j = 0; j < nf; ++j)
        {
            if (tipFaces[j].empty()) continue;
            std::ostringstream name;
            name << "tip" << std::setw(2) << std::setfill('0') << j;
            tipPatch[j] = name.str();
            gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, tipFaces[j]), tipPatch[j]);
        }

        gmsh::model::mesh::generate(3);
        std::vector<std::size_t> nodeTags;
        std::vector<double> coords, param;
        gmsh::model::mesh::getNodes(nodeTags, coords, param);
        std::vector<int> types;
        std::vector<std::vector<std::size_t>> elemTags, elemNodes;
        gmsh::model::mesh::getElements(types, elemTags, elemNodes, 3);
        std::size_t cells = 0;
        for (const auto& e : elemTags) cells += e.size();

        std::ostringstream table;
        table << "flight,root_angle_deg,root_x_m,root_y_m,elbow_x_m,elbow_y_m,tip_x_m,tip_y_m,patch,to_curtain,"
                 "spill_rate_kg_m_s,layer_thickness_m,fall_height_m,release_width_m,release_normal_x,release_normal_y,repose_angle_deg\n"
              << std::setprecision(10);
        int releasing = 0;
        for (int j = 0; j < nf; ++j)
        {
            const drum::ReleaseConditions r = model.at(flights[j].psi);
            const bool curtain = r.toCurtain && r.spillRate > 0 && !tipPatch[j].empty();
            releasing += curtain;
            table << j << ',' << flights[j].psi << ',' << flights[j].root.x() << ',' << flights[j].root.y() << ','
                  << flights[j].elbow.x() << ',' << flights[j].elbow.y() << ','
                  << flights[j].tip.x() << ',' << flights[j].tip.y() << ','
                  << (tipPatch[j].empty() ? std::string("-") : tipPatch[j]) << ',' << int(curtain) << ','
                  << (curtain ? r.spillRate : 0.0) << ',' << (curtain ? r.layerThickness : 0.0) << ','
                  << (curtain ? r.fallHeight : 0.0) << ',' << w << ',' << (flights[j].lip0 - flights[j].tip).x()/t << ',' << (flights[j].lip0 - flights[j].tip).y()/t << ',' << c.phiDeg << '\n';
        }

        drum::ResultsFolder results(whole);
        gmsh::option::setNumber("Mesh.MshFileVersion", 2.2);
        gmsh::option::setNumber("Mesh.Binary", 0);
        gmsh::option::setNumber("Mesh.SaveAll", 0);
        gmsh::write((results.path()/"drumSegment.msh").string());
        {
            std::ofstream f(results.path()/"flights.csv");
            f << table.str();
            if (!f.flush()) throw std::runtime_error("could not write " + (results.path()/"flights.csv").string());
        }
        gmsh::finalize();
        gmshUp = false;
        for (const auto& f : results.commit())
        {
            std::cout << "Kept your file " << (o.out/f).string() << '\n';
        }
        std::cout << "drumSegmentMesh: " << o.out.string() << "/drumSegment.msh: " << cells << " cells ("
                  << o.level.name << ", " << o.level.axialLayers << " layers over " << o.length << " m), "
                  << nf << " flights at phi " << c.phiDeg << " deg, " << releasing
                  << " releasing into the curtains; flights.csv beside it\n";
        return 0;
    }
    catch (const drum::InputError& e)
    {
        std::cerr << "drumSegmentMesh: input error: " << e.what() << '\n';
        if (gmshUp) gmsh::finalize();
        return 2;
    }
    catch (const std::exception& e)
    {
        std::cerr << "drumSegmentMesh: error: " << e.what() << '\n';
        if (gmshUp) gmsh::finalize();
        return 1;
    }
    catch (const std::string& e)     // gmsh's API reports its errors so
    {
        std::cerr << "drumSegmentMesh: gmsh: " << e << '\n';
        if (gmshUp) gmsh::finalize();
        return 1;
    }
}
