// Fuzz target: a ShaderToy program's description (docs/SHADERTOY.md) — our
// manifest (shadertoy.json) or ShaderToy's own export — through the JSON
// reader and its parser, paths resolved in tests/fuzz/images/ (which holds a
// pass file or two, so that mutations get past the code files), then back to
// a manifest (shadertoyManifest). No program runs: that needs a GL context.
#include "fuzz_target.h"
#include "stochtex/gpu/shadertoy_spec.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace stochtex;
    return fuzz::run([&] {
        const nlohmann::json j = JsonReader::parse(fuzz::text(data, size), "fuzz.json");
        const std::filesystem::path json = fuzz::imagesDir() / "fuzz.json";
        const ShadertoySpec spec = isShadertoyExport(j)
                                       ? parseShadertoyExport(JsonReader(j, json.string()), json, fuzz::imagesDir())
                                       : parseShadertoyManifest(JsonReader(j, json.string()), fuzz::imagesDir());
        for (const ShadertoyPass& pass : spec.passes)
            for (const ShadertoyChannel& ch : pass.channels)
                if (!ch.image.empty() && !fuzz::insideImagesDir(ch.image)) return;  // never reads outside
        (void)shadertoyManifest(spec, fuzz::imagesDir());
    });
}
