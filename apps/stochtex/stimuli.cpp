// stochtex stimuli: the perception experiment of the thesis (§2.6.2): partly
// correlated tiled white noise stimuli and the page that shows them, or
// (--analyse) the detection rates of the answers that page collected.
#include <cstdio>

#include "common.h"
#include "progress.h"
#include "stochtex/core/parallel.h"
#include "stochtex/studies/stimuli.h"
#include "stochtex/studies/stimuli_analysis.h"

namespace stochtex::cli {

void registerStimuli(CLI::App& app) {
    struct Args {
        StimulusSetOptions set;
        std::string dir, answers;
        int threads = 0;
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("stimuli",
                                   "Perception experiment (thesis §2.6.2): tiled white-noise stimuli with "
                                   "tile-to-tile correlation, the experiment page (experiment.html), or "
                                   "with --analyse the detection rates of its answers");
    addOutputFolderFlag(*cmd, args->dir);
    const auto& members = stimulusSetMembers();
    const auto member = [&](const char* name) { return addMemberOption(*cmd, optionMember(members, name), args->set); };
    std::vector<CLI::Option*> setFlags{
        member("size"),
        cmd->add_option("--tiles", args->set.tiles, "Tile sizes w, pixels, each dividing --size")->delimiter(','),
        cmd->add_option("--correlations", args->set.correlations, "Tile-to-tile correlations in [0, 1] (eq. 2.28)")
            ->delimiter(','),
        member("repeats"),
        addSeedFlag(*cmd, "--seed", args->set.seed, "Seed of the images and of the trial order"),
        member("durationMs"),
        member("resetMs"),
        bindParameter(*cmd,
                      cmd->add_option("--mean", args->set.mean, "Mean display value of stimuli and screen, (0, 1)")
                          ->capture_default_str(),
                      "mean"),
        bindParameter(*cmd,
                      cmd->add_option("--contrast", args->set.contrast,
                                      "Noise amplitude, fraction of the largest that never clips, (0, 1]")
                          ->capture_default_str(),
                      "contrast")};
    cmd->add_option("--analyse,--analyze", args->answers, "Answers CSV of experiment.html: write detection rates");
    addThreadsFlag(*cmd, args->threads);
    cmd->callback([args, setFlags] {
        if (!args->answers.empty()) {
            for (const CLI::Option* f : setFlags) refuseWithoutEffect(f, false, "with --analyse");
            const DetectionRates r = detectionRates(readStimulusAnswers(args->answers));
            const std::vector<std::string> files = writeReport(args->dir, detectionReport(r, args->answers));
            std::printf("%s\nwrote %s to %s\n", r.table.markdown().c_str(), listNames(files).c_str(),
                        args->dir.c_str());
            return;
        }
        validateStimulusSet(args->set);
        ThreadLimit limit(args->threads);
        ensureFolder(args->dir);
        ProgressLine progress("stimuli");
        const StimulusSet set = stimulusSet(args->set, progress.callback());
        progress.finish();
        writeReport(args->dir, stimulusSetReport(set));
        std::printf(
            "wrote %zu stimuli (%d px, %zu tile sizes x %zu correlations x %d), stimuli.csv, "
            "experiment.html and index.html to %s\nopen experiment.html in a browser; analyse its answers with "
            "stochtex stimuli --analyse answers.csv -o FOLDER\n",
            set.images.size(), args->set.size, args->set.tiles.size(), args->set.correlations.size(), args->set.repeats,
            args->dir.c_str());
    });
}

}  // namespace stochtex::cli
