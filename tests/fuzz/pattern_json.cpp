// Fuzz target: a pattern file's text through the JSON reader and the
// pattern parser (no building: the pipeline target does that).
#include "fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace stochtex;
    return fuzz::run([&] {
        const nlohmann::json j = JsonReader::parse(fuzz::text(data, size), "fuzz.json");
        (void)parsePatternSpec(JsonReader(j, "fuzz.json"), fuzz::imagesDir());
    });
}
