#include "marble_flags.h"

#include "common.h"

namespace stochtex::cli {

void addMarbleFlags(CLI::App& cmd, MarbleParams& p, bool withScalingAndLayer) {
    addParameterOptions(cmd, marbleParamsMembers(), p);
    if (withScalingAndLayer) {
        addEnumFlag(cmd, "--scaling", p.scaling, kMarbleScalingNames, "scaling",
                    "continuous (noise(x / 2^l): stretches, slides), blended (the two integer scales mixed) or "
                    "blended-corrected (their contrast restored)");
        addEnumFlag(cmd, "--layer", p.layer, kMarbleLayerNames, "layer",
                    "marble, scaled-noise, scaling-only (white cell noise through the scaling) or base-noise");
    }
    addSeedFlag(cmd, "--seed", p.seed, "Seed of the noises (instance k uses a seed derived from it)");
}

}  // namespace stochtex::cli
