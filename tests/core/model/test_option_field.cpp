// The options' vocabulary: a field accepts its range and states it as errors do.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "popup/model/option_field.hpp"

using namespace popup;

namespace {

TEST(OptionField, AcceptsItsRangeWithOpenEndsRefused)
{
    const OptionField margin = OptionField::number("margin", "free border").at_least(0).below(0.4);
    EXPECT_TRUE(margin.accepts(0.0));
    EXPECT_TRUE(margin.accepts(0.39));
    EXPECT_FALSE(margin.accepts(0.4));
    EXPECT_FALSE(margin.accepts(-1e-9));
    EXPECT_FALSE(margin.accepts(std::nan("")));
    const OptionField weight = OptionField::number("w", "a weight").above(0);
    EXPECT_FALSE(weight.accepts(0.0));
    EXPECT_TRUE(weight.accepts(1e300));
    EXPECT_FALSE(weight.accepts(std::numeric_limits<double>::infinity()));
}

TEST(OptionField, StatesItsRangeAsErrorsDo)
{
    EXPECT_EQ(OptionField::count("max_mechanisms", "").at_least(1).at_most(32).range(), "1 to 32");
    EXPECT_EQ(OptionField::count("samples", "").at_least(500).at_most(2000000).range(),
              "500 to 2000000");
    EXPECT_EQ(OptionField::number("card_width", "", "mm").at_least(20).at_most(2000).range(),
              ">= 20 and <= 2000 mm");
    EXPECT_EQ(OptionField::number("min_shape", "", "a fraction of the model's diagonal")
                  .above(0)
                  .below(1)
                  .range(),
              "> 0 and < 1 (a fraction of the model's diagonal)");
    EXPECT_EQ(OptionField::number("angle", "", "°").above(0).below(90).range(), "> 0 and < 90°");
    EXPECT_EQ(OptionField::count("first_frame", "").at_least(0).range(), ">= 0");
    EXPECT_EQ(OptionField::number("h", "", "mm").range(), "any finite number");
    EXPECT_EQ(OptionField::on_off("outlines", "").range(), "on or off");
}

TEST(OptionField, CheckOptionNamesTheOwnerTheOptionTheValueAndTheRange)
{
    Diagnostics errors;
    const OptionField f = OptionField::count("search_chains", "").at_least(1).at_most(16);
    check_option(errors, "MotionOptions", f, 4);
    EXPECT_TRUE(errors.empty());
    check_option(errors, "MotionOptions", f, 0);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].code, DiagnosticCode::bad_option);
    EXPECT_EQ(errors[0].parameter.value_or(""), "search_chains");
    EXPECT_EQ(errors[0].message, "MotionOptions.search_chains = 0, must be 1 to 16");
}

} // namespace
