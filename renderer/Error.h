#pragma once
// Error values the renderer throws. Every message names what was wrong and,
// where there is one, the file; the CLI prints what() on one line.
#include <stdexcept>
#include <string>

namespace dw {

class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A problem with an input file: "<path>: <detail>".
class FileError : public Error {
public:
    FileError(std::string path, const std::string& detail)
        : Error(path + ": " + detail), path_(std::move(path)) {}
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

// The OpenGL implementation lacks something the renderer needs.
class GlUnsupportedError : public Error {
public:
    using Error::Error;
};

}  // namespace dw
