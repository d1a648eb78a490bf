// The C++ tests' main: they read their data by paths relative to the source tree
// (tests/data/...), so they run there, wherever they are started from. ctest starts them in the
// build folder, because CMake 4.3 (Debian sid) writes its test list into the working folder and
// the source tree may be read-only (make test-matrix mounts it so).
#include <cstdio>

#include <gtest/gtest.h>
#include <unistd.h>

int main(int argc, char** argv)
{
    if (chdir(POPUP_SOURCE_DIR) != 0) {
        std::perror("popup_core_tests: cannot enter the source tree " POPUP_SOURCE_DIR);
        return 1;
    }
    testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
