// Images in and out, for Python: the library's readers and streamed
// writers (PNG, EXR, JPEG, TIFF), linear light in memory.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstring>
#include <string>

#include "bindings.h"
#include "stochtex/core/error.h"
#include "stochtex/image/image_io.h"

namespace stochtex::python {

void bindImages(py::module_& m) {
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
        [](const std::string& path, const py::array_t<float, py::array::c_style | py::array::forcecast>& pixels,
           int bits, bool half) {
            if (pixels.ndim() != 2 && pixels.ndim() != 3)
                throw InputError::parameter("pixels",
                                            "must be an array of shape (height, width) or (height, width, "
                                            "channels)");
            const int channels = pixels.ndim() == 3 ? int(pixels.shape(2)) : 1;
            if (channels < 1 || channels > 4)
                throw InputError::parameter("pixels", "must have 1 to 4 channels, got " + std::to_string(channels));
            if (pixels.shape(0) < 1 || pixels.shape(1) < 1 || pixels.shape(0) > kMaxImageSide ||
                pixels.shape(1) > kMaxImageSide)
                throw InputError::parameter("pixels",
                                            "must be 1 to " + std::to_string(kMaxImageSide) + " pixels on each side");
            Image image(int(pixels.shape(1)), int(pixels.shape(0)), channels, Image::Uninitialized{});
            std::memcpy(image.data().data(), pixels.data(), image.data().size() * sizeof(float));
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
}

}  // namespace stochtex::python
