// drumSolver -case DIR: solids transport through a flighted rotary drum from
// the case dictionary DIR/drumDict (README.md beside this file documents
// every entry). The model is selected by model.type (src/drum/models):
//   compartment  Lee/Sheehan slice network (Lee 2008 Ch. 3, App. 10.2)
//   twoPhase     Sherritt (1991) airborne/dense model (DRUM3 axial solve)
// The model reads and checks its own sections before anything runs and
// writes its outputs into a fresh folder that replaces DIR/results only
// when complete.
#include "drum/io/inputError.hpp"
#include "drum/io/resultsFolder.hpp"
#include "drum/models/drumModel.hpp"
#include "drum/models/runOutputs.hpp"

#include <cstring>
#include <iostream>

namespace fs = std::filesystem;

namespace
{

const char* const usage = "Usage: drumSolver -case DIR\n  reads DIR/drumDict (YAML), writes DIR/results/\n";

//- The case folder from the arguments; exit code >= 0 when done already
int parseArguments(int argc, char* argv[], fs::path& caseDir)
{
    caseDir = ".";
    bool given = false;
    for (int i = 1; i < argc; ++i)
    {
        if (std::strcmp(argv[i], "-case") == 0)
        {
            if (i + 1 >= argc)
            {
                std::cerr << "drumSolver: -case needs a folder\n" << usage;
                return 2;
            }
            if (given)
            {
                std::cerr << "drumSolver: -case given twice ('" << caseDir.string() << "' and '" << argv[i + 1]
                          << "'): give one case\n" << usage;
                return 2;
            }
            caseDir = argv[++i];
            given = true;
        }
        else if (std::strcmp(argv[i], "-help") == 0 || std::strcmp(argv[i], "--help") == 0)
        {
            std::cout << usage;
            return 0;
        }
        else
        {
            std::cerr << "drumSolver: unknown argument '" << argv[i] << "'\n" << usage;
            return 2;
        }
    }
    return -1;
}

} // namespace


int main(int argc, char* argv[])
{
    fs::path caseDir;
    if (const int done = parseArguments(argc, argv, caseDir); done >= 0)
    {
        return done;
    }
    // errors name the results folder, not the hidden one a run writes into
    std::string partial, target;
    const auto named = [&](std::string msg)
    {
        for (std::size_t at; !partial.empty() && (at = msg.find(partial)) != std::string::npos;)
        {
            msg.replace(at, partial.size(), target);
        }
        return msg;
    };
    try
    {
        drum::say("reading " + (caseDir/"drumDict").string());
        const drum::DrumCase c = drum::readDrumCase(caseDir, drum::drumModelSections());
        for (const std::string& w : c.warnings)
        {
            drum::say("warning: " + w);
        }
        const std::unique_ptr<drum::DrumModel> model = drum::DrumModel::New(c);

        drum::ResultsFolder results(caseDir/"results");
        partial = results.path().string();
        target = results.target().string();
        for (const auto& f : results.cleaned())
        {
            drum::say("removed " + f.string() + ", left by a run that was killed");
        }
        model->run(results.path());
        for (const auto& f : results.commit())
        {
            drum::say("kept your file " + (results.target()/f).string());
        }
        drum::say("results in " + results.target().string());
    }
    catch (const drum::InputError& e)
    {
        // Model-level errors carry no file: this dictionary is where to fix them
        std::cerr << "drumSolver: input error: "
                  << (e.file().empty() ? (caseDir/"drumDict").string() + ": " : std::string())
                  << named(e.what()) << std::endl;
        return 1;
    }
    catch (const std::exception& e)
    {
        std::cerr << "drumSolver: error: " << named(e.what()) << " (results/ left as it was)" << std::endl;
        return 1;
    }
    return 0;
}
