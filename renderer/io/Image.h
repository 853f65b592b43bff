#pragma once
// A decoded image in CPU memory, 8-bit RGBA, rows top-down.
#include <cstdint>
#include <string>
#include <vector>

namespace dw {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  // width * height * 4
    std::string source;              // file or "<name>#image3" it came from
};

}  // namespace dw
