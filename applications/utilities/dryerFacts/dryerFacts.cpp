// dryerFacts: the facts the C++ side owns, for the Python tools to ask instead of
// repeating them: the drag laws (particleDrag::dragLawNames), Eq 142's constants
// (particleDrag::SheetVelocityConstants, Sherritt 1991 Eq 142), the drift table's
// columns (drum::driftTableColumns, its file format), the spill-rate bound and the
// slot's solids fraction (particleDrag/releaseLayer.hpp).
//
//   dryerFacts                  the facts as one JSON object on stdout
//   dryerFacts -slotSolidsFraction S RHO B V
//                               S/(RHO B V), 17 significant digits (a test ties the
//                               Python side's copy of it to this)
// Exit 2 on bad options.
#include "drum/drift/driftTableFile.hpp"
#include "particleDrag/dragLaw.hpp"
#include "particleDrag/gasProperties.hpp"
#include "particleDrag/releaseLayer.hpp"
#include "particleDrag/sheetVelocity.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace
{

std::string quoted(const std::string& s)
{
    return "\"" + s + "\"";
}

std::string list(const std::vector<std::string>& words)
{
    std::string out = "[";
    for (std::size_t i = 0; i < words.size(); ++i)
    {
        out += (i ? ", " : "") + quoted(words[i]);
    }
    return out + "]";
}

bool number(const char* text, double& v)
{
    char* end = nullptr;
    v = std::strtod(text, &end);
    return end != text && *end == '\0';
}

} // namespace

int main(int argc, char* argv[])
{
    const char* usage = "Usage: dryerFacts                       (the facts as JSON)\n"
                        "       dryerFacts -slotSolidsFraction S RHO B V\n";
    if (argc == 2 && (!std::strcmp(argv[1], "-help") || !std::strcmp(argv[1], "-h")))
    {
        std::fputs(usage, stdout);
        return 0;
    }
    if (argc == 6 && !std::strcmp(argv[1], "-slotSolidsFraction"))
    {
        double v[4];
        for (int i = 0; i < 4; ++i)
        {
            if (!number(argv[2 + i], v[i]))
            {
                std::fprintf(stderr, "dryerFacts: '%s' is not a number\n%s", argv[2 + i], usage);
                return 2;
            }
        }
        std::printf("%.17g\n", particleDrag::slotSolidsFraction(v[0], v[1], v[2], v[3]));
        return 0;
    }
    if (argc != 1)
    {
        std::fprintf(stderr, "dryerFacts: unknown options\n%s", usage);
        return 2;
    }
    const particleDrag::SheetVelocityConstants eq142;
    std::printf("{\n");
    std::printf("  \"dragLaws\": %s,\n", list(particleDrag::dragLawNames()).c_str());
    std::printf("  \"eq142\": {\"k\": %.17g, \"a\": %.17g, \"b\": %.17g, \"c\": %.17g},\n",
                eq142.k, eq142.a, eq142.b, eq142.c);
    std::printf("  \"driftTableColumns\": %s,\n", list(drum::driftTableColumns()).c_str());
    std::printf("  \"tunnelDriftColumn\": %s,\n", quoted(drum::tunnelDriftColumn()).c_str());
    std::printf("  \"maxSpillRate\": %.17g,\n", particleDrag::maxSpillRate);
    std::printf("  \"curtainEdgeSolidsFraction\": %.17g,\n", particleDrag::curtainEdgeSolidsFraction);
    std::printf("  \"gasTemperatureRangeC\": [%.17g, %.17g],\n", particleDrag::minTemperatureC,
                particleDrag::maxTemperatureC);
    std::printf("  \"gasPressureRangeKPa\": [%.17g, %.17g]\n", particleDrag::minPressureKPa,
                particleDrag::maxPressureKPa);
    std::printf("}\n");
    return 0;
}
