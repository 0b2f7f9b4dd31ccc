// Drift models on the table (table, tableVc), the porousSheet reduced model
// (limits, fit recovering known constants from a table it generated), the
// factory and the drift dictionary
#include "drum/drift/driftDictionary.hpp"
#include "drum/drift/porousSheetDrift.hpp"
#include "drum/drift/porousSheetFit.hpp"
#include "drum/drift/tableDrift.hpp"
#include "drum/io/inputError.hpp"
#include "particleDrag/loneParticleFall.hpp"
#include "syntheticTable.hpp"
#include "testTempDir.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>

using namespace drum;
namespace fs = std::filesystem;

namespace
{

fs::path tmpDir()
{
    return testTempDir("driftModelsTest");
}

const particleDrag::Gas air = particleDrag::Gas::air(20);

DriftQuery query(const synthetic::Point& p)
{
    DriftQuery q;
    q.gasVelocity = p[0];
    q.spillRate = p[1];
    q.fallHeight = p[2];
    q.flightLength = p[3];
    q.particleDensity = p[4];
    q.particleDiameter = p[5];
    return q;
}

// A table whose drift is the lone particle at V_c = r V_g with a given r(point)
fs::path loneParticleTable(const std::string& name, const std::function<double(const synthetic::Point&)>& ratio)
{
    const fs::path f = tmpDir()/name;
    synthetic::write(f, synthetic::table(synthetic::defaultGrid(), [&](const synthetic::Point& p) -> synthetic::Values
    {
        const double r = ratio(p);
        const double d = particleDrag::loneParticleAdvance({}, {p[5], p[4]}, air, r*p[0], p[2]);
        return {r, d, 1.0};
    }));
    return f;
}

} // namespace


TEST(TableDrift, TableAndTableVcOnNodes)
{
    const auto f = loneParticleTable("half.csv", [](const synthetic::Point&) { return 0.5; });
    const auto table = std::make_shared<const DriftTable>(DriftTable::read(f));
    const TableDrift td(table);
    const TableVcDrift tv(table, air);
    const IsolatedParticleDrift iso(air);
    for (const auto& r : table->rows())
    {
        DriftQuery q = query(r.x);
        EXPECT_NEAR(td.displacement(q), r.v.drift, 1e-12);
        DriftQuery half = q;
        half.gasVelocity *= 0.5;
        EXPECT_NEAR(tv.displacement(q), iso.displacement(half), 1e-12);
        // incline: free slide added to the level table
        q.incline = 0.05;
        EXPECT_NEAR(td.displacement(q), r.v.drift + q.fallHeight*std::sin(0.05), 1e-12);
    }
    // between nodes tableVc is exact (V_c/V_g constant), table interpolates
    const DriftQuery mid = query({2.2, 5, 3, 1.3, 2000, 3e-4});
    DriftQuery half = mid;
    half.gasVelocity *= 0.5;
    EXPECT_NEAR(tv.displacement(mid), iso.displacement(half), 1e-12);
    EXPECT_NEAR(td.displacement(mid)/iso.displacement(half), 1.0, 0.15);
}


TEST(TableDrift, StillGasHasNoGasDriftAndNeverQueriesTheTable)
{
    // The synthetic grid starts above 0 m/s: a query at V_g = 0 is outside
    // it, and a refusing table would throw if it were asked
    const auto f = loneParticleTable("still.csv", [](const synthetic::Point&) { return 0.5; });
    const auto table = std::make_shared<const DriftTable>(DriftTable::read(f));
    ASSERT_GT(table->rows().front().x[0], 0.0);
    const TableDrift td(table);
    DriftQuery q = query(table->rows().front().x);
    q.gasVelocity = 0;
    EXPECT_EQ(td.displacement(q), 0.0);
    q.incline = 0.03;   // only the free slide down the incline remains
    EXPECT_NEAR(td.displacement(q), q.fallHeight*std::sin(0.03), 1e-15);
    // a query with gas outside the grid is still refused
    q.gasVelocity = 0.5*table->rows().front().x[0];
    EXPECT_THROW(td.displacement(q), InputError);
}


TEST(PorousSheet, DiluteCurtainIsTheIsolatedParticleDenseShieldsStrongly)
{
    PorousSheetConstants c;
    c.a = 20;
    c.b = 0.5;
    const PorousSheetDrift m(c, air);
    const IsolatedParticleDrift iso(air);
    DriftQuery q = query({3, 1e-6, 5, 2, 2650, 5e-4});
    EXPECT_NEAR(m.velocityRatio(q), 1.0, 1e-4);
    EXPECT_NEAR(m.displacement(q), iso.displacement(q), 1e-4*iso.displacement(q));
    q.spillRate = 0;
    EXPECT_EQ(m.velocityRatio(q), 1.0);
    EXPECT_DOUBLE_EQ(m.displacement(q), iso.displacement(q));
    // ratio falls monotonically with spill rate and flight length, rises with fall height
    double last = 1;
    for (double S : {1.0, 5.0, 20.0, 100.0, 1000.0})
    {
        q.spillRate = S;
        const double r = m.velocityRatio(q);
        EXPECT_LT(r, last);
        last = r;
    }
    EXPECT_LT(last, 0.05);   // dense: strong shielding
    EXPECT_LT(m.displacement(q), 0.05*iso.displacement(q) + 1e-12);
    q.spillRate = 20;
    DriftQuery longer = q, higher = q;
    longer.flightLength = 4;
    higher.fallHeight = 10;
    EXPECT_LT(m.velocityRatio(longer), m.velocityRatio(q));
    EXPECT_GT(m.velocityRatio(higher), m.velocityRatio(q));
    // dense power law: (aN)^-b
    q.spillRate = 1e5;
    EXPECT_NEAR(std::log(m.velocityRatio(q)), -c.b*std::log(c.a*m.dragNumber(q)), 1e-3);
}


TEST(PorousSheet, FitRecoversConstantsOfATableItGenerated)
{
    PorousSheetConstants truth;
    truth.a = 3.7;
    truth.b = 0.62;
    const PorousSheetDrift model(truth, air);
    const auto f = loneParticleTable("porous.csv", [&](const synthetic::Point& p) { return model.velocityRatio(query(p)); });
    const DriftTable table = DriftTable::read(f);
    const PorousSheetFit fit = fitPorousSheet(table, air);
    EXPECT_TRUE(fit.converged);
    EXPECT_EQ(fit.rows, int(table.size()));
    EXPECT_NEAR(fit.constants.a/truth.a, 1.0, 1e-4);
    EXPECT_NEAR(fit.constants.b/truth.b, 1.0, 1e-4);
    EXPECT_LT(fit.rmsLn, 1e-6);
    EXPECT_EQ(fit.constants.provenance.at("fittedTo"), f.string());
    // constants file round trip
    const fs::path cf = tmpDir()/"porousSheet.yaml";
    writePorousSheetConstants(cf, fit.constants);
    const auto back = readPorousSheetConstants(cf);
    EXPECT_NEAR(back.a, fit.constants.a, 1e-8*fit.constants.a);
    EXPECT_NEAR(back.b, fit.constants.b, 1e-8);
    EXPECT_EQ(back.provenance.at("rows"), std::to_string(fit.rows));
    // malformed constants
    synthetic::write(tmpDir()/"bad.yaml", "model: porousSheet\na_per_m: -1\nb: 0.5\n");
    EXPECT_THROW(readPorousSheetConstants(tmpDir()/"bad.yaml"), InputError);
    synthetic::write(tmpDir()/"other.yaml", "model: other\na_per_m: 1\nb: 0.5\n");
    EXPECT_THROW(readPorousSheetConstants(tmpDir()/"other.yaml"), InputError);
    EXPECT_THROW(readPorousSheetConstants(tmpDir()/"absent.yaml"), InputError);
}


TEST(PorousSheet, OneFitOverSeveralTables)
{
    PorousSheetConstants truth;
    truth.a = 1.9;
    truth.b = 0.8;
    const PorousSheetDrift model(truth, air);
    const auto gen = [&](const synthetic::Point& p) { return model.velocityRatio(query(p)); };
    const DriftTable t1 = DriftTable::read(loneParticleTable("porousA.csv", gen));
    const DriftTable t2 = DriftTable::read(loneParticleTable("porousB.csv", gen));
    const PorousSheetFit fit = fitPorousSheet(std::vector<const DriftTable*>{&t1, &t2}, air);
    EXPECT_TRUE(fit.converged);
    EXPECT_EQ(fit.rows, int(t1.size() + t2.size()));
    EXPECT_NEAR(fit.constants.a/truth.a, 1.0, 1e-4);
    EXPECT_NEAR(fit.constants.b/truth.b, 1.0, 1e-4);
    EXPECT_EQ(fit.constants.provenance.at("fittedTo"), t1.file().string() + "," + t2.file().string());
    EXPECT_THROW(fitPorousSheet(std::vector<const DriftTable*>{}, air), InputError);
}


TEST(DriftFactory, NamesTablesAndErrors)
{
    const auto f = loneParticleTable("factory.csv", [](const synthetic::Point& p) { return 1.0/(1 + 0.02*p[1]); });
    DriftSettings s;
    s.table = f;
    for (const auto& name : {"isolated", "sherritt", "table", "tableVc"})
    {
        s.model = name;
        EXPECT_EQ(makeDriftModel(s, air)->name(), name);
    }
    s.model = "magic";
    try
    {
        makeDriftModel(s, air);
        FAIL();
    }
    catch (const InputError& e)
    {
        for (const auto& n : driftModelNames()) EXPECT_NE(std::string(e.what()).find(n), std::string::npos) << e.what();
    }
    EXPECT_THROW(makeDriftModel("magic", air), InputError);
    s.model = "table";
    s.table = tmpDir()/"absent.csv";
    EXPECT_THROW(makeDriftModel(s, air), InputError);
    s.model = "porousSheet";
    s.constants = tmpDir()/"absent.yaml";
    EXPECT_THROW(makeDriftModel(s, air), InputError);
}


TEST(DriftDictionary, ReadsModelTableAndPolicy)
{
    const fs::path dir = tmpDir();
    const auto f = loneParticleTable("dict.csv", [](const synthetic::Point&) { return 0.7; });
    auto read = [&](const std::string& yaml) { return readDriftSettings(YAML::Load(yaml), "drumDict", dir); };
    auto s = read("model: {drift: tableVc}\ndrift: {table: dict.csv, outside: clamp}\n");
    EXPECT_EQ(s.model, "tableVc");
    EXPECT_EQ(s.table, dir/"dict.csv");
    EXPECT_EQ(s.outside, OutOfRangePolicy::clamp);
    EXPECT_EQ(read("model: {type: compartment}\n").model, "sherritt");
    EXPECT_EQ(read("model: {drift: table}\n").outside, OutOfRangePolicy::refuse);
    const auto m = makeDriftModel(s, air);
    EXPECT_EQ(m->name(), "tableVc");
    EXPECT_THROW(read("model: {drift: cfdMagic}\n"), InputError);
    EXPECT_THROW(read("model: {drift: table}\ndrift: {table: nothere.csv}\n"), InputError);
    EXPECT_THROW(read("model: {drift: table}\ndrift: {outside: sometimes}\n"), InputError);
    EXPECT_THROW(read("model: {drift: table}\ndrift: {tabel: dict.csv}\n"), InputError);
}


TEST(PorousSheet, FitUsesTheCurtainSauterDiameterFromTheTableHeader)
{
    // A table from a curtain of the three diameter nodes in given shares: one
    // V_c/V_g for all classes of a case, set by the curtain's d32
    PorousSheetConstants truth;
    truth.a = 2.5;
    truth.b = 0.4;
    const auto grid = synthetic::defaultGrid();
    const std::vector<double> w{0.2, 0.5, 0.3};
    const double d32 = sauterDiameter(grid[5], w);
    EXPECT_NEAR(d32, 1/(0.2/1e-4 + 0.5/5e-4 + 0.3/2e-3), 1e-15);
    const PorousSheetDrift model(truth, air, {}, d32);
    std::string text = synthetic::table(grid, [&](const synthetic::Point& p) -> synthetic::Values
    {
        return {model.velocityRatio(query(p)), 0.1, 1.0};
    });
    const std::string fixed = "# fixed: release_velocity_m_s=0";
    text.replace(text.find(fixed), fixed.size(), fixed + " class_mass_fractions=0.2,0.5,0.3");
    const fs::path f = tmpDir()/"sauter.csv";
    synthetic::write(f, text);
    const PorousSheetFit fit = fitPorousSheet(DriftTable::read(f), air);
    EXPECT_NEAR(fit.constants.a/truth.a, 1.0, 1e-4);
    EXPECT_NEAR(fit.constants.b/truth.b, 1.0, 1e-4);
    EXPECT_NE(fit.constants.provenance.at("curtainDiameter").find("Sauter"), std::string::npos);
    // the same class query sees the curtain, not its own size
    DriftQuery fine = query({3, 10, 4, 1.5, 2650, 1e-4}), coarse = fine;
    coarse.particleDiameter = 2e-3;
    EXPECT_DOUBLE_EQ(model.velocityRatio(fine), model.velocityRatio(coarse));
    EXPECT_GT(model.displacement(fine), model.displacement(coarse));
}


TEST(DriftDictionary, RefusesATableSweptInAnotherGas)
{
    const fs::path dir = tmpDir();
    // the header's fixed line as buildDriftTable writes it, air at 20 degC
    std::string text = synthetic::table(synthetic::defaultGrid(), [](const synthetic::Point&) -> synthetic::Values
        { return {0.5, 0.1, 1.0}; });
    const std::string plain = "# fixed: release_velocity_m_s=0 ";
    ASSERT_NE(text.find(plain), std::string::npos);
    text.replace(text.find(plain), plain.size(),
                 "# fixed: gas=air(rho=1.2086,nu=1.5054e-05) release_velocity_m_s=0 ");
    synthetic::write(dir/"air20.csv", text);
    const auto s = readDriftSettings(YAML::Load("model: {drift: table}\ndrift: {table: air20.csv}\n"), "drumDict", dir);
    EXPECT_NO_THROW(makeDriftModel(s, particleDrag::Gas::air(20)));
    EXPECT_NO_THROW(makeDriftModel(s, particleDrag::Gas::air(25)));    // rho -1.7 %, nu +3 %: within 5 %
    try
    {
        makeDriftModel(s, particleDrag::Gas::air(80));                 // 17 % lighter
        ADD_FAILURE() << "a 20 degC table served an 80 degC case";
    }
    catch (const InputError& e)
    {
        const std::string m = e.what();
        EXPECT_NE(m.find("air20.csv"), std::string::npos) << m;
        EXPECT_NE(m.find("fixed gas"), std::string::npos) << m;
        EXPECT_NE(m.find("within 5 %"), std::string::npos) << m;
    }
    const auto vc = readDriftSettings(YAML::Load("model: {drift: tableVc}\ndrift: {table: air20.csv}\n"), "drumDict", dir);
    EXPECT_THROW(makeDriftModel(vc, particleDrag::Gas::air(80)), InputError);
    // a table without a recorded gas is not checked
    loneParticleTable("noGas.csv", [](const synthetic::Point&) { return 0.7; });
    const auto none = readDriftSettings(YAML::Load("model: {drift: table}\ndrift: {table: noGas.csv}\n"), "drumDict", dir);
    EXPECT_NO_THROW(makeDriftModel(none, particleDrag::Gas::air(80)));
}

TEST(FullDragParticleDrift, TheFallSpeedJoinsTheSlipAndDragSlowsTheFall)
{
    const particleDrag::Gas air = particleDrag::Gas::air(20);
    const auto full = drum::makeDriftModel("isolatedFullDrag", air);
    const auto eq17 = drum::makeDriftModel("isolated", air);
    EXPECT_EQ(full->name(), "isolatedFullDrag");
    drum::DriftQuery q;
    q.gasVelocity = 3;
    q.fallHeight = 10.3;
    q.spillRate = 10;
    q.flightLength = 1;
    // a 1 mm shale grain: drag slows its 10 m fall well below the drag-free speed
    q.particleDiameter = 1e-3;
    q.particleDensity = 1200;
    const double a = full->displacement(q), b = eq17->displacement(q);
    EXPECT_GT(a, 1.5*b) << a << " " << b;
    // a 20 mm steel ball hardly feels the vertical drag, but its fall speed joins the
    // slip: the horizontal drag K |w| w_x exceeds Eq 17's K V_g^2 by up to |w|/V_g,
    // with |w| <= V_g + g t over the drag-free time t of Eq 19
    q.particleDiameter = 20e-3;
    q.particleDensity = 7800;
    const double t = particleDrag::fallTime(q.fallHeight);
    const double r = full->displacement(q)/eq17->displacement(q);
    EXPECT_GT(r, 1.0);
    EXPECT_LT(r, 1 + 9.81*t/q.gasVelocity);
    // still gas on a level floor: no drift
    q.gasVelocity = 0;
    EXPECT_EQ(full->displacement(q), 0.0);
}


TEST(DriftDictionary, ScaleAndRecordedQueries)
{
    const fs::path dir = tmpDir();
    auto read = [&](const std::string& yaml) { return readDriftSettings(YAML::Load(yaml), "drumDict", dir); };
    DriftQuery q;
    q.particleDiameter = 850e-6;
    q.particleDensity = 1590;
    q.gasVelocity = 1.2;
    q.fallHeight = 3;
    q.spillRate = 10;
    q.flightLength = 1.133;
    const auto plain = makeDriftModel(read("model: {drift: sherritt}\n"), air);
    const auto scaled = makeDriftModel(read("model: {drift: sherritt}\ndrift: {scale: 1.4}\n"), air);
    // the factor multiplies the model's own drift, nothing else
    EXPECT_DOUBLE_EQ(scaled->displacement(q), 1.4*plain->displacement(q));
    EXPECT_GT(plain->displacement(q), 0);
    // on an incline the free slide (the displacement in still gas) is kept
    DriftQuery tilted = q, still = q;
    tilted.incline = -0.05;
    still.incline = -0.05;
    still.gasVelocity = 0;
    const double slide = plain->displacement(still);
    EXPECT_LT(slide, 0);
    EXPECT_NEAR(scaled->displacement(tilted), slide + 1.4*(plain->displacement(tilted) - slide), 1e-12);

    const auto rec = makeDriftModel(read("model: {drift: isolated}\ndrift: {recordQueries: true}\n"), air);
    const auto* r = dynamic_cast<const RecordingDrift*>(rec.get());
    ASSERT_NE(r, nullptr);
    EXPECT_EQ(r->name(), "isolated");
    EXPECT_EQ(r->range().count, 0);
    const double d1 = rec->displacement(q);
    DriftQuery q2 = q;
    q2.fallHeight = 0.7;
    q2.spillRate = 31;
    rec->displacement(q2);
    EXPECT_DOUBLE_EQ(d1, makeDriftModel(read("model: {drift: isolated}\n"), air)->displacement(q));
    const DriftQueryRange range = r->range();
    EXPECT_EQ(range.count, 2);
    EXPECT_DOUBLE_EQ(range.lo[fallHeightAxis], 0.7);
    EXPECT_DOUBLE_EQ(range.hi[fallHeightAxis], 3);
    EXPECT_DOUBLE_EQ(range.lo[spillRateAxis], 10);
    EXPECT_DOUBLE_EQ(range.hi[spillRateAxis], 31);
    EXPECT_DOUBLE_EQ(range.lo[diameterAxis], 850e-6);
    EXPECT_NE(r->rangeCsv().find("fall_height_m,0.7,3,2\n"), std::string::npos) << r->rangeCsv();
    // queries without Lee's angles (NaN) leave the angle rows out
    EXPECT_EQ(range.angleCount, 0);
    EXPECT_EQ(r->rangeCsv().find("angle"), std::string::npos) << r->rangeCsv();
    // the flight model's queries carry them: their extent is recorded, the
    // others' still counted on the table's axes
    DriftQuery q3 = q, q4 = q;
    q3.releaseAngleDeg = 95;
    q3.reposeAngleDeg = 58;
    q4.releaseAngleDeg = 180;
    q4.reposeAngleDeg = 37;
    rec->displacement(q3);
    rec->displacement(q4);
    EXPECT_EQ(r->range().count, 4);
    EXPECT_EQ(r->range().angleCount, 2);
    EXPECT_NE(r->rangeCsv().find("release_angle_deg,95,180,2\nrepose_angle_deg,37,58,2\n"), std::string::npos)
        << r->rangeCsv();

    // bad entries name the entry and the range
    for (const std::string bad : {"0", "-1", "11", "big"})
    {
        try
        {
            read("model: {drift: sherritt}\ndrift: {scale: " + bad + "}\n");
            FAIL() << "scale " << bad << " accepted";
        }
        catch (const InputError& e)
        {
            EXPECT_NE(std::string(e.what()).find("drift.scale"), std::string::npos) << e.what();
        }
    }
    EXPECT_THROW(read("model: {drift: sherritt}\ndrift: {recordQueries: maybe}\n"), InputError);
}
