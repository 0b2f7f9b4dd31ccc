// model.drift auto (issue 7, "model no more than a scene needs"): lone
// particles for dilute curtains, the CFD table inside its range, the reduced
// model outside it - each answer equal to the chosen model's, the choice
// counted and explained; the dictionary entries and their errors.
#include "drum/drift/autoDrift.hpp"
#include "drum/drift/driftDictionary.hpp"
#include "drum/drift/porousSheetDrift.hpp"
#include "drum/drift/tableDrift.hpp"
#include "drum/io/inputError.hpp"
#include "particleDrag/loneParticleFall.hpp"
#include "syntheticTable.hpp"
#include "testTempDir.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <unistd.h>

using namespace drum;
namespace fs = std::filesystem;

namespace
{

const particleDrag::Gas air = particleDrag::Gas::air(20);

fs::path tmpDir()
{
    return testTempDir("autoDriftTest");
}

// Table: V_c/V_g = 0.6 everywhere, drift = lone particle at that V_c; the
// flight length held fixed at 1 m
fs::path fixedLengthTable()
{
    auto grid = synthetic::defaultGrid();
    grid[3] = {1.0};
    const fs::path f = tmpDir()/"auto.csv";
    synthetic::write(f, synthetic::table(grid, [](const synthetic::Point& p) -> synthetic::Values
    {
        return {0.6, particleDrag::loneParticleAdvance({}, {p[5], p[4]}, air, 0.6*p[0], p[2]), 1.0};
    }));
    return f;
}

struct Models
{
    std::shared_ptr<const DriftTable> table;
    std::shared_ptr<const DriftModel> inside;
    std::shared_ptr<const PorousSheetDrift> reduced;
    std::shared_ptr<const DriftModel> isolated;
};

Models models()
{
    DriftTableOptions o;
    o.outside = OutOfRangePolicy::clamp;
    o.warn = [](const std::string&) {};
    Models m;
    m.table = std::make_shared<const DriftTable>(DriftTable::read(fixedLengthTable(), o));
    m.inside = std::make_shared<TableVcDrift>(m.table, air);
    PorousSheetConstants c;
    c.a = 20;
    c.b = 0.5;
    m.reduced = std::make_shared<const PorousSheetDrift>(c, air);
    m.isolated = std::make_shared<const IsolatedParticleDrift>(air);
    return m;
}

DriftQuery query(double Vg, double S, double y, double L, double rho, double d)
{
    DriftQuery q;
    q.gasVelocity = Vg;
    q.spillRate = S;
    q.fallHeight = y;
    q.flightLength = L;
    q.particleDensity = rho;
    q.particleDiameter = d;
    return q;
}

} // namespace


TEST(AutoDrift, ChoosesTheCheapestAdequateModelAndSaysWhy)
{
    const Models m = models();
    const AutoDrift a(m.table, m.inside, m.reduced, m.isolated);

    // Dilute: the reduced model sees almost no shielding -> lone particles
    const DriftQuery dilute = query(3, 1e-5, 4, 1, 2650, 5e-4);
    ASSERT_GE(m.reduced->velocityRatio(dilute), 0.95);
    std::string why;
    EXPECT_EQ(a.choose(dilute, &why), AutoDrift::dilute);
    EXPECT_NE(why.find("dilute"), std::string::npos) << why;
    EXPECT_DOUBLE_EQ(a.displacement(dilute), m.isolated->displacement(dilute));

    // Inside the table (flight length 1.1 within the fixed axis' 20 %)
    const DriftQuery in = query(3, 8, 4, 1.1, 2650, 5e-4);
    ASSERT_LT(m.reduced->velocityRatio(in), 0.95);
    EXPECT_EQ(a.choose(in, &why), AutoDrift::inside) << why;
    EXPECT_DOUBLE_EQ(a.displacement(in), m.inside->displacement(in));
    // below the smallest fall height the table's anchor applies: inside
    EXPECT_EQ(a.choose(query(3, 8, 0.3, 1, 2650, 5e-4)), AutoDrift::inside);
    // the end nodes as other units round them (2000 um as 2000*1e-6 m) are on the
    // table, as the table itself reads them; a real step past them is not
    EXPECT_EQ(a.choose(query(3, 8, 4, 1, 2650, 2e-3*(1 + 1e-13)), &why), AutoDrift::inside) << why;
    EXPECT_EQ(a.choose(query(3, 8, 10*(1 + 1e-13), 1, 2650, 5e-4), &why), AutoDrift::inside) << why;
    EXPECT_EQ(a.choose(query(3, 8, 4, 1, 2650, 2e-3*(1 + 1e-6))), AutoDrift::outside);

    // Outside: spill rate beyond the sweep, or the fixed axis beyond its reach
    const DriftQuery beyond = query(3, 60, 4, 1, 2650, 5e-4);
    EXPECT_EQ(a.choose(beyond, &why), AutoDrift::outside);
    EXPECT_NE(why.find("spill_rate_kg_m_s = 60"), std::string::npos) << why;
    EXPECT_DOUBLE_EQ(a.displacement(beyond), m.reduced->displacement(beyond));
    const DriftQuery longFlight = query(3, 8, 4, 1.5, 2650, 5e-4);
    EXPECT_EQ(a.choose(longFlight, &why), AutoDrift::outside);
    EXPECT_NE(why.find("flight_length_m"), std::string::npos) << why;
    a.displacement(longFlight);

    EXPECT_EQ(a.count(AutoDrift::dilute), 1);
    EXPECT_EQ(a.count(AutoDrift::inside), 1);
    EXPECT_EQ(a.count(AutoDrift::outside), 2);
    const std::string s = a.summary();
    EXPECT_NE(s.find("4 queries"), std::string::npos) << s;
    EXPECT_NE(s.find("spill_rate_kg_m_s 1"), std::string::npos) << s;
    EXPECT_NE(s.find("flight_length_m 1"), std::string::npos) << s;
    EXPECT_NE(s.find("curtainCase"), std::string::npos) << s;

    // Without a table, everything shielded goes to the reduced model
    const AutoDrift noTable(nullptr, nullptr, m.reduced, m.isolated);
    EXPECT_EQ(noTable.choose(in, &why), AutoDrift::outside);
    EXPECT_NE(why.find("no drift table"), std::string::npos);

    // An outside model of its own (the dictionary's default: Eq 142) answers
    // outside the table; dilution is still judged by the reduced model
    const auto eq142 = std::make_shared<const SherrittSheetDrift>(air);
    const AutoDrift withEq142(m.table, m.inside, m.reduced, m.isolated, {}, eq142);
    EXPECT_EQ(withEq142.modelName(AutoDrift::outside), "sherritt");
    EXPECT_DOUBLE_EQ(withEq142.displacement(beyond), eq142->displacement(beyond));
    EXPECT_NE(eq142->displacement(beyond), m.reduced->displacement(beyond));
    EXPECT_DOUBLE_EQ(withEq142.displacement(dilute), m.isolated->displacement(dilute));
}


TEST(AutoDrift, DictionaryEntriesAndErrors)
{
    const fs::path dir = tmpDir();
    const fs::path t = fixedLengthTable();
    fs::copy_file(t, dir/"t.csv", fs::copy_options::overwrite_existing);
    const fs::path constants = dir/"ps.yaml";
    PorousSheetConstants c;
    c.a = 20;
    c.b = 0.5;
    writePorousSheetConstants(constants, c);
    auto read = [&](const std::string& yaml) { return readDriftSettings(YAML::Load(yaml), "drumDict", dir); };

    const auto s = read("model: {drift: auto}\ndrift: {table: t.csv, constants: ps.yaml, "
                        "auto: {inside: table, diluteRatio: 0.9, fixedAxisTolerance: 0.1}}\n");
    EXPECT_EQ(s.model, "auto");
    EXPECT_EQ(s.autoInside, "table");
    EXPECT_DOUBLE_EQ(s.autoOptions.diluteRatio, 0.9);
    EXPECT_DOUBLE_EQ(s.autoOptions.fixedAxisTolerance, 0.1);
    const auto m = makeDriftModel(s, air);
    ASSERT_EQ(m->name(), "auto");
    const auto& a = dynamic_cast<const AutoDrift&>(*m);
    EXPECT_EQ(a.modelName(AutoDrift::inside), "table");
    EXPECT_EQ(a.modelName(AutoDrift::outside), "sherritt");   // the default outside the table
    EXPECT_EQ(a.choose(query(3, 8, 4, 1.15, 2650, 5e-4)), AutoDrift::outside);  // 15 % > 10 %
    const auto r = makeDriftModel(read("model: {drift: auto}\ndrift: {table: t.csv, constants: ps.yaml, "
                                       "auto: {outside: porousSheet}}\n"), air);
    EXPECT_EQ(dynamic_cast<const AutoDrift&>(*r).modelName(AutoDrift::outside), "porousSheet");

    auto expectError = [&](const std::string& yaml, const std::string& entry)
    {
        try
        {
            read(yaml);
            ADD_FAILURE() << "no error for " << yaml;
        }
        catch (const InputError& e)
        {
            EXPECT_NE(std::string(e.what()).find(entry), std::string::npos) << e.what();
        }
    };
    expectError("model: {drift: auto}\ndrift: {auto: {inside: cfd}}\n", "drift.auto.inside");
    expectError("model: {drift: auto}\ndrift: {auto: {diluteRatio: 1.5}}\n", "drift.auto.diluteRatio");
    expectError("model: {drift: auto}\ndrift: {auto: {fixedAxisTolerance: x}}\n", "drift.auto.fixedAxisTolerance");
    expectError("model: {drift: auto}\ndrift: {auto: {dilute: 0.9}}\n", "drift.auto.dilute");
    expectError("model: {drift: auto}\ndrift: {auto: {outside: isolated}}\n", "drift.auto.outside");
}
