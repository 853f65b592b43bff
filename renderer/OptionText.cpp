#include "renderer/OptionText.h"

#include <cmath>
#include <cstdio>

namespace dw {

std::string figureText(double v) {
    if (std::isnan(v)) return "-";
    char text[32];
    std::snprintf(text, sizeof(text), "%.4g", v);
    return text;
}

std::string optionNumberText(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

std::string optionRangeText(const NumericOption& o) {
    std::string s = o.whole() ? "a whole number " : "a number ";
    s += o.minOpen ? "above " + optionNumberText(o.min) + " and at most " + optionNumberText(o.max)
                   : "from " + optionNumberText(o.min) + " to " + optionNumberText(o.max);
    return s + " (" + std::string(o.what) + ")";
}

std::string optionRefusal(const NumericOption& o, const std::string& given) {
    return std::string(o.flag) + " must be " + optionRangeText(o) + ", got '" + given + "'";
}

}  // namespace dw
