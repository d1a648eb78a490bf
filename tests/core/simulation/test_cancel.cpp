#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "popup/mechanisms/box_fold.hpp"
#include "popup/model/cancel_flag.hpp"
#include "popup/model/card.hpp"
#include "popup/sheets/sheet_layout.hpp"
#include "popup/simulation/check_validity.hpp"
#include "test_support.hpp"

namespace popup {
namespace {

TEST(Cancel, ASetFlagStopsTheCheckTheSweepAndTheLayoutAtTheirFirstCheckpoint)
{
    const Scaffold s = fixtures::generator_card(200);
    CancelFlag flag;
    flag.cancel();
    ValidityOptions check;
    check.cancel = &flag;
    EXPECT_THROW(check_validity(s, check), Cancelled);
    SimulationOptions sim;
    sim.cancel = &flag;
    EXPECT_THROW(simulate_fold(s, {M_PI / 2}, sim), Cancelled);
    SheetOptions sheets;
    sheets.nest.paper = {"A2", 420.0, 594.0};
    sheets.cancel = &flag;
    EXPECT_THROW(layout_sheets(s, sheets), Cancelled);
    // Without a flag, or with one never set, the same calls run to the end.
    CancelFlag idle;
    check.cancel = &idle;
    EXPECT_TRUE(check_validity(s, check).valid());
}

TEST(Cancel, AFlagSetFromAnotherThreadStopsACheckUnderWay)
{
    // A box with 10 panel pairs checked at 5000 samples runs for seconds (the benchmark
    // BM_CheckValidityBoxPanelPairs/10 takes about 0.1 s at 181); the flag is set 20 ms in.
    Scaffold s = fixtures::generator_card(200);
    BoxFoldParams box;
    box.offset = 40;
    box.width = 60;
    box.panel_pairs = 10;
    ASSERT_TRUE(add_box_fold(s, central_fold(s), box, "Box").ok);
    CancelFlag flag;
    ValidityOptions check;
    check.samples = 5000;
    check.cancel = &flag;
    std::thread canceller([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        flag.cancel();
    });
    bool cancelled = false;
    try {
        check_validity(s, check);
    } catch (const Cancelled& e) {
        cancelled = true;
        EXPECT_NE(std::string(e.what()).find("cancelled"), std::string::npos);
    }
    canceller.join();
    EXPECT_TRUE(cancelled);
}

} // namespace
} // namespace popup
