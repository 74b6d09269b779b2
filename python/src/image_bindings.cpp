// Images in and out, for Python: the library's readers and streamed
// writers (PNG, EXR, JPEG, TIFF), linear light in memory.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstring>
#include <memory>
#include <string>

#include "bindings.h"
#include "stochtex/core/error.h"
#include "stochtex/image/image_io.h"
#include "stochtex/image/image_stream.h"

namespace stochtex::python {

namespace {

// A PNG or EXR written a band of rows at a time (bake-image's writer): the
// file appears under its name only when finish() succeeds.
class ImageStream {
public:
    ImageStream(const std::string& path, int width, int height, int channels, int bits)
        : width_(width), height_(height), channels_(channels) {
        if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
            throw InputError::parameter("size", "must be 1 to " + std::to_string(kMaxImageSide) +
                                                    " pixels on each side, got " + std::to_string(width) + "x" +
                                                    std::to_string(height));
        if (channels != 1 && channels != 3)
            throw InputError::parameter("channels", "must be 1 or 3, got " + std::to_string(channels));
        checkImageStreamFormat(path);
        WriteOptions options;
        options.bitDepth = bits;
        checkImageOutputFormat(path, options);
        py::gil_scoped_release release;
        writer_ = openImageStream(path, width, height, channels, bits);
    }

    void writeRows(const py::array_t<float, py::array::c_style | py::array::forcecast>& rows) {
        const bool shaped = rows.ndim() == (channels_ == 1 ? 2 : 3) && rows.shape(1) == width_ &&
                            (channels_ == 1 || rows.shape(2) == channels_);
        if (!shaped || rows.shape(0) < 1)
            throw InputError::parameter("rows", "must be an array of shape (rows, " + std::to_string(width_) +
                                                    (channels_ == 1 ? "" : ", " + std::to_string(channels_)) + ")");
        if (rows.shape(0) > height_ - written_)
            throw InputError::parameter("rows", std::to_string(rows.shape(0)) + " rows would pass the image's " +
                                                    std::to_string(height_) + " (" + std::to_string(written_) +
                                                    " written)");
        Image band(width_, int(rows.shape(0)), channels_, Image::Uninitialized{});
        std::memcpy(band.data().data(), rows.data(), band.data().size() * sizeof(float));
        py::gil_scoped_release release;
        writer_->writeRows(band);
        written_ += band.height();
    }

    void finish() {
        if (written_ != height_)
            throw InputError::parameter("rows", "the image has " + std::to_string(height_) + " rows, " +
                                                    std::to_string(written_) + " were written");
        py::gil_scoped_release release;
        writer_->finish();
    }
    int written() const { return written_; }

private:
    std::unique_ptr<ImageStreamWriter> writer_;
    int width_, height_, channels_, written_ = 0;
};

}  // namespace

Image imageOf(const Pixels& pixels, const std::string& parameter) {
    if (pixels.ndim() != 2 && pixels.ndim() != 3)
        throw InputError::parameter(parameter,
                                    "must be an array of shape (height, width) or (height, width, channels)");
    const int channels = pixels.ndim() == 3 ? int(pixels.shape(2)) : 1;
    if (channels < 1 || channels > 4)
        throw InputError::parameter(parameter, "must have 1 to 4 channels, got " + std::to_string(channels));
    if (pixels.shape(0) < 1 || pixels.shape(1) < 1 || pixels.shape(0) > kMaxImageSide ||
        pixels.shape(1) > kMaxImageSide)
        throw InputError::parameter(parameter,
                                    "must be 1 to " + std::to_string(kMaxImageSide) + " pixels on each side");
    Image image(int(pixels.shape(1)), int(pixels.shape(0)), channels, Image::Uninitialized{});
    std::memcpy(image.data().data(), pixels.data(), image.data().size() * sizeof(float));
    return image;
}

void bindImages(py::module_& m) {
    py::class_<ImageStream>(m, "ImageStream",
                            "A PNG (8 or 16 bits, sRGB-encoded) or EXR (float) written a band of rows at a time, "
                            "top to bottom, in bounded memory; the file appears under its name only at finish() "
                            "(a stream dropped before leaves nothing).")
        .def(py::init<const std::string&, int, int, int, int>(), py::arg("path"), py::arg("width"), py::arg("height"),
             py::kw_only(), py::arg("channels") = 3, py::arg("bits") = 8)
        .def("write_rows", &ImageStream::writeRows, py::arg("rows"),
             "The next rows, linear light: float32 (rows, width, channels) ((rows, width) for 1 channel).")
        .def("finish", &ImageStream::finish, "Completes the file once every row is written.")
        .def_property_readonly("rows_written", &ImageStream::written);

    m.def(
        "read_image",
        [](const std::string& path) {
            Image image;
            {
                py::gil_scoped_release release;
                image = readImage(path);
            }
            return imageArray(std::move(image));
        },
        py::arg("path"),
        "An image file's values as float32 (height, width, channels): an EXR's floats (stochtex writes linear "
        "light), an 8/16-bit file's codes scaled to [0, 1] (sRGB-encoded where stochtex wrote them).");
    m.def(
        "write_image",
        [](const std::string& path, const Pixels& pixels, int bits, bool half) {
            const Image image = imageOf(pixels);
            WriteOptions options;
            options.bitDepth = bits;
            options.exrHalf = half;
            py::gil_scoped_release release;
            checkImageOutputFormat(path, options);
            writeImage(path, image, options);
        },
        py::arg("path"), py::arg("pixels"), py::kw_only(), py::arg("bits") = 8, py::arg("half") = false,
        "Writes linear-light pixels to PNG/TIFF (8 or 16 bits, sRGB-encoded), JPEG or EXR (float, or half), "
        "atomically: a failed write leaves no file.");
    m.def(
        "encode_image",
        [](const Pixels& pixels, const std::string& format, int bits, bool display) {
            const Image image = imageOf(pixels);
            WriteOptions options;
            options.bitDepth = bits;
            if (display) options.transfer = Transfer::Linear;  // display codes: written as they are
            const std::string name = "image." + format;
            checkImageOutputFormat(name, options);
            std::vector<unsigned char> bytes;
            {
                py::gil_scoped_release release;
                bytes = encodeImage(name, image, options);
            }
            return py::bytes(reinterpret_cast<const char*>(bytes.data()), bytes.size());
        },
        py::arg("pixels"), py::kw_only(), py::arg("format") = "png", py::arg("bits") = 8, py::arg("display") = false,
        "The bytes write_image would write, in memory (png, jpg, tif, exr): linear-light pixels sRGB-encoded, or "
        "with display=True values that are display codes already (a study's figures) as they are.");
}

}  // namespace stochtex::python
