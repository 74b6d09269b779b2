#include "marble_flags.h"

#include "common.h"

namespace stochtex::cli {

void addMarbleFlags(CLI::App& cmd, MarbleParams& p, bool withScalingAndLayer) {
    cmd.add_option("--band-period", p.bandPeriod, "Pixels between two bands, 2π/|a|")->capture_default_str();
    cmd.add_option("--band-angle", p.bandAngle, "Direction of a, degrees from the x axis (0: vertical veins)")
        ->capture_default_str();
    cmd.add_option("--distortion", p.distortion, "b: band phase, radians, per unit of noise")->capture_default_str();
    cmd.add_option("--level", p.level, "m: noise cells of 2^m pixels")->capture_default_str();
    cmd.add_option("--level-amplitude", p.levelAmplitude, "n in l = m + n cos(q x) + r t (stretching)")
        ->capture_default_str();
    cmd.add_option("--level-period", p.levelPeriod, "2π/q, pixels along x of one cycle of l")->capture_default_str();
    cmd.add_option("--level-rate", p.levelRate, "r, change of l per unit of time (sliding)")->capture_default_str();
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
