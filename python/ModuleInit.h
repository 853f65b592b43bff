#pragma once
// What the module checks and sets when Python imports it, before any class
// is defined (kept out of the bindings, python/Bindings.h, which hold the API).
#include <pybind11/pybind11.h>

#include <string>

namespace dw {

// Imports numpy: every image the module returns is a numpy array, and
// pybind11 imports numpy only at the first one, so a python3 without numpy
// imported the module and failed at its first render. Throws
// pybind11::import_error (Python's ImportError, one line) naming numpy, the
// interpreter (sys.executable) and numpy's own import error.
void requireNumpy();

// The build's version and commit as a PEP 440 version with a local part,
// "VERSION+COMMIT" (renderer/record/BuildInfo: the project version and `git
// describe --always --dirty` at configure time, each character other than
// a letter or digit written as '.'); "VERSION" alone when the commit is unknown.
std::string moduleVersion();

// `git describe --always --dirty` at configure time, as records hold it
// ("unknown" when the source was not a git checkout).
std::string moduleCommit();

}  // namespace dw
