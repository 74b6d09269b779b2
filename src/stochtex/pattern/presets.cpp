#include "stochtex/pattern/presets.h"

#include <algorithm>

#include "stochtex/core/embedded_file.h"
#include "stochtex/core/error.h"
#include "stochtex/core/names.h"

namespace stochtex {

extern const EmbeddedFile kEmbeddedPresets[];
extern const std::size_t kEmbeddedPresetsCount;

std::vector<std::string> presetNames() {
    std::vector<std::string> names;
    for (size_t i = 0; i < kEmbeddedPresetsCount; ++i) names.emplace_back(kEmbeddedPresets[i].name);
    std::sort(names.begin(), names.end());
    return names;
}

const char* presetText(const std::string& name) {
    for (size_t i = 0; i < kEmbeddedPresetsCount; ++i)
        if (name == kEmbeddedPresets[i].name) return kEmbeddedPresets[i].contents;
    std::string list;
    for (const auto& n : presetNames()) list += (list.empty() ? "" : ", ") + n;
    throw InputError("unknown preset \"" + name + "\"" + didYouMean(name, presetNames()) + " (known presets: " + list + ")");
}

PatternSpec loadPreset(const std::string& name) {
    const std::string source = "preset " + name;
    const nlohmann::json j = JsonReader::parse(presetText(name), source);
    return parsePatternSpec(JsonReader(j, source), ".");
}

}  // namespace stochtex
