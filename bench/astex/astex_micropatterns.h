// ASTex MicroPatterns (github.com/ASTex-ICube/ASTex, Algo/MicroPatterns: the
// CPU code published with the paper) behind a plain interface, so that its
// headers (ITK images, Eigen, C++17) stay in one translation unit of the
// comparison benchmark (bench_vs_astex.cpp).
#pragma once

#include <memory>
#include <vector>

namespace stochtex::bench {

class AstexMicroPatterns {
public:
    // Its precomputation, as its test program runs it: the two noises'
    // packed mean/variance MIP pyramid (PackedInputNoises) and the 8 × 8
    // blurred colormaps (BlurredColorMaps). noiseA, noiseB: size² values in
    // [0, 1], row-major; colormap: side² linear RGB triples, row j at y = j.
    AstexMicroPatterns(const std::vector<float>& noiseA, const std::vector<float>& noiseB, int size,
                       const std::vector<float>& colormap, int side);
    ~AstexMicroPatterns();
    AstexMicroPatterns(const AstexMicroPatterns&) = delete;
    AstexMicroPatterns& operator=(const AstexMicroPatterns&) = delete;

    // Its render, `patterns(img, pixels, noises, colormaps, scale,
    // Tiling_n_Blendinng)`: pixels² at `scale` example texels per pixel,
    // on its own thread pool (one thread per core the machine reports).
    void render(int pixels, double scale);
    // The last render as pixels² linear RGB triples, row-major.
    std::vector<float> image() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace stochtex::bench
