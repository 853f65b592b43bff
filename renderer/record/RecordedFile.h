#pragma once
// One input file of an experiment record (a scene's file, a shader file):
// its path as the record names it and the sha256 of its content.
#include <string>

namespace dw {

struct RecordedFile {
    std::string path, sha256;  // sha256 empty: the file could not be read
};

}  // namespace dw
