// GL test binaries create one headless context (EGL, llvmpipe on CI) for all cases.
#include <gtest/gtest.h>

#include <cstdio>

#include "tests/support/TestSupport.h"

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    try {
        dw::test::initGl();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "cannot create the headless GL context: %s\n", e.what());
        return 1;
    }
    return RUN_ALL_TESTS();
}
