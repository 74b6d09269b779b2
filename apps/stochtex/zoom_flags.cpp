#include "zoom_flags.h"

#include "stochtex/image/image_io.h"

namespace stochtex::cli {

void addZoomFlags(CLI::App& cmd, ZoomFlags& f, bool withLayers) {
    ZoomParams& p = f.params;
    for (const OptionMember<ZoomParams>& m : zoomParamsMembers())
        if (withLayers || m.info.name != "layers") addMemberOption(cmd, m, p);
    addEnumFlag(cmd, "--scaling", p.scaling, kZoomScalingNames, "scaling",
                "sliding (eq. 2.2) or exponential (eq. 2.5, no sliding)");
    addEnumFlag(cmd, "--offsets", p.offsets, kZoomOffsetsNames, "offsets",
                "Layer offsets: none, simple, hashed (pcg3d) or sin-hash (eq. 2.23)");
    addEnumFlag(cmd, "--interpolation", p.interpolation, kLatticeInterpolationNames, "interpolation",
                "Base lattice reconstruction: nearest or linear");
    cmd.add_option("--base", f.base,
                   "Base texture: 'white' (white noise) or an image file (colour: gray by 0.21r + 0.72g + 0.07b)")
        ->capture_default_str();
    addParameterOptions(cmd, zoomBaseMembers(), f.lattice);
    cmd.add_option("--seed", f.seed, "Seed of the white noise (instance k uses a seed derived from it)")
        ->capture_default_str();
}

ZoomParams makeZoomParams(const ZoomFlags& f) {
    ZoomParams p = f.params;
    p.offsetSeed = f.seed;
    validateZoomParams(p);
    return p;
}

ZoomBase makeZoomBase(const ZoomFlags& f) {
    ZoomBase b = f.lattice;
    b.seed = f.seed;
    if (f.base == "white") {
        validateZoomBase(b);
        return b;
    }
    b.image = toGray(readImage(f.base));
    try {
        LatticeTexture::checkImage(b.image);
    } catch (const InputError& e) {
        throw InputError(f.base + ": " + e.what());
    }
    return b;
}

void addCorrelationStudyFlags(CLI::App& cmd, CorrelationStudyOptions& study, const std::string& sizeFlag,
                              bool withVariants) {
    if (withVariants)
        cmd.add_option("--variant", study.variants, "Variants: sliding, fixed, simple, random (repeatable)")
            ->delimiter(',')
            ->transform(enumTransformer(kZoomVariantNames, "variant"))
            ->default_str("sliding,fixed,simple,random");
    cmd.add_option("--layers-list", study.layers, "Layer counts n of the correlation grid, e.g. 16,8,4,2")
        ->delimiter(',')
        ->default_str("16,8,4,2");
    const auto& members = correlationStudyMembers();
    addMemberOption(cmd, optionMember(members, "instances"), study);
    // The plots' extent: --size in `correlation`, --plot-size in `analyze`.
    ParamInfo plotSize = optionMember(members, "plotSize").info;
    plotSize.flag = sizeFlag.substr(2);
    addParameterOption(cmd, plotSize, study.size);
}

}  // namespace stochtex::cli
