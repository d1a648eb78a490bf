// The cutting-sheet layout of a 53-piece card (issue 4's goal: unfold + tabs + nest + files for
// 50 pieces in at most 1 s). Counters: sheets from true-shape nesting and, as the baseline on the
// same pieces in the same run, from the bounding-box shelf packer (goal: at most 0.8 ×).
#include <benchmark/benchmark.h>

#include "popup/sheets/sheet_layout.hpp"
#include "sheet_designs.hpp"

namespace {

void run_layout(benchmark::State& state, int round_trip_angles)
{
    const popup::Scaffold scaffold = popup::fixtures::many_piece_card(4);
    popup::SheetOptions options;
    options.nest.paper = popup::paper_by_name("A3").value;
    options.round_trip_angles = round_trip_angles;
    popup::Result<popup::SheetSet> r;
    for (auto _ : state) {
        r = popup::layout_sheets(scaffold, options);
        benchmark::DoNotOptimize(r.value.cut_length);
    }
    state.counters["pieces"] = double(r.value.pieces.size());
    state.counters["sheets"] = r.value.sheet_count;
    state.counters["shelf_sheets"] = r.value.shelf_sheet_count;
    state.counters["ratio"] = double(r.value.sheet_count) / r.value.shelf_sheet_count;
}

/// The whole layout with its 13-angle round trip, as `popup sheet` runs it.
void BM_LayoutSheets(benchmark::State& state)
{
    run_layout(state, 13);
}

/// The same with the smallest round trip (design and closed states only).
void BM_LayoutSheetsTwoAngleRoundTrip(benchmark::State& state)
{
    run_layout(state, 2);
}

} // namespace

BENCHMARK(BM_LayoutSheets)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LayoutSheetsTwoAngleRoundTrip)->Unit(benchmark::kMillisecond);
