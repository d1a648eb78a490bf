#include <gtest/gtest.h>

#include "popup/io/design_file.hpp"
#include "popup/simulation/check_validity.hpp"
#include "sample_files.hpp"

using namespace popup;

// Tests run from the repository root (see tests/core/CMakeLists.txt).
TEST(SampleFiles, MatchTheirBuilders)
{
    for (const auto& sample : fixtures::sample_files()) {
        const Result<Scaffold> loaded = load_scaffold(sample.path);
        ASSERT_TRUE(loaded.ok) << sample.path << ": "
                               << (loaded.diagnostics.empty() ? "" : loaded.diagnostics[0].message);
        EXPECT_EQ(scaffold_to_json(loaded.value), scaffold_to_json(sample.scaffold))
            << sample.path << " is stale: rerun build/tests/core/popup_write_samples .";
    }
}

TEST(SampleFiles, DemoCardIsValid)
{
    const Result<Scaffold> demo = load_scaffold("resources/samples/demo_card.json");
    ASSERT_TRUE(demo.ok);
    const ValidityReport r = check_validity(demo.value);
    EXPECT_TRUE(r.valid());
    EXPECT_EQ(demo.value.patches.size(), 8u);
}
