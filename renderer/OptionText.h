#pragma once
// How the messages name a numeric option's range (OptionLimits'
// kNumericOptions): the command line's refusals (headless/CommandLine) and
// the checks that take the same values from Python or the window
// (BudgetPicker::check) say it in the same words, e.g.
//   "--budget-ms must be a number above 0 and at most 1000000000 (GPU milliseconds), got '2e+09'".
// Needs no GL.
#include <string>

#include "renderer/OptionLimits.h"

namespace dw {

// A figure in a table's or a pick's line: 4 significant digits (%.4g), NaN as "-".
std::string figureText(double v);
// A number as the messages write it (%.10g: "1000000000", "1e+18", "nan").
std::string optionNumberText(double v);
// "a whole number from 1 to 100000 (counted frames)", "a number above 0 and at most 1e+18 (...)".
std::string optionRangeText(const NumericOption& o);
// "<flag> must be <range>, got '<value>'": the refusal of a value out of `o`'s range.
std::string optionRefusal(const NumericOption& o, const std::string& given);

}  // namespace dw
