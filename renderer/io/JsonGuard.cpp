#include "renderer/io/JsonGuard.h"

#include <atomic>
#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/Error.h"
#include "renderer/io/TextFile.h"

namespace dw {

namespace {

// One open container: its kind, and where the scan is inside it.
struct Frame {
    bool object = false;
    bool expectKey = true;  // objects: the next string is a key
    std::string key;        // objects: the current member's key
    std::size_t index = 0;  // arrays: the current element's index
};

// "lights[2].intensity"; a very deep path keeps its start and end only.
std::string pathOf(const std::vector<Frame>& stack) {
    std::string p;
    for (const Frame& f : stack) {
        if (f.object) {
            if (f.expectKey) continue;  // between members: the object itself
            if (!p.empty()) p += '.';
            p += f.key;
        } else {
            p += "[" + std::to_string(f.index) + "]";
        }
    }
    constexpr std::size_t kShown = 60;
    if (p.size() > 2 * kShown) p = p.substr(0, kShown) + "..." + p.substr(p.size() - kShown / 2);
    return p.empty() ? "top level" : p;
}

bool isNumberByte(char c) {
    return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
}

}  // namespace

void checkJsonText(std::string_view text, const std::string& source, const JsonGuardOptions& options) {
    std::vector<Frame> stack;
    std::size_t i = 0;
    const std::size_t n = text.size();
    while (i < n) {
        const char c = text[i];
        switch (c) {
            case ' ': case '\t': case '\n': case '\r': ++i; break;
            case '{':
            case '[': {
                if (static_cast<int>(stack.size()) >= options.maxDepth)
                    throw FileError(source, textPosition(text, i + 1) + ": JSON nested deeper than " +
                                                std::to_string(options.maxDepth) + " levels (at " + pathOf(stack) + ")");
                Frame f;
                f.object = c == '{';
                stack.push_back(f);
                ++i;
                break;
            }
            case '}':
            case ']':
                if (stack.empty()) return;  // malformed: the parser reports it
                stack.pop_back();
                ++i;
                break;
            case ',':
                if (stack.empty()) return;
                if (stack.back().object) stack.back().expectKey = true;
                else ++stack.back().index;
                ++i;
                break;
            case ':': ++i; break;
            case '"': {
                std::size_t j = i + 1;
                while (j < n && text[j] != '"') j += text[j] == '\\' ? 2 : 1;
                if (j >= n) return;
                if (!stack.empty() && stack.back().object && stack.back().expectKey) {
                    stack.back().key.assign(text.substr(i + 1, j - i - 1));
                    stack.back().expectKey = false;
                }
                i = j + 1;
                break;
            }
            default: {
                if (c == 't' || c == 'f' || c == 'n') {
                    while (i < n && text[i] >= 'a' && text[i] <= 'z') ++i;
                    break;
                }
                if (!isNumberByte(c)) return;
                std::size_t j = i;
                while (j < n && isNumberByte(text[j])) ++j;
                const std::string token(text.substr(i, j - i));
                errno = 0;
                char* end = nullptr;
                const double v = std::strtod(token.c_str(), &end);
                // The number a parser reads is the longest prefix that is one
                // ("3.4e381" of "3.4e381e4"): check it before giving up on the rest.
                if (end == token.c_str()) return;
                const std::string number(token.c_str(), static_cast<std::size_t>(end - token.c_str()));
                const bool beyondDouble = errno == ERANGE && std::isinf(v);
                if ((beyondDouble || (options.numbersAreFloats && std::fabs(v) > static_cast<double>(FLT_MAX))) &&
                    options.integerProblem) {
                    const std::string path = pathOf(stack);
                    if (const std::string problem = options.integerProblem(path, v, number); !problem.empty())
                        throw FileError(source, path + ": " + problem);
                }
                if (beyondDouble)
                    throw FileError(source, pathOf(stack) + ": " + number + " is too large for any number the workbench reads (" +
                                                textPosition(text, i + 1) + ")");
                if (options.numbersAreFloats && std::fabs(v) > static_cast<double>(FLT_MAX))
                    throw FileError(source, pathOf(stack) + ": " + number +
                                                " does not fit a 32-bit float (largest about 3.4e38)");
                if (end != token.c_str() + token.size()) return;  // malformed after the number: the parser reports it
                i = j;
                break;
            }
        }
    }
}

}  // namespace dw

namespace dw {

std::string jsonErrorText(const std::exception& e) {
    std::string m = e.what();
    if (m.rfind("[json.exception.", 0) == 0) {
        const std::size_t close = m.find("] ");
        if (close != std::string::npos) m = m.substr(close + 2);
    }
    return m;
}

}  // namespace dw

namespace dw {

namespace {

std::atomic<long long> parses{0};

template <typename Json>
Json guardedParse(std::string_view text, const std::string& source, const JsonGuardOptions& options,
                  const typename Json::parser_callback_t& events = nullptr) {
    ++parses;
    checkJsonText(text, source, options);  // depth first: nlohmann's parser recurses
    try {
        return Json::parse(text, events);
    } catch (const nlohmann::json::parse_error& e) {
        // "parse error at line 1, column 5: syntax error while parsing value - ...":
        // the position in our words, then what the parser expected.
        std::string detail = jsonErrorText(e);
        if (const std::size_t colon = detail.find(": "); detail.rfind("parse error", 0) == 0 && colon != std::string::npos)
            detail = detail.substr(colon + 2);
        throw FileError(source, "malformed JSON at " + textPosition(text, e.byte) + ": " + detail);
    } catch (const nlohmann::json::exception& e) {
        throw FileError(source, "unreadable JSON: " + jsonErrorText(e));
    }
}

}  // namespace

nlohmann::json parseJson(std::string_view text, const std::string& source, const JsonGuardOptions& options) {
    return guardedParse<nlohmann::json>(text, source, options);
}

nlohmann::json parseJsonWithEvents(std::string_view text, const std::string& source, const JsonEvents& events,
                                   const JsonGuardOptions& options) {
    const nlohmann::json::parser_callback_t callback = [&events](int depth, nlohmann::json::parse_event_t event,
                                                                 nlohmann::json& parsed) {
        return events(depth, static_cast<int>(event), parsed);
    };
    return guardedParse<nlohmann::json>(text, source, options, callback);
}

nlohmann::ordered_json parseOrderedJson(std::string_view text, const std::string& source, const JsonGuardOptions& options) {
    return guardedParse<nlohmann::ordered_json>(text, source, options);
}

long long jsonParseCount() { return parses.load(); }

nlohmann::json readJsonFile(const std::string& path, const JsonGuardOptions& options) {
    return parseJson(readWholeFile(path, "not found", "cannot read"), path, options);
}

}  // namespace dw
