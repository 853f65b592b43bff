#pragma once
// One line of a CSV file as bench and tradeoff write them (RFC 4180 quoting,
// no newline inside a field). Needs no GL.
#include <string>
#include <vector>

namespace dw {

// `text` as one field: quoted when it holds a comma, a quote or a line break.
std::string csvField(const std::string& text);
// The shortest text that reads back to the same double; "" for NaN (a
// CSV read back gives the very numbers written).
std::string csvNumber(double v);
// One line into its fields (quotes undone; a trailing '\r' dropped).
std::vector<std::string> splitCsvLine(const std::string& line);

}  // namespace dw
