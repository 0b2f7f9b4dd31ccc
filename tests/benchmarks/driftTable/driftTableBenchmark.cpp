// ns per drift query: DriftTable lookup on a 6-axis grid (all axes varied,
// 2^6 = 64 corners per lookup) and on a 4-axis grid, the table and tableVc
// drift models, against the isolated-particle and Sherritt models of the
// shared core. Queries are random inside the grid, precomputed.
#include "drum/drift/porousSheetDrift.hpp"
#include "drum/drift/tableDrift.hpp"
#include "syntheticTable.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <unistd.h>

namespace
{

using namespace drum;

std::array<std::vector<double>, 6> grid(bool sixAxes)
{
    // the shipped table's sweep (etc/defaults/driftTables/driftTableDict)
    std::array<std::vector<double>, 6> g{{{1.4, 4, 8.6}, {0.2, 2, 10, 35}, {0.5, 1, 2, 3.5, 6.6, 10.3},
                                          {1, 2}, {1200, 2650}, {74e-6, 150e-6, 300e-6, 840e-6, 2.4e-3}}};
    if (!sixAxes)
    {
        g[3] = {1};
        g[4] = {2650};
    }
    return g;
}

std::shared_ptr<const DriftTable> makeTable(bool sixAxes)
{
    const auto file = std::filesystem::temp_directory_path()/("driftTableBenchmark_" + std::to_string(::getpid())
                      + (sixAxes ? "_6" : "_4") + ".csv");
    synthetic::write(file, synthetic::table(grid(sixAxes), [](const synthetic::Point& p) -> synthetic::Values
    {
        return {1/(1 + 0.1*p[1]), 0.01*p[0]*p[2]/std::sqrt(p[5]*1e3), 1.0};
    }));
    auto t = std::make_shared<const DriftTable>(DriftTable::read(file));
    std::filesystem::remove(file);
    return t;
}

std::vector<DriftQuery> queries(bool sixAxes)
{
    const auto g = grid(sixAxes);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<DriftQuery> qs(4096);
    for (auto& q : qs)
    {
        auto pick = [&](int a) { return g[a].front() + u(rng)*(g[a].back() - g[a].front()); };
        q.gasVelocity = pick(0);
        q.spillRate = pick(1);
        q.fallHeight = pick(2);
        q.flightLength = pick(3);
        q.particleDensity = pick(4);
        q.particleDiameter = pick(5);
    }
    return qs;
}

const particleDrag::Gas air = particleDrag::Gas::air(20);

void run(benchmark::State& state, const DriftModel& m, const std::vector<DriftQuery>& qs)
{
    std::size_t i = 0;
    for (auto _ : state)
    {
        benchmark::DoNotOptimize(m.displacement(qs[i++ & 4095]));
    }
}

void BM_tableLookup6(benchmark::State& state)
{
    static const auto t = makeTable(true);
    static const auto qs = queries(true);
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(t->lookup(qs[i++ & 4095]));
}
void BM_tableLookup4(benchmark::State& state)
{
    static const auto t = makeTable(false);
    static const auto qs = queries(false);
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(t->lookup(qs[i++ & 4095]));
}
void BM_tableDrift6(benchmark::State& state)
{
    static const TableDrift m(makeTable(true));
    static const auto qs = queries(true);
    run(state, m, qs);
}
void BM_tableVcDrift6(benchmark::State& state)
{
    static const TableVcDrift m(makeTable(true), air);
    static const auto qs = queries(true);
    run(state, m, qs);
}
void BM_isolated(benchmark::State& state)
{
    static const IsolatedParticleDrift m(air);
    static const auto qs = queries(true);
    run(state, m, qs);
}
void BM_sherritt(benchmark::State& state)
{
    static const SherrittSheetDrift m(air);
    static const auto qs = queries(true);
    run(state, m, qs);
}
void BM_porousSheet(benchmark::State& state)
{
    static const PorousSheetDrift m({4.0, 0.47, {}}, air, {}, 5e-4);
    static const auto qs = queries(true);
    run(state, m, qs);
}

} // namespace

BENCHMARK(BM_tableLookup6);
BENCHMARK(BM_tableLookup4);
BENCHMARK(BM_tableDrift6);
BENCHMARK(BM_tableVcDrift6);
BENCHMARK(BM_isolated);
BENCHMARK(BM_sherritt);
BENCHMARK(BM_porousSheet);
BENCHMARK_MAIN();
