#pragma once
// The flags describing the marble texture (thesis eq. 2.29), shared by the
// `marble` study and the `marble` texture source of `spectrum`, `flow` and
// `coherence`.
#include <CLI/CLI.hpp>

#include "stochtex/textures/marble_texture.h"

namespace stochtex::cli {

// withScalingAndLayer: --scaling and --layer too (the study sets them per panel).
void addMarbleFlags(CLI::App& cmd, MarbleParams& p, bool withScalingAndLayer);

}  // namespace stochtex::cli
