#pragma once
// Finds where a NaN or an infinity enters the pipeline (issue 10): counts the
// non-finite values of every buffer a frame produced, in pipeline order, so
// the first one named is the earliest pass that made one. Used by
// `render --check-finite` and the buffer viewer's non-finite view.
#include <string>
#include <vector>

#include "renderer/graph/OutputRegistry.h"
#include "renderer/io/ImageIO.h"

namespace dw {

struct NonFiniteCount {
    std::string buffer;        // the output's name
    long long values = 0;      // values (channels) checked
    long long nan = 0, positiveInf = 0, negativeInf = 0;
    int firstX = -1, firstY = -1;  // the first non-finite pixel (image rows top-down), -1 if none
    long long nonFinite() const { return nan + positiveInf + negativeInf; }
};

class FiniteCheck {
public:
    // Counts the non-finite values of one image (all channels).
    static NonFiniteCount count(const FloatImage& image, const std::string& name);
    // Every output produced this frame (allocated and written), in pipeline
    // order; integer and depth-stencil formats are read as their values.
    // Needs the GL context the frame was drawn in.
    static std::vector<NonFiniteCount> scan(const OutputRegistry& outputs);
};

}  // namespace dw
