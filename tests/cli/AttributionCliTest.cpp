// `tradeoff --attribute` as a user runs it (issue 34 part 4): one row per
// approximation family with its parts and their intervals; the post effects'
// parts exactly 0 on the L-buffer (they act after it), a family whose knobs
// change nothing exactly 0, each part the difference of the rows it names,
// a family the reference models kept and said, bad input refused in one line.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "tests/support/TestSupport.h"

namespace fs = std::filesystem;

namespace {

fs::path dir() {
    static const fs::path d = [] {
        fs::path p = dw::test::tempDir() / "attribution";
        fs::create_directories(p);
        return p;
    }();
    return d;
}

dw::test::CommandResult run(const std::string& args) {
    return dw::test::runCommand("DW_REFERENCE_CACHE=" + (dir() / "cache").string() + " " + DW_WORKBENCH_BINARY + " " + args);
}

using Row = std::map<std::string, std::string>;

// The CSV's rows by their first column (no field of these tests holds a comma).
std::map<std::string, Row> readRows(const fs::path& path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    std::vector<std::string> header;
    std::stringstream h(line);
    for (std::string f; std::getline(h, f, ',');) header.push_back(f);
    std::map<std::string, Row> rows;
    while (std::getline(in, line)) {
        std::stringstream s(line);
        Row row;
        size_t i = 0;
        for (std::string f; i < header.size() && std::getline(s, f, ','); ++i) row[header[i]] = f;
        rows[row["row"]] = row;
    }
    return rows;
}

double num(const Row& r, const std::string& column) {
    const std::string& t = r.at(column);
    return t.empty() ? std::nan("") : std::stod(t);
}

}  // namespace

TEST(AttributionCli, EachFamilysPartsOnTheLBufferWithTheThresholdKeptUnderWindowedAttenuation) {
    const fs::path csv = dir() / "lbuffer.csv", png = dir() / "lbuffer.png";
    const auto r = run("tradeoff --attribute --scene default --size 96x54 --metric rms --buffer lbuffer "
                       "--set lighting.attenuation=windowed --ao-rays 16 --resamples 200 --quiet --csv " + csv.string() +
                       " --plot " + png.string() + " --plot-size 400x300");
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    EXPECT_NE((r.out + r.err).find("| shadows | only exact"), std::string::npos) << r.out << r.err;
    EXPECT_NE((r.out + r.err).find("note: light_cutoff: left as it is (the reference models it here): lighting.threshold"),
              std::string::npos) << r.out << r.err;
    EXPECT_TRUE(fs::file_size(png) > 1000);
    const auto rows = readRows(csv);
    ASSERT_EQ(rows.size(), 11u);
    const double asIs = num(rows.at("as_is"), "error"), exact = num(rows.at("all_exact"), "error");
    EXPECT_GT(asIs, exact);
    EXPECT_NEAR(num(rows.at("all_exact"), "removed"), asIs - exact, 1e-6 * asIs);
    for (const char* family : {"shadows", "ao", "light_cutoff", "gbuffer", "texture_filter", "transparency", "bloom",
                               "dof", "aa"}) {
        const Row& f = rows.at(family);
        // Each part is the difference of the two errors it names, inside its interval.
        EXPECT_NEAR(num(f, "removed"), asIs - num(f, "only_exact"), 1e-6 * asIs) << family;
        EXPECT_NEAR(num(f, "added"), num(f, "only_approximate") - exact, 1e-6 * asIs) << family;
        for (const char* part : {"removed", "added"}) {
            EXPECT_LE(num(f, std::string(part) + "_lo"), num(f, part)) << family << " " << part;
            EXPECT_GE(num(f, std::string(part) + "_hi"), num(f, part)) << family << " " << part;
        }
    }
    // Bloom, depth of field and anti-aliasing (FXAA by default) act after the L-buffer; `default` has no blended surface.
    for (const char* none : {"bloom", "dof", "aa", "transparency"}) {
        EXPECT_EQ(num(rows.at(none), "removed"), 0.0) << none;
        EXPECT_EQ(num(rows.at(none), "added"), 0.0) << none;
    }
    // The AO and the shadow maps do change the L-buffer against rays.
    EXPECT_GT(num(rows.at("ao"), "added_lo"), 0.0);
    EXPECT_GT(num(rows.at("shadows"), "added_lo"), 0.0);
    // Under the windowed model the threshold is the reference's own: the family sets the strategy alone.
    EXPECT_EQ(rows.at("light_cutoff").at("sets"), "\"lighting.strategy=fullscreen\"");
}

TEST(AttributionCli, FxaaIsAPartOfTheFinalImagesError) {
    const fs::path csv = dir() / "final.csv";
    const auto r = run("tradeoff --attribute --scene default --size 96x54 --ao-rays 16 --resamples 200 --quiet "
                       "--plot none --csv " + csv.string());
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    EXPECT_NE((r.out + r.err).find("Where the flip error of `final` comes from"), std::string::npos) << r.out << r.err;
    EXPECT_NE((r.out + r.err).find("the parts sum to"), std::string::npos) << r.out << r.err;
    const auto rows = readRows(csv);
    EXPECT_GT(num(rows.at("aa"), "added_lo"), 0.0);
    EXPECT_FALSE(fs::exists(dir() / "attribution.png"));
}

TEST(AttributionCli, BadInputIsOneLineBeforeAnythingRenders) {
    const fs::path csv = dir() / "bad.csv";
    auto r = run("tradeoff --attribute --scene default --metric psnr --csv " + csv.string());
    EXPECT_NE(r.code, 0);
    EXPECT_NE((r.out + r.err).find("--attribute needs an error metric whose parts subtract: flip or rms, got 'psnr'"),
              std::string::npos) << r.out << r.err;
    EXPECT_FALSE(fs::exists(csv));
    r = run("tradeoff --attribute --scene default --buffer depth --csv " + csv.string());
    EXPECT_NE(r.code, 0);
    EXPECT_NE((r.out + r.err).find("--buffer: expected final, lbuffer, ao or shadow, got 'depth'"), std::string::npos) << r.out << r.err;
    r = run("tradeoff --attribute --scene nowhere.json --csv " + csv.string());
    EXPECT_NE(r.code, 0);
    EXPECT_NE((r.out + r.err).find("nowhere.json"), std::string::npos) << r.out << r.err;
    EXPECT_FALSE(fs::exists(csv));
}
