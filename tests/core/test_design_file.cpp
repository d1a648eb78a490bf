#include <gtest/gtest.h>

#include <fstream>

#include "popup/design_file.hpp"
#include "test_support.hpp"

using namespace popup;

namespace {
Scaffold tent_card()
{
    Scaffold s = fixtures::make_card(200, 140);
    fixtures::add_tent_fold(s, 40, 60, 30, 40);
    fixtures::add_step_fold(s, 120, 40, 30, 20);
    return s;
}

std::string first_subject(const Result<Scaffold>& r)
{
    return r.diagnostics.empty() ? "" : r.diagnostics.front().subject;
}
} // namespace

TEST(DesignFile, RoundTripKeepsEveryCoordinateAndFold)
{
    const Scaffold s = tent_card();
    const Result<Scaffold> back = scaffold_from_json(scaffold_to_json(s));
    ASSERT_TRUE(back.ok) << first_subject(back);
    ASSERT_EQ(back.value.patches.size(), s.patches.size());
    ASSERT_EQ(back.value.hinges.size(), s.hinges.size());
    for (size_t i = 0; i < s.patches.size(); ++i) {
        EXPECT_EQ(back.value.patches[i].id, s.patches[i].id);
        EXPECT_EQ(back.value.patches[i].role, s.patches[i].role);
        for (size_t k = 0; k < s.patches[i].outer.size(); ++k)
            EXPECT_EQ(back.value.patches[i].outer[k], s.patches[i].outer[k]);
    }
    for (size_t i = 0; i < s.hinges.size(); ++i)
        EXPECT_EQ(back.value.hinges[i].direction, s.hinges[i].direction);
    EXPECT_DOUBLE_EQ(back.value.design_angle, s.design_angle);
}

TEST(DesignFile, SaveAndLoadThroughAFile)
{
    const Scaffold s = tent_card();
    const std::string path = ::testing::TempDir() + "/tent.json";
    save_scaffold(s, path);
    const Result<Scaffold> back = load_scaffold(path);
    ASSERT_TRUE(back.ok);
    EXPECT_NEAR(back.value.size(), s.size(), 1e-12);
}

TEST(DesignFile, MissingFileIsNamed)
{
    const Result<Scaffold> r = load_scaffold("/nonexistent/card.json");
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.diagnostics.front().code, "unreadable_file");
    EXPECT_NE(r.diagnostics.front().message.find("/nonexistent/card.json"), std::string::npos);
}

TEST(DesignFile, MalformedJsonIsReported)
{
    const Result<Scaffold> r = scaffold_from_json("{\"format\": ");
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.diagnostics.front().code, "bad_json");
}

TEST(DesignFile, BadFieldsAreNamedByPath)
{
    std::string text = scaffold_to_json(tent_card());
    // Break the fourth point of the third patch.
    auto broken = [&](const std::string& from, const std::string& to) {
        std::string t = text;
        t.replace(t.find(from), from.size(), to);
        return scaffold_from_json(t);
    };
    EXPECT_EQ(first_subject(broken("\"popup-design\"", "\"other\"")), "format");
    EXPECT_EQ(first_subject(broken("\"version\": 1", "\"version\": 7")), "version");
    EXPECT_EQ(first_subject(broken("\"ground\": 0", "\"ground\": \"zero\"")), "ground");
    EXPECT_EQ(first_subject(broken("\"role\": \"support\"", "\"role\": \"roof\"")),
              "patches[2].role");
    EXPECT_EQ(first_subject(broken("\"outline\": [", "\"outlines\": [")), "patches[0].outline");
    EXPECT_EQ(first_subject(broken("\"fold\": \"valley\"", "\"fold\": \"up\"")), "hinges[0].fold");
}

TEST(DesignFile, NullCoordinateIsNamed)
{
    std::string text = scaffold_to_json(tent_card());
    // First coordinate of the first point of the first outline.
    const size_t key = text.find("\"outline\"");
    ASSERT_NE(key, std::string::npos);
    const size_t start = text.find_first_not_of(" \n", text.find('[', text.find('[', key) + 1) + 1);
    text.replace(start, text.find(',', start) - start, "null");
    const Result<Scaffold> r = scaffold_from_json(text);
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(first_subject(r), "patches[0].outline[0][0]");
}
