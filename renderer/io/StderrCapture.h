#pragma once
// Holds what is written to the process's stderr (file descriptor 2) while it
// lives, and gives it back instead of letting it reach the terminal: libpng
// and libjpeg, under OpenImageIO, print their own lines ("libpng error: IDAT:
// ...") before OIIO reports the same problem as an error string; the CLI's
// promise is one line per problem, in the workbench's words.
// Not thread-safe (it swaps a process-wide descriptor); used around image
// decoding, which the readers do on one thread. A no-op in sanitizer builds,
// whose reports must reach the terminal even if the process dies inside.
#include <string>

namespace dw {

class StderrCapture {
public:
    StderrCapture();
    ~StderrCapture();
    StderrCapture(const StderrCapture&) = delete;
    StderrCapture& operator=(const StderrCapture&) = delete;

    // What was written so far (restores nothing; the destructor does).
    std::string text();

private:
    int saved_ = -1;  // the original stderr, -1 when not capturing
    int file_ = -1;   // an unlinked temporary file that receives the bytes
};

}  // namespace dw
