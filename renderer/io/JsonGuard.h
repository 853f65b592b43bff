#pragma once
// Checks JSON text before any parser builds a tree from it, for every JSON the
// product reads (scene files, presets, glTF, bench results):
//  - nesting depth is bounded (kMaxJsonDepth): recursive readers and writers
//    (tinygltf's extras, nlohmann's dump) would otherwise overflow the stack;
//  - a number that does not fit a 64-bit double ("1e400") is reported with the
//    JSON path of its field, not the JSON library's exception text;
//  - optionally, every number must fit a 32-bit float (|v| <= FLT_MAX): the
//    renderer stores every quantity of these formats as a float, and 1e39
//    would silently become +inf.
// Text that is not well-formed JSON is left to the parser to report: the scan
// stops quietly at the first byte it does not expect.
#include <cstddef>
#include <exception>
#include <functional>
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

namespace dw {

// Deeper than any file of these formats needs, far below what the recursive
// readers' stacks can take (also under AddressSanitizer).
constexpr int kMaxJsonDepth = 128;

struct JsonGuardOptions {
    int maxDepth = kMaxJsonDepth;
    bool numbersAreFloats = true;  // refuse numbers beyond the 32-bit float range
    // For formats with integer fields (glTF's counts, offsets, indices): given
    // the JSON path of a number beyond a float (or a double), its value and
    // its text, what is wrong with it as that field's integer, or empty when
    // the field is not an integer (then the float message stands).
    std::function<std::string(const std::string& path, double value, const std::string& number)> integerProblem;
};

// Throws FileError(source, "<json path>: <problem>"), e.g.
// "scene.json: lights[0].intensity: 1e39 does not fit a 32-bit float (largest about 3.4e38)"
// or "preset.json: line 1, column 129: JSON nested deeper than 128 levels (at knobs.x[0][0]...)".
void checkJsonText(std::string_view text, const std::string& source, const JsonGuardOptions& options = {});

// The one way the product reads JSON: checkJsonText, then nlohmann's parser.
// Nothing calls nlohmann::json::parse directly (a unit test looks), so no
// reader can forget the guard. Malformed JSON throws
// FileError(source, "malformed JSON at line L, column C: <what the parser expected>").
nlohmann::json parseJson(std::string_view text, const std::string& source, const JsonGuardOptions& options = {});
// The same, with nlohmann's parser callback seeing every event: `event` is
// nlohmann::json::parse_event_t as an int (object_start, object_end,
// array_start, array_end, key, value), `parsed` the key or value; return
// true to keep it. What the parsed value alone cannot show, such as a key
// given twice in one object (the parser keeps the last). Exceptions the
// callback throws pass through unchanged.
using JsonEvents = std::function<bool(int depth, int event, nlohmann::json& parsed)>;
nlohmann::json parseJsonWithEvents(std::string_view text, const std::string& source, const JsonEvents& events,
                                   const JsonGuardOptions& options = {});
// The same, keeping the file's key order (scene settings apply in order).
nlohmann::ordered_json parseOrderedJson(std::string_view text, const std::string& source, const JsonGuardOptions& options = {});
// The same for a file: readWholeFile, then parseJson.
nlohmann::json readJsonFile(const std::string& path, const JsonGuardOptions& options = {});

// JSON texts parsed (parseJson, parseOrderedJson, readJsonFile) in this
// process so far: tests check that a file's JSON is parsed once.
long long jsonParseCount();

// A JSON library exception's text without its "[json.exception.type_error.302] "
// tag, for the rare error the checks above leave to the parser.
std::string jsonErrorText(const std::exception& e);

}  // namespace dw
