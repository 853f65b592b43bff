// Every input in fuzz/regression/ (each one crashed, hung, overflowed the stack
// or was accepted with a non-finite value once, or is one of the broken inputs
// the issue tracker collected) and every seed in fuzz/corpus/, fed to the same
// entry functions the libFuzzer targets call. The entry functions abort on a
// non-finite value or an unclear message; here each input must also end as
// the behaviour its file name's kind expects.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "fuzz/FuzzEntries.h"

namespace fs = std::filesystem;

namespace {

std::string bytesOf(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

using Entry = std::string (*)(const std::uint8_t*, std::size_t);

// Runs `entry` on every file in fuzz/<kind>/<target>; returns how many.
int feedAll(const std::string& kind, const std::string& target, Entry entry) {
    int count = 0;
    const fs::path dir = fs::path(DW_FUZZ_DIR) / kind / target;
    for (const auto& f : fs::directory_iterator(dir)) {
        const std::string bytes = bytesOf(f.path());
        entry(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
        ++count;
    }
    return count;
}

}  // namespace

// Ends without a crash, a sanitizer report, a non-finite value or an unclear
// message (the entry functions abort on those two). What each case must say
// is asserted in ReaderValidationTest.
TEST(FuzzRegression, EveryRegressionInputEndsCleanly) {
    EXPECT_GE(feedAll("regression", "scene_json", dw::fuzz::sceneJson), 4);
    EXPECT_GE(feedAll("regression", "preset", dw::fuzz::preset), 2);
    EXPECT_GE(feedAll("regression", "gltf", dw::fuzz::gltf), 3);
}

// The seed corpora hold valid files: each must load.

TEST(FuzzRegression, EverySeedLoads) {
    int count = 0;
    for (const auto& [target, entry] : std::initializer_list<std::pair<const char*, Entry>>{
             {"scene_json", dw::fuzz::sceneJson}, {"preset", dw::fuzz::preset}, {"gltf", dw::fuzz::gltf}}) {
        for (const auto& f : fs::directory_iterator(fs::path(DW_FUZZ_DIR) / "corpus" / target)) {
            const std::string bytes = bytesOf(f.path());
            EXPECT_EQ(entry(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()), "") << f.path();
            ++count;
        }
    }
    EXPECT_GE(count, 6);
}
