#include "sample_files.hpp"

#include "validity_cases.hpp"

namespace popup::fixtures {

std::vector<SampleFile> sample_files()
{
    return {
        {"resources/samples/demo_card.json", valid_multi_card()},
        {"tests/data/tent_fold.json", valid_tent_card()},
        {"tests/data/broken_tent.json", broken_tent_card()},
        {"tests/data/unstable_five_bar.json", five_bar_card()},
        {"tests/data/colliding_walls.json", colliding_walls_card()},
        {"tests/data/sticking_out_tent.json", sticking_out_tent_card()},
    };
}

} // namespace popup::fixtures
