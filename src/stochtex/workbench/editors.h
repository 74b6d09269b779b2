#pragma once
// The workbench's editing panels (Dear ImGui) over a pattern's JSON: the
// noises' spectra, the colormap (a painted layout's shapes and colours, and
// painting shapes on the colormap's canvas), a texture graph's nodes with
// one widget per parameter of the node table (pattern/graph_nodes.h), and
// the header (seed, scale). The panels never change the document: they
// return the edits made this frame, which the workbench applies (and
// refuses, with the parser's message, when the pattern would not parse).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "stochtex/pattern/colormap.h"
#include "stochtex/pattern/graph_nodes.h"

namespace stochtex {

struct JsonEdit {
    std::string pointer;  // where, as a JSON pointer
    nlohmann::json value;  // the new value (ignored by a removal)
    bool remove = false;   // remove the element or member
};

// The brush of the colormap canvas: a click adds a shape of this kind and
// colour at the point clicked; the move tool drags the shape under the
// cursor (the last one containing it, the one that gives its colour).
struct PaintBrush {
    int shape = 0;  // 0 disc, 1 ring, 2 square, 3 move
    int moving = -1;  // the shape being dragged by the move tool
    float radius = 0.08f;
    float colour[3] = {0.85f, 0.35f, 0.2f};  // sRGB codes, as a colour picker gives them
};

// The graph panel's "add node" row: the type chosen and the image a node
// with a path parameter (an exemplar) reads.
struct NodeAddition {
    int type = 0;  // index into graphNodes()
    char image[512] = "";
};

// What the panels keep between frames.
struct EditorState {
    PaintBrush brush;
    NodeAddition addition;
};

// What the panels show beside the numbers, as ImGui texture ids of images
// in display codes (null: none): the colormap's table as a canvas (x to the
// right, y up, as the table's domain; clicks on a painted one add the
// brush's shape), and each noise's example and power spectrum.
struct EditorPreviews {
    void* colormap = nullptr;
    std::string colormapPointer = "/colormap";  // the colormap the canvas shows (a graph's output node's)
    float canvasSize = 200;
    const PaintedColormap* painted = nullptr;  // the output colormap's layout as parsed (for the move tool)
    bool expandAll = false;  // every header and node open
    void* example[2] = {nullptr, nullptr};
    void* spectrum[2] = {nullptr, nullptr};
};

// Every panel of the pattern.
std::vector<JsonEdit> patternEditor(const nlohmann::json& pattern, const EditorPreviews& previews, EditorState& state);

// A graph's structure as edits (the parser then refuses a cycle, a missing
// node, a colour into a field, with its message):
// the ids of the nodes whose output fits an input of this type, but `except`;
std::vector<std::string> nodesFitting(const nlohmann::json& graph, PortType type, const std::string& except = "");
// a new node of type `node` under a fresh id ("TYPE_N"), its required
// parameters at their samples, each input fed by the first node that fits
// (a spectral noise first: a Gaussian source suits every field input).
JsonEdit addGraphNode(const nlohmann::json& graph, const NodeInfo& node, const std::string& imagePath);

// A colour member ("#rrggbb", [r, g, b] codes in [0, 1]) as sRGB codes;
// false if it is neither.
bool colourCodes(const nlohmann::json& value, float rgb[3]);
// sRGB codes as "#rrggbb".
std::string colourHex(const float rgb[3]);

}  // namespace stochtex
