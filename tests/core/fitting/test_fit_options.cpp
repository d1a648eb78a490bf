// FitOptions' table: one field per option with FitOptions{}'s defaults, and check_fit_options
// refusing what lies outside it, naming the option and its range.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "popup/fitting/fit_design.hpp"

using namespace popup;

namespace {

std::map<std::string, OptionField> by_name()
{
    std::map<std::string, OptionField> out;
    for (const OptionField& f : fit_option_fields())
        out[f.name] = f;
    return out;
}

TEST(FitOptions, TheTableHoldsEveryOptionWithTheStructsDefaults)
{
    const auto fields = by_name();
    const FitOptions o;
    EXPECT_EQ(fields.size(), 14u);
    EXPECT_EQ(fields.at("card_width").default_value, o.card.width);
    EXPECT_EQ(fields.at("card_depth").default_value, o.card.depth);
    EXPECT_EQ(fields.at("max_mechanisms").default_value, o.max_mechanisms);
    EXPECT_EQ(fields.at("seed").default_value, double(o.seed));
    EXPECT_EQ(fields.at("min_part_mm").default_value, o.min_part_mm);
    EXPECT_EQ(fields.at("up").kind, OptionKind::direction);
    EXPECT_TRUE(fields.at("up").optional);
    for (const OptionField& f : fit_option_fields())
        EXPECT_FALSE(f.doc.empty()) << f.name;
    EXPECT_TRUE(check_fit_options(o).empty());
}

TEST(FitOptions, EveryDefaultIsInItsOwnRange)
{
    for (const OptionField& f : fit_option_fields()) {
        if (!f.optional) {
            EXPECT_TRUE(f.accepts(f.default_value)) << f.name << " = " << f.default_value;
        }
    }
}

TEST(FitOptions, OutOfRangeOptionsAreNamedWithTheirRange)
{
    FitOptions o;
    o.max_mechanisms = 0;
    o.card.width = 3000;
    const Diagnostics bad = check_fit_options(o);
    ASSERT_EQ(bad.size(), 2u);
    EXPECT_EQ(bad[0].message, "FitOptions.card_width = 3000, must be >= 20 and <= 2000 mm");
    EXPECT_EQ(bad[1].message, "FitOptions.max_mechanisms = 0, must be 1 to 32");
    EXPECT_EQ(bad[1].parameter.value_or(""), "max_mechanisms");
}

TEST(FitOptions, MinPartIsAtMostAQuarterOfTheCardsSmallerSide)
{
    FitOptions o;
    o.card.depth = 100;
    o.min_part_mm = 25;
    EXPECT_TRUE(check_fit_options(o).empty());
    o.min_part_mm = 26;
    const Diagnostics bad = check_fit_options(o);
    ASSERT_EQ(bad.size(), 1u);
    EXPECT_EQ(bad[0].parameter.value_or(""), "min_part_mm");
    EXPECT_NE(bad[0].message.find("a quarter of the card's smaller dimension (25 mm)"),
              std::string::npos)
        << bad[0].message;
}

TEST(FitResult, PopsUpOnlyWhenValidWithAMechanism)
{
    FitResult r;
    r.valid = true;
    EXPECT_FALSE(r.pops_up()); // a bare card
    r.mechanisms.push_back({});
    EXPECT_TRUE(r.pops_up());
    r.valid = false;
    EXPECT_FALSE(r.pops_up());
}

} // namespace
