// Writing images: our streamed encoders (PNG through libpng, EXR with our
// ZIP blocks) against OpenCV's whole-image encoder for the same EXR, on a
// 2048² render of the marble preset (real content, for the compression).
// Counters: MB/s of float pixels encoded, and the file's size over the
// float image's bytes.
#include <benchmark/benchmark.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "stochtex/image/image_io.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/presets.h"

using namespace stochtex;

namespace {

const Image& marble2048() {
    static const Image image = [] {
        View view;
        view.width = view.height = 2048;
        return GraphPattern::build(loadPreset("marble")).render(view);
    }();
    return image;
}

// 0: PNG 8-bit, 1: EXR float (ours), 2: EXR half (ours), 3: EXR float
// (OpenCV: channels swapped, cv::imencode, ZIP), 4: EXR half (OpenCV),
// 5: TIFF 8-bit, 6: JPEG.
void BM_EncodeImage(benchmark::State& state) {
    const Image& image = marble2048();
    const int kind = int(state.range(0));
    static const char* const kPaths[] = {"a.png", "a.exr", "a.exr", "", "", "a.tif", "a.jpg"};
    size_t bytes = 0;
    for (auto _ : state) {
        std::vector<unsigned char> out;
        if (kind == 3 || kind == 4) {
            setenv("OPENCV_IO_ENABLE_OPENEXR", "1", 0);
            cv::Mat rgb(image.height(), image.width(), CV_32FC3, const_cast<float*>(image.data().data())), bgr;
            cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
            const int type = kind == 4 ? cv::IMWRITE_EXR_TYPE_HALF : cv::IMWRITE_EXR_TYPE_FLOAT;
            cv::imencode(".exr", bgr, out, {cv::IMWRITE_EXR_TYPE, type});
        } else {
            out = encodeImage(kPaths[kind], image, WriteOptions{.exrHalf = kind == 2});
        }
        bytes = out.size();
        benchmark::DoNotOptimize(out.data());
    }
    const double floatBytes = double(image.data().size()) * sizeof(float);
    state.counters["MB/s"] = benchmark::Counter(floatBytes * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["size/float"] = double(bytes) / floatBytes;
}
BENCHMARK(BM_EncodeImage)->DenseRange(0, 6)->ArgName("kind")->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
