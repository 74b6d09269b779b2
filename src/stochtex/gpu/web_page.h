#pragma once
// The WebGL2 page (`stochtex web`): a self-contained folder — index.html,
// page.js and data.js — that renders a file's program in a browser in real
// time, with the program render --gpu runs (recipe "graph-web": the same
// generated chunk, the same camera and estimator files, as GLSL ES 3.00)
// and the export's 8-bit data (the paper's layout, gpu/packed_stats.h).
// Nothing is fetched: data.js holds the data as base64 (PNG for the 8-bit
// textures, decoded by page.js itself; raw little-endian floats for the
// point path's examples and tables), so the page works opened from disk
// (file://, where browsers refuse fetches and cross-origin images) and
// from any static server.
//
// The page offers the zoom and plane views with mouse (wheel zooms about
// the cursor, drag pans) and touch (one finger pans, two pinch), the filter
// (none, paper, smooth), the most probes per footprint (aniso), the plane's
// tilt, and shows the pattern's file and program. Its state lives in the
// URL's fragment (#view=plane&scale=2&x=…&y=…&filter=smooth&aniso=4&tilt=60
// &size=W,H), so a link reproduces a view and a test can set one.
#include <string>

#include "stochtex/pattern/camera.h"
#include "stochtex/pattern/filter_options.h"
#include "stochtex/pattern/pattern_file.h"

namespace stochtex {

struct WebPageOptions {
    // The response (colormap or lean), the estimator and the starting filter
    // (none, paper or smooth: both tables are embedded) and aniso.
    FilterOptions options;
    Camera camera;           // the starting view (its size: the canvas's)
    std::string sourceText;  // the pattern file as written, shown on the page
};

// Writes index.html, page.js and data.js into `dir` (created; InputError
// naming it if it cannot be). InputError when the program needs more
// textures than WebGL 2 guarantees a fragment shader (16), both paths
// counted, or options the page cannot show (a statistics source other
// than point or estimators).
void writeWebPage(const PatternSpec& spec, const WebPageOptions& options, const std::string& dir);

}  // namespace stochtex
