// True-shape nesting against the shelf-packing baseline on the same 50 pop-up-like pieces (A4,
// 10 mm margins, 2 mm spacing). The "sheets" counters give the ratio nest / shelf.
#include <benchmark/benchmark.h>

#include "nest_shapes_fixture.hpp"
#include "popup/sheets/nest.hpp"

namespace {

using Packer = popup::Result<popup::Nesting> (*)(const std::vector<popup::NestShape>&,
                                                 const popup::NestOptions&);

void run_packer(benchmark::State& state, Packer pack)
{
    const std::vector<popup::NestShape> pieces =
        popup::fixtures::popup_piece_set(static_cast<int>(state.range(0)));
    const popup::NestOptions options;
    int sheets = 0;
    for (auto _ : state) {
        const popup::Result<popup::Nesting> nesting = pack(pieces, options);
        if (!nesting.ok) {
            state.SkipWithError("the synthetic pieces did not pack");
            break;
        }
        sheets = nesting.value.sheet_count;
        benchmark::DoNotOptimize(nesting.value.placements.data());
    }
    state.counters["pieces"] = static_cast<double>(pieces.size());
    state.counters["sheets"] = sheets;
}

void BM_NestShapes(benchmark::State& state)
{
    run_packer(state, popup::nest_shapes);
}

void BM_NestShelfPack(benchmark::State& state)
{
    run_packer(state, popup::shelf_pack);
}

} // namespace

BENCHMARK(BM_NestShapes)->Arg(50)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NestShelfPack)->Arg(50)->Unit(benchmark::kMillisecond);
