// stochtex: command-line entry point. Each command lives in its own file and
// registers itself here; exit code 0 = success, 2 = bad input or a machine
// that cannot run the command (no display, no OpenGL 4.3), 1 = bug.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "common.h"
#include "progress.h"
#include "stochtex/core/atomic_file.h"
#include "stochtex/core/budget.h"
#include "stochtex/core/error.h"
#include "stochtex/core/watchdog.h"
#include "stochtex/gpu/gl_context.h"
#include "stochtex/gpu/shader.h"

int main(int argc, char** argv) {
    // An interrupted command removes its temporary files and dies of the signal.
    stochtex::installTempFileCleanup();
    CLI::App app{"stochtex: colour-mapped noise vector fields and procedural texture analysis"};
    // Usage lines read "stochtex render ...", whatever path the binary was started by.
    app.name("stochtex");
    app.require_subcommand(1);
    // --quiet (and --help, --version) may follow the command's name.
    app.fallthrough(true);
    app.set_version_flag("--version", "stochtex " STOCHTEX_VERSION);
    app.add_flag_callback(
        "--quiet,-q", [] { stochtex::cli::setProgressQuiet(true); },
        "No progress line (it is drawn only when stderr is a terminal)");
    stochtex::cli::bindParameter(
        app,
        app.add_option_function<double>(
            "--budget", [](double factor) { stochtex::setBudgetFactor(factor); },
            "Multiply every work, memory and time budget by this factor, in [1/64, 64] (README, \"Bad input\")"),
        "budget");
    // Past a budget that only a watchdog can enforce (a shader compile, a GPU
    // frame) the process ends there (core/watchdog.h), with the same advice.
    stochtex::setOverrunAdvice(stochtex::cli::budgetAdvice);
    // Every option's help shows its default (inherited by the commands).
    app.option_defaults()->always_capture_default();
    stochtex::cli::registerRender(app);
    stochtex::cli::registerGallery(app);
    stochtex::cli::registerNoise(app);
    stochtex::cli::registerColormap(app);
    stochtex::cli::registerPresets(app);
    stochtex::cli::registerNodes(app);
    stochtex::cli::registerStability(app);
    stochtex::cli::registerZoom(app);
    stochtex::cli::registerCorrelation(app);
    stochtex::cli::registerContrast(app);
    stochtex::cli::registerAnalyze(app);
    stochtex::cli::registerSpectrum(app);
    stochtex::cli::registerFlow(app);
    stochtex::cli::registerCoherence(app);
    stochtex::cli::registerFractalize(app);
    stochtex::cli::registerStimuli(app);
    stochtex::cli::registerMarble(app);
    stochtex::cli::registerReproduce(app);
    stochtex::cli::registerScene(app);
    stochtex::cli::registerView(app);
    stochtex::cli::registerBake(app);
    stochtex::cli::registerBakeImage(app);
    stochtex::cli::registerWeb(app);
    stochtex::cli::registerShadertoy(app);
    stochtex::cli::tidyDefaults(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        const std::string explained =
            stochtex::cli::explainParseError(app, std::vector<std::string>(argv + 1, argv + argc));
        std::fprintf(stderr, "stochtex: error: %s\nRun with --help for usage.\n",
                     explained.empty() ? e.what() : explained.c_str());
        return 2;
    } catch (const stochtex::InputError& e) {
        std::fprintf(stderr, "stochtex: error: %s%s\n",
                     stochtex::cli::describeInputError(e, stochtex::cli::commandThatRan(app)).c_str(),
                     e.isOverBudget() ? stochtex::cli::budgetAdvice().c_str() : "");
        return 2;
    } catch (const stochtex::GpuUnavailable& e) {
        // Not a bug: what the user asked for needs a display or GPU this machine lacks.
        std::fprintf(stderr, "stochtex: error: %s\n", e.what());
        return 2;
    } catch (const stochtex::ShaderError& e) {
        std::fprintf(stderr, "stochtex: error: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "stochtex: internal error: %s\n", e.what());
        return 1;
    }
    return 0;
}
