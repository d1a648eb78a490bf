// MotionOptions' table (its own fields, the view's, the chains') and check_motion_options:
// every bad option named with its range, the two weights of eq 6.5 not both 0.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "popup/motion/motion_types.hpp"

using namespace popup;

namespace {

std::vector<std::string> named(const Diagnostics& diagnostics)
{
    std::vector<std::string> out;
    for (const Diagnostic& d : diagnostics) {
        EXPECT_EQ(d.code, DiagnosticCode::bad_option);
        out.push_back(d.parameter.value_or(""));
    }
    return out;
}

TEST(MotionOptions, TheTableHoldsEveryOptionGroupedWithTheStructsDefaults)
{
    std::map<std::string, OptionField> fields;
    for (const OptionField& f : motion_option_fields())
        fields[f.group + "." + f.name] = f;
    const MotionOptions o;
    EXPECT_EQ(fields.at(".iterations").default_value, double(o.iterations));
    EXPECT_EQ(fields.at(".seed").default_value, double(o.seed));
    EXPECT_EQ(fields.at("view.card_width").default_value, o.view.card.width);
    EXPECT_EQ(fields.at("view.last_frame").default_value, -1.0);
    EXPECT_EQ(fields.at("chains.prune_fraction").default_value, o.chains.prune_fraction);
    EXPECT_EQ(fields.size(), motion_option_fields().size()); // no name twice in a group
    for (const OptionField& f : motion_option_fields()) {
        EXPECT_FALSE(f.doc.empty()) << f.name;
        if (!f.optional && (f.kind == OptionKind::number || f.kind == OptionKind::count)) {
            EXPECT_TRUE(f.accepts(f.default_value)) << f.name;
        }
    }
    EXPECT_TRUE(check_motion_options(o).empty());
}

TEST(MotionOptions, BadOptionsAreNamedWithTheirRange)
{
    MotionOptions o;
    o.iterations = -3;
    o.search_chains = 17;
    o.chains.prune_fraction = 2;
    const Diagnostics bad = check_motion_options(o);
    EXPECT_EQ(named(bad),
              (std::vector<std::string>{"iterations", "search_chains", "prune_fraction"}));
    EXPECT_EQ(bad[0].message, "MotionOptions.iterations = -3, must be 0 to 100000000");
    EXPECT_EQ(bad[1].message, "MotionOptions.search_chains = 17, must be 1 to 16");
    EXPECT_EQ(bad[2].message, "ChainOptions.prune_fraction = 2, must be >= 0 and <= 1");
}

TEST(MotionOptions, TheWeightsOfEq65AreNotBothZero)
{
    MotionOptions o;
    o.motion_weight = 0;
    EXPECT_TRUE(check_motion_options(o).empty());
    o.depth_weight = 0;
    EXPECT_EQ(named(check_motion_options(o)), (std::vector<std::string>{"motion_weight"}));
    o.depth_weight = -1;
    EXPECT_EQ(named(check_motion_options(o)), (std::vector<std::string>{"depth_weight"}));
}

TEST(MotionOptions, TheViewsOptionsAreCheckedWithThem)
{
    MotionOptions o;
    o.view.card.depth = 0;
    o.view.up = Vec3(0, 0, 3); // along the view
    o.view.first_frame = 4;
    o.view.last_frame = 4;
    o.view.scale = -1.0;
    const Diagnostics bad = check_motion_options(o);
    EXPECT_EQ(named(bad), (std::vector<std::string>{"up", "scale", "card_depth", "last_frame"}));
    EXPECT_EQ(bad[2].message, "MotionView.card_depth = 0, must be > 0 and <= 2000 mm");
    o = MotionOptions();
    o.view.centre = Vec2(0, std::nan(""));
    o.view.angle_tolerance = 90;
    EXPECT_EQ(named(check_motion_options(o)),
              (std::vector<std::string>{"angle_tolerance", "centre"}));
}

TEST(MotionResult, PopsUpOnlyWhenValidWithAMechanism)
{
    MotionResult r;
    r.valid = true;
    EXPECT_FALSE(r.pops_up()); // every chain printed on the page
    r.mechanisms.push_back({});
    EXPECT_TRUE(r.pops_up());
}

} // namespace
