// Every numeric option of every subcommand held to its range (issue 32):
// limits::kNumericOptions (renderer/OptionLimits.h) is walked with values
// outside each range (1e30, -1, 1e10, nan, inf, one past each end); each is
// refused with the usage exit and one line naming the option and its range,
// never a crash, a bare library message or a run. The help texts are read
// back to find numeric options the table lacks, and print its ranges.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "renderer/OptionLimits.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

using Result = test::CommandResult;

std::vector<std::string> lines(const std::string& s) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start < s.size()) {
        const auto end = s.find('\n', start);
        out.push_back(s.substr(start, end == std::string::npos ? std::string::npos : end - start));
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return out;
}

std::string text(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

// Values outside `o`'s range, as written on the command line.
std::vector<std::string> outOfRange(const NumericOption& o) {
    std::vector<std::string> values;
    for (const std::string v : {"1e30", "-1", "1e10", "nan", "inf"}) {
        const double d = std::strtod(v.c_str(), nullptr);
        // "1e30" is no whole number even where its value is in range.
        if (o.holds(d) && !o.whole()) continue;
        if (o.holds(d) && o.whole() && v.find_first_of("en") == std::string::npos) continue;
        values.push_back(v);
    }
    values.push_back(o.whole() ? std::to_string(static_cast<long long>(o.max) + 1) : text(o.max * 1.5 + 1));
    if (o.whole() || !o.minOpen) values.push_back(o.whole() ? std::to_string(static_cast<long long>(o.min) - 1) : text(o.min - 0.5));
    else values.push_back(text(o.min));
    return values;
}

// The option as written with `v` in the place of its one number.
std::string written(const NumericOption& o, const std::string& v) {
    switch (o.form) {
    case OptionForm::Size: return v + "x90";
    case OptionForm::SizeList: return "160x90," + v + "x90";
    case OptionForm::WholeList: return "4," + v;
    case OptionForm::Shard: return "0/" + v;
    default: return v;
    }
}

// The value as the refusal quotes it: a list's one item, else all of it.
std::string quoted(const NumericOption& o, const std::string& v) {
    if (o.form == OptionForm::SizeList) return v + "x90";
    if (o.form == OptionForm::WholeList) return v;
    return written(o, v);
}

// What a command needs besides the option to read its options at all.
std::string context(const std::string& command) { return command == "list" ? " passes" : ""; }

int usageExit(const std::string& command) { return command == "compare" ? 5 : 2; }

}  // namespace

TEST(OptionRangeCli, EveryNumericOptionRefusesValuesOutsideItsRangeInOneLine) {
    int runs = 0;
    for (const NumericOption& o : limits::kNumericOptions) {
        const std::string command(o.command), flag(o.flag);
        for (const std::string& v : outOfRange(o)) {
            const std::string value = written(o, v);
            const Result r = test::runWorkbench(command + context(command) + " " + flag + " " + value);
            ++runs;
            SCOPED_TRACE(command + " " + flag + " " + value);
            EXPECT_EQ(r.code, usageExit(command)) << r.err;
            const auto err = lines(r.err);
            ASSERT_FALSE(err.empty());
            // The line names the option and its range; the next only points at the help.
            EXPECT_NE(err[0].find(flag), std::string::npos) << err[0];
            EXPECT_NE(err[0].find(text(o.max)), std::string::npos) << err[0];
            EXPECT_NE(err[0].find("'" + quoted(o, v) + "'"), std::string::npos) << err[0];
            ASSERT_LE(err.size(), 2u) << r.err;
            if (err.size() == 2) {
                EXPECT_NE(err[1].find("lists its options"), std::string::npos) << r.err;
            }
        }
    }
    EXPECT_GT(runs, 300);
}

TEST(OptionRangeCli, ValuesInsideTheRangeAreNotRefusedByIt) {
    // At the ends, as the help states them: compare's two files then decide (missing: exit 4).
    for (const std::string& args : {std::string("--ppd 1"), std::string("--ppd 1000"), std::string("--fail-ssim -1"),
                                    std::string("--failpercent 100"), std::string("--hardfail 3.4e38")}) {
        const Result r = test::runWorkbench("compare missing-a.png missing-b.png " + args);
        EXPECT_EQ(r.code, 4) << args << ": " << r.err;
        EXPECT_NE(r.err.find("missing-a.png"), std::string::npos) << r.err;
    }
}

TEST(OptionRangeCli, TheTableHoldsEveryNumericOptionTheHelpNames) {
    // A flag followed by a number's metavariable (N, X, P, R, K, WxH, i/n) is numeric.
    const std::regex numeric(R"((--[a-z][a-z-]*)[ =](N|X|P|R|K|WxH|i/n)\b)");
    std::set<std::string> commands;
    for (const NumericOption& o : limits::kNumericOptions) commands.insert(std::string(o.command.substr(0, o.command.find(' '))));
    for (const char* c : {"gui", "render", "bench", "reference", "tradeoff", "compare", "replay", "list"}) commands.insert(c);
    for (const std::string& command : commands) {
        const Result help = test::runWorkbench("help " + command);
        ASSERT_EQ(help.code, 0) << command;
        for (std::sregex_iterator it(help.out.begin(), help.out.end(), numeric), end; it != end; ++it) {
            const std::string flag = (*it)[1];
            if (flag == "--preset") continue;  // P: a preset's name
            EXPECT_TRUE(findNumericOption(command, flag) != nullptr)
                << command << " " << flag << " takes a number but limits::kNumericOptions has no range for it";
        }
        // Its help prints each of its ranges.
        for (const NumericOption& o : limits::kNumericOptions) {
            if (o.command.substr(0, o.command.find(' ')) != command) continue;
            const std::string line = "  " + std::string(o.flag) + " ";  // "--budget" is not "--budget-ms"'s row
            const auto at = help.out.find(std::string(o.command) + "'s numeric options");
            ASSERT_NE(at, std::string::npos) << command << " help lacks the ranges of " << o.command;
            const auto row = help.out.find(line, at);
            ASSERT_NE(row, std::string::npos) << o.command << " " << o.flag;
            const std::string rowText = help.out.substr(row, help.out.find('\n', row) - row);
            EXPECT_NE(rowText.find(text(o.max)), std::string::npos) << rowText;
        }
    }
}

TEST(OptionRangeCli, PpdBeyondTheFilterRadiusIsRefusedNotACrash) {
    // The case's pair: --ppd 1e30 overflowed the filter radius (a crash), 1e10 a bare vector-size error.
    for (const std::string ppd : {"1e30", "1e10", "1e6", "1001", "0", "0.5"}) {
        const Result r = test::runWorkbench("compare a.pfm b.pfm --ppd " + ppd);
        EXPECT_EQ(r.code, 5) << ppd << ": " << r.err;
        EXPECT_NE(r.err.find("--ppd must be a number from 1 to 1000 (pixels per degree), got '" + ppd + "'"), std::string::npos)
            << r.err;
    }
}
