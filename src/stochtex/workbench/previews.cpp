#include "stochtex/workbench/previews.h"

#include "stochtex/image/colour_space.h"
#include "stochtex/noise/spectrum.h"
#include "stochtex/pattern/colormap.h"
#include "stochtex/pattern/part_cache.h"
#include "stochtex/pattern/pattern_parts.h"

namespace stochtex {

const PatternPreviews& PreviewCache::update(const PatternSpec& spec, PartCache* parts) {
    if (colormapKey_ != spec.colormap) {
        const ColormapTable table = *colormapPart(parts, spec.colormap);
        previews_.colormap = encodeTransfer(table.toImage(), spec.colormap.transfer.value_or(Transfer::Srgb));
        colormapKey_ = spec.colormap;
        ++colormapBuilds_;
    }
    for (int k = 0; k < 2; ++k) {
        // A graph's leaves are its nodes'; a quadrature pair's N_y is N_x's partner.
        const bool shown = !spec.graph && !(k == 1 && spec.quadraturePair);
        if (!shown) {
            previews_.examples[size_t(k)] = {};
            previews_.spectra[size_t(k)] = {};
            noiseKeys_[size_t(k)].reset();
            continue;
        }
        // The example the renderer builds: with the seed the pattern gives it
        // (noiseSeed: the pattern seed's, unless the noise has its own).
        NoiseSpec noise = spec.noise[size_t(k)];
        if (noise.source == NoiseSpec::Source::Spectrum) noise.spectrum.seed = noiseSeed(spec, k);
        if (noiseKeys_[size_t(k)] == noise) continue;
        noiseKeys_[size_t(k)].reset();  // stays unset if the build throws
        Image example = buildExampleImage(noise, k == 0 ? "noise_x" : "noise_y");
        previews_.spectra[size_t(k)] = displaySpectrum(powerSpectrum(example));
        previews_.examples[size_t(k)] = std::move(example);
        noiseKeys_[size_t(k)] = std::move(noise);
        ++exampleBuilds_;
    }
    return previews_;
}

void PreviewCache::clear() {
    colormapKey_.reset();
    for (std::optional<NoiseSpec>& key : noiseKeys_) key.reset();
}

}  // namespace stochtex
