// stochtex nodes: the nodes of texture graphs, each with its ports and its
// parameter table (the table that parses graph files), as text or JSON.
#include <cstdio>

#include "common.h"
#include "stochtex/pattern/graph_nodes.h"

namespace stochtex::cli {

void registerNodes(CLI::App& app) {
    auto json = std::make_shared<bool>(false);
    auto* cmd = app.add_subcommand("nodes", "List the nodes of texture graphs with their inputs and parameters");
    cmd->add_flag("--json", *json, "Print the node table as JSON");
    cmd->callback([json] {
        const nlohmann::json table = graphNodesJson();
        if (*json) {
            std::printf("%s\n", table.dump(2).c_str());
            return;
        }
        for (const auto& n : table) {
            std::string inputs;
            for (const auto& p : n["inputs"])
                inputs += (inputs.empty() ? "" : ", ") + p["name"].get<std::string>() + ": " + p["type"].get<std::string>();
            std::printf("%s (%s; %s → %s)\n  %s\n", n["type"].get<std::string>().c_str(),
                        n["category"].get<std::string>().c_str(), inputs.empty() ? "no inputs" : inputs.c_str(),
                        n["output"].get<std::string>().c_str(), n["description"].get<std::string>().c_str());
            for (const auto& p : n["params"]) {
                std::string range;
                if (p.contains("min")) range = "[" + formatValue(p["min"]) + ", " + formatValue(p["max"]) + "]";
                for (const auto& c : p.value("choices", nlohmann::json::array()))
                    range += (range.empty() ? "" : "|") + c.get<std::string>();
                const auto& d = p["default"];
                const std::string fallback = d.is_null()     ? (p["type"] == "seed" ? "(derived)" : "(required)")
                                             : d.is_number() ? formatValue(d.get<double>())
                                                             : d.dump();
                std::printf("  %-12s %-10s %-12s %-16s %s\n", p["name"].get<std::string>().c_str(),
                            p["type"].get<std::string>().c_str(), fallback.c_str(), range.c_str(),
                            p["description"].get<std::string>().c_str());
            }
        }
    });
}

}  // namespace stochtex::cli
