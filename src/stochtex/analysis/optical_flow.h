#pragma once
// Optical flow of frame sequences (thesis §2.8, Figures 2.24–2.25) through
// OpenCV's video module: dense Farnebäck and DIS (dense inverse search), and
// sparse pyramidal Lucas–Kanade on a grid of points; colour images of a
// dense field (direction → hue, magnitude → value), arrows on a grid, and
// summary numbers that turn "the sliding texture moves outward, the fixed one
// does not" into a measurement.
//
// Conventions: a flow vector (u, v) at pixel (x, y) of `prev` says that the
// content there is found at (x + u, y + v) in `next`, in pixels, x to the
// right and y down (image rows). Frames are 1-channel (colour frames go
// through toGray) with values in [0, 1]; they are quantised to 8 bits, the
// input the three OpenCV methods take.
#include <vector>

#include "stochtex/core/enum_names.h"
#include "stochtex/image/image.h"

namespace stochtex {

enum class FlowMethod { Farneback, Dis, LucasKanade };
inline const EnumNames<FlowMethod> kFlowMethodNames{
    {"farneback", FlowMethod::Farneback}, {"dis", FlowMethod::Dis}, {"lucas-kanade", FlowMethod::LucasKanade}};

// One motion vector: at (x, y) of the first frame, moving by (u, v).
struct FlowVector {
    float x = 0, y = 0, u = 0, v = 0;
};

// A dense 2-channel (u, v) field the size of the frames, by Farnebäck or DIS.
// InputError if the frames differ in size or are smaller than 16×16;
// std::invalid_argument for LucasKanade (sparse: use flowVectors).
Image denseFlow(const Image& prev, const Image& next, FlowMethod method);

// Vectors on a grid of `step` pixels (points at step/2 + k·step), at least
// `margin` pixels from the border: sampled from the dense field for Farnebäck
// and DIS; tracked by pyramidal Lucas–Kanade (21×21 windows, 3 levels) for
// LucasKanade, whose points that cannot be tracked are left out.
std::vector<FlowVector> flowVectors(const Image& prev, const Image& next, FlowMethod method, int step, int margin);
// The dense field's vectors on the same grid.
std::vector<FlowVector> sampleFlow(const Image& flow, int step, int margin);

// Numbers of a set of vectors about a centre (cx, cy) (the zoom centre):
// the mean vector; the mean magnitude; the mean radial (outward) component
// (u, v)·(p − c)/|p − c|; the fraction of moving vectors (|(u, v)| ≥ 0.05 px)
// that point outward; and the least-squares expansion rate k of
// radial ≈ k·|p − c| (a zoom by s about c has k = s − 1).
struct FlowSummary {
    int vectors = 0;
    double meanU = 0, meanV = 0;
    double meanMagnitude = 0;
    double meanRadial = 0;
    double outwardFraction = 0;
    double expansionRate = 0;
};
FlowSummary summariseFlow(const std::vector<FlowVector>& vectors, double cx, double cy);

// The dense field as colour (RGB display codes, the HSV colours as they are;
// written with kNoTransfer like every figure):
// hue = direction (0° = right, counter-clockwise on screen), saturation 1,
// value = min(1, magnitude / maxMagnitude); maxMagnitude ≤ 0 uses the field's
// largest magnitude.
Image flowColourImage(const Image& flow, double maxMagnitude = 0);

// The frame (gray, its values shown as display codes) with each vector drawn
// as an arrow, lengthened by `scale` so that sub-pixel motion is visible (RGB).
Image flowArrowsImage(const Image& frame, const std::vector<FlowVector>& vectors, double scale);

}  // namespace stochtex
