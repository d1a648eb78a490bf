#include <gtest/gtest.h>

#include <fstream>

#include "popup/io/design_file.hpp"
#include "popup/mechanisms/horizontal_translation.hpp"
#include "popup/model/card.hpp"
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

std::string first_parameter(const Result<Scaffold>& r)
{
    return r.diagnostics.empty() ? "" : r.diagnostics.front().parameter.value_or("");
}
} // namespace

TEST(DesignFile, RoundTripKeepsEveryCoordinateAndFold)
{
    const Scaffold s = tent_card();
    const Result<Scaffold> back = scaffold_from_json(scaffold_to_json(s));
    ASSERT_TRUE(back.ok) << first_parameter(back);
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
    EXPECT_EQ(r.diagnostics.front().code, DiagnosticCode::unreadable_file);
    EXPECT_NE(r.diagnostics.front().message.find("/nonexistent/card.json"), std::string::npos);
}

TEST(DesignFile, EndlessAndNulNamedFilesAreRefused)
{
    const Result<Scaffold> endless = load_scaffold("/dev/zero"); // returns, with a limit
    ASSERT_FALSE(endless.ok);
    EXPECT_EQ(endless.diagnostics.front().code, DiagnosticCode::unreadable_file);
    EXPECT_NE(endless.diagnostics.front().message.find("larger than 256 MiB"), std::string::npos)
        << endless.diagnostics.front().message;
    const std::string tricked = std::string("tests/data/tent_fold.json") + '\0' + ".evil";
    const Result<Scaffold> nul = load_scaffold(tricked);
    ASSERT_FALSE(nul.ok);
    EXPECT_NE(nul.diagnostics.front().message.find("NUL"), std::string::npos);
    EXPECT_TRUE(load_scaffold("tests/data/tent_fold.json").ok); // the real file still loads
}

TEST(DesignFile, AFarCoordinateIsNamedByItsField)
{
    std::string text = scaffold_to_json(tent_card());
    const size_t key = text.find("\"outline\"");
    const size_t start = text.find_first_not_of(" \n", text.find('[', text.find('[', key) + 1) + 1);
    text.replace(start, text.find(',', start) - start, "1e308");
    const Result<Scaffold> r = scaffold_from_json(text);
    ASSERT_FALSE(r.ok);
    EXPECT_EQ(first_parameter(r), "patches[0].outline[0][0]");
    EXPECT_NE(r.diagnostics.front().message.find("within ±1e6 mm"), std::string::npos);
}

TEST(DesignFile, MalformedJsonIsReported)
{
    const Result<Scaffold> r = scaffold_from_json("{\"format\": ");
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.diagnostics.front().code, DiagnosticCode::bad_json);
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
    EXPECT_EQ(first_parameter(broken("\"popup-design\"", "\"other\"")), "format");
    EXPECT_EQ(first_parameter(broken("\"version\": 1", "\"version\": 7")), "version");
    EXPECT_EQ(first_parameter(broken("\"ground\": 0", "\"ground\": \"zero\"")), "ground");
    EXPECT_EQ(first_parameter(broken("\"role\": \"support\"", "\"role\": \"roof\"")),
              "patches[2].role");
    EXPECT_EQ(first_parameter(broken("\"outline\": [", "\"outlines\": [")), "patches[0].outline");
    EXPECT_EQ(first_parameter(broken("\"fold\": \"valley\"", "\"fold\": \"up\"")),
              "hinges[0].fold");
    // Ids beyond 32 bits would wrap onto another patch (2^32 onto patch 0): refused, with range.
    for (const char* id : {"4294967296", "2147483648", "-2147483649", "18446744073709551615"}) {
        const Result<Scaffold> r = broken("\"ground\": 0", std::string("\"ground\": ") + id);
        EXPECT_EQ(first_parameter(r), "ground") << id;
        EXPECT_NE(r.diagnostics.front().message.find("-2147483648 and 2147483647"),
                  std::string::npos)
            << r.diagnostics.front().message;
    }
    EXPECT_TRUE(broken("\"ground\": 0", "\"ground\": 0").ok);
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
    EXPECT_EQ(first_parameter(r), "patches[0].outline[0][0]");
}

TEST(DesignFile, SlitsRoundTripAndBadOnesAreNamed)
{
    Scaffold s = tent_card();
    s.slits.push_back({4, 2, 3, {30, 50, 0}, {30, 60, 0}});
    const std::string text = scaffold_to_json(s);
    EXPECT_NE(text.find("\"slits\""), std::string::npos);
    // The slit above lies on the tent's foot line, not in the other slope's plane.
    const Result<Scaffold> back = scaffold_from_json(text);
    EXPECT_FALSE(back.ok);
    bool named = false;
    for (const Diagnostic& d : back.diagnostics)
        named |= d.message.rfind("slit 4: ", 0) == 0 && d.code == DiagnosticCode::slit_off_plane;
    EXPECT_TRUE(named);
    std::string broken = text;
    broken.replace(broken.find("\"slits\": ["), 10, "\"slits\": [{\"patches\": [2]},");
    const Result<Scaffold> bad = scaffold_from_json(broken);
    EXPECT_FALSE(bad.ok);
    EXPECT_EQ(bad.diagnostics.front().parameter, "slits[0].patches");
}

TEST(DesignFile, SlitOfAHorizontalTranslationRoundTrips)
{
    CardParams c;
    Scaffold s = make_card(c).value;
    HorizontalTranslationParams p;
    p.offset = 60;
    p.width = 50;
    ASSERT_TRUE(add_horizontal_translation(s, central_fold(s), p).ok);
    const Result<Scaffold> back = scaffold_from_json(scaffold_to_json(s));
    ASSERT_TRUE(back.ok) << back.diagnostics.front().message;
    ASSERT_EQ(back.value.slits.size(), 1u);
    EXPECT_EQ(back.value.slits[0].patch_cut, s.slits[0].patch_cut);
    EXPECT_EQ(back.value.slits[0].patch_through, s.slits[0].patch_through);
    EXPECT_EQ(back.value.slits[0].from, s.slits[0].from);
    EXPECT_EQ(back.value.slits[0].to, s.slits[0].to);
}
