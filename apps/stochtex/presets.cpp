// stochtex presets: lists the embedded presets or prints one as JSON.
#include <cstdio>

#include "common.h"
#include "stochtex/pattern/presets.h"

namespace stochtex::cli {

void registerPresets(CLI::App& app) {
    auto dump = std::make_shared<std::string>();
    auto* cmd = app.add_subcommand("presets", "List the embedded pattern presets");
    cmd->add_option("--dump", *dump, "Print this preset's JSON (a starting point for your own patterns)");
    cmd->callback([dump] {
        if (!dump->empty()) {
            std::fputs(presetText(*dump), stdout);
            return;
        }
        for (const auto& name : presetNames()) {
            const auto j = nlohmann::json::parse(presetText(name));
            std::printf("%-16s %s\n", name.c_str(), j.value("description", std::string()).c_str());
        }
    });
}

}  // namespace stochtex::cli
