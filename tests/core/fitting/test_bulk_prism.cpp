#include <gtest/gtest.h>

#include "fitting/card_hinge.hpp"
#include "fitting/synthetic_models.hpp"
#include "popup/fitting/bulk_prism.hpp"

using namespace popup;
using namespace popup::testing;

/// The samples of a box standing on the card, centred on its fold, all lie on that box: its
/// bulk is the box itself (every face holds more samples than one quantile step, so the
/// quantiles the descent tries include each face exactly).
TEST(BulkBox, RecoversABoxStandingOnTheFold)
{
    // Card frame: y along the fold (a), x across (s), z up (t).
    const ModelMesh box = box_mesh({-15, 50, 0}, {15, 110, 25});
    const SurfaceSamples samples = sample_surface(box, 6000, 1);
    const BulkBox bulk = bulk_box(samples, card_hinge(), 11.1);
    EXPECT_NEAR(bulk.prism.a0, 50, 1e-9);
    EXPECT_NEAR(bulk.prism.a1, 110, 1e-9);
    EXPECT_NEAR(bulk.prism.s1, 15, 1e-9);
    EXPECT_NEAR(bulk.prism.s0, -15, 1e-9);
    EXPECT_NEAR(bulk.prism.height, 25, 1e-9);
    EXPECT_NEAR(bulk.mean_distance, 0, 1e-9);
    // The page alone: the mean height of the box's surface, area-weighted by hand: top 1800 mm²
    // at 25, four walls (2·60·25 + 2·30·25 = 4500 mm²) at 12.5 on average, bottom at 0.
    EXPECT_NEAR(bulk.page_distance, (1800 * 25 + 4500 * 12.5) / 8100.0, 0.5);
}

/// A slab thinner than the narrowest glue tab's crease gets a box of that height, no lower: the
/// mechanism could not be glued otherwise.
TEST(BulkBox, KeepsEveryDimensionAtLeastMinPart)
{
    const ModelMesh slab = box_mesh({-30, 60, 0}, {30, 140, 2});
    const BulkBox bulk = bulk_box(sample_surface(slab, 4000, 1), card_hinge(), 11.1);
    EXPECT_GE(bulk.prism.height, 11.1 - 1e-12);
    EXPECT_GE(bulk.prism.s1, 11.1 - 1e-12);
    EXPECT_GE(bulk.prism.a1 - bulk.prism.a0, 11.1 - 1e-12);
    EXPECT_GE(bulk.prism.a0, 0.0);
    EXPECT_LE(bulk.prism.a1, 210.0);
    // It cannot stand up from the page better than the page itself (fit_design then keeps no
    // bulk box): the samples lie at most 2 mm from the page.
    EXPECT_LE(bulk.page_distance, 2.0);
    EXPECT_LE(bulk.mean_distance, bulk.page_distance + 1e-12);
}
