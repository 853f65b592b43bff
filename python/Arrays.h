#pragma once
// Images between the workbench and numpy: H x W x C arrays, top row first,
// channels interleaved; uint8 for 8-bit display values, float32 for the rest.
// Each conversion copies the pixels once.
#include <pybind11/numpy.h>

#include "python/WorkbenchSession.h"
#include "renderer/io/ImageIO.h"

namespace dw::python {

// A read-back output: uint8 when it holds 8-bit display values, else float32.
pybind11::array toArray(const BufferImage& image);
// A float image (a reference, an error map): float32.
pybind11::array_t<float> toArray(const FloatImage& image);

// An H x W (x C) array as a FloatImage: uint8 as display values v / 255,
// anything else as float32. `what` names the array in the messages: Error
// for another number of dimensions or what does not convert to float32,
// ValueError for a side under 1 or beyond an int.
FloatImage toFloatImage(const pybind11::array& input, const char* what);

}  // namespace dw::python
