#include "python/Arrays.h"

#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "renderer/Error.h"

namespace py = pybind11;

namespace dw::python {

py::array toArray(const BufferImage& image) {
    const std::vector<py::ssize_t> shape = {image.height, image.width, image.channels};
    if (image.eightBit) {
        py::array_t<std::uint8_t> a(shape);
        std::memcpy(a.mutable_data(), image.bytes.data(), image.bytes.size());
        return a;
    }
    py::array_t<float> a(shape);
    std::memcpy(a.mutable_data(), image.floats.data(), image.floats.size() * sizeof(float));
    return a;
}

py::array_t<float> toArray(const FloatImage& image) {
    py::array_t<float> a(std::vector<py::ssize_t>{image.height, image.width, image.channels});
    std::memcpy(a.mutable_data(), image.pixels.data(), image.pixels.size() * sizeof(float));
    return a;
}

FloatImage toFloatImage(const py::array& input, const char* what) {
    if (input.ndim() != 2 && input.ndim() != 3)
        throw Error(std::string(what) + ": expected an H x W or H x W x C array, got " + std::to_string(input.ndim()) +
                    " dimensions");
    // Every side at least 1 (an image without pixels or channels has no error to measure), each within an int.
    for (py::ssize_t d = 0; d < input.ndim(); ++d)
        if (input.shape(d) < 1 || input.shape(d) > std::numeric_limits<int>::max())
            throw py::value_error(std::string(what) + ": an H x W (x C) array with every side from 1 to " +
                                  std::to_string(std::numeric_limits<int>::max()) + ", got " +
                                  py::str(py::tuple(input.attr("shape"))).cast<std::string>());
    FloatImage image;
    image.height = static_cast<int>(input.shape(0));
    image.width = static_cast<int>(input.shape(1));
    image.channels = input.ndim() == 3 ? static_cast<int>(input.shape(2)) : 1;
    image.pixels.resize(static_cast<size_t>(input.size()));
    if (py::isinstance<py::array_t<std::uint8_t>>(input)) {
        auto bytes = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(input);
        for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = static_cast<float>(bytes.data()[i]) / 255.0f;
    } else {
        auto floats = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(input);
        if (!floats) throw Error(std::string(what) + ": not convertible to float32");
        std::memcpy(image.pixels.data(), floats.data(), image.pixels.size() * sizeof(float));
    }
    return image;
}

}  // namespace dw::python
