#include "stochtex/image/image_io.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <random>
#include <vector>

#include "stochtex/core/error.h"

namespace stochtex {
namespace fs = std::filesystem;

namespace {

// OpenCV refuses EXR unless this is set before its first codec call.
void enableExr() {
    static const bool done = [] {
        setenv("OPENCV_IO_ENABLE_OPENEXR", "1", 0);
        return true;
    }();
    (void)done;
}

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

}  // namespace

bool isSupportedImagePath(const std::string& path) {
    const std::string ext = lowerExtension(path);
    return ext == ".png" || ext == ".exr";
}

Image readImage(const std::string& path) {
    enableExr();
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) throw InputError(path + ": no such image file");
    std::ifstream in(path, std::ios::binary);
    std::vector<uchar> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in.good() && !in.eof()) throw InputError(path + ": cannot read file");
    cv::Mat m;
    try {
        m = cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
    } catch (const cv::Exception& e) {
        throw InputError(path + ": cannot decode image (" + e.msg + ")");
    }
    if (m.empty()) throw InputError(path + ": not a readable image (corrupt or unsupported format)");

    const int channels = m.channels();
    if (channels != 1 && channels != 3 && channels != 4)
        throw InputError(path + ": unsupported channel count " + std::to_string(channels));
    double scale = 1.0;
    switch (m.depth()) {
        case CV_8U: scale = 1.0 / 255.0; break;
        case CV_16U: scale = 1.0 / 65535.0; break;
        case CV_32F:
        case CV_64F: scale = 1.0; break;
        default: throw InputError(path + ": unsupported pixel depth");
    }
    cv::Mat f;
    m.convertTo(f, CV_32F, scale);
    if (channels == 3) cv::cvtColor(f, f, cv::COLOR_BGR2RGB);
    if (channels == 4) cv::cvtColor(f, f, cv::COLOR_BGRA2RGBA);

    Image image(f.cols, f.rows, channels);
    for (int y = 0; y < f.rows; ++y) {
        const float* src = f.ptr<float>(y);
        float* dst = image.row(y);
        for (int i = 0; i < f.cols * channels; ++i) {
            if (!std::isfinite(src[i])) throw InputError(path + ": contains NaN or infinite values");
            dst[i] = src[i];
        }
    }
    return image;
}

void writeFileAtomic(const std::string& path, const std::string& bytes) {
    const fs::path target(path);
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) throw InputError(path + ": directory " + dir.string() + " does not exist");
    std::random_device rd;
    // Built by appending: GCC 12 warns falsely (-Wrestrict) on "." + string.
    std::string name = ".";
    name += target.filename().string();
    name += '.';
    name += std::to_string(rd());
    name += ".tmp";
    const fs::path tmp = dir / name;
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw InputError(path + ": cannot create file in " + dir.string());
        out.write(bytes.data(), std::streamsize(bytes.size()));
        out.close();
        if (!out) {
            fs::remove(tmp, ec);
            throw InputError(path + ": write failed");
        }
    }
    fs::rename(tmp, target, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw InputError(path + ": cannot rename temporary file into place");
    }
}

void writeImage(const std::string& path, const Image& image, const WriteOptions& options) {
    enableExr();
    const std::string ext = lowerExtension(path);
    if (ext != ".png" && ext != ".exr")
        throw InputError(path + ": unsupported output format '" + ext + "' (use .png or .exr)");
    if (image.empty()) throw InputError(path + ": refusing to write an empty image");
    const int channels = image.channels();
    cv::Mat f(image.height(), image.width(), CV_32FC(channels), const_cast<float*>(image.data().data()));
    cv::Mat bgr;
    if (channels == 3)
        cv::cvtColor(f, bgr, cv::COLOR_RGB2BGR);
    else if (channels == 4)
        cv::cvtColor(f, bgr, cv::COLOR_RGBA2BGRA);
    else
        bgr = f;

    cv::Mat encoded;
    std::vector<int> params;
    if (ext == ".png") {
        if (options.pngBitDepth == 16)
            bgr.convertTo(encoded, CV_16U, 65535.0);  // convertTo rounds and saturates
        else if (options.pngBitDepth == 8)
            bgr.convertTo(encoded, CV_8U, 255.0);
        else
            throw InputError(path + ": PNG bit depth must be 8 or 16");
        params = {cv::IMWRITE_PNG_COMPRESSION, 3};
    } else {
        encoded = bgr;
        params = {cv::IMWRITE_EXR_TYPE, options.exrHalf ? cv::IMWRITE_EXR_TYPE_HALF : cv::IMWRITE_EXR_TYPE_FLOAT};
    }
    std::vector<uchar> buffer;
    bool ok = false;
    try {
        ok = cv::imencode(ext, encoded, buffer, params);
    } catch (const cv::Exception& e) {
        throw InputError(path + ": cannot encode image (" + e.msg + ")");
    }
    if (!ok) throw InputError(path + ": cannot encode image");
    writeFileAtomic(path, std::string(buffer.begin(), buffer.end()));
}

}  // namespace stochtex
