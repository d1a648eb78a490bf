#include "sample_files.hpp"

#include <algorithm>

#include "sheet_designs.hpp"
#include "validity_cases.hpp"

namespace popup::fixtures {

std::vector<SampleFile> sample_files()
{
    std::vector<SampleFile> files{
        {"resources/samples/demo_card.json", valid_multi_card()},
        {"tests/data/tent_fold.json", valid_tent_card()},
        {"tests/data/broken_tent.json", broken_tent_card()},
        {"tests/data/unstable_five_bar.json", five_bar_card()},
        {"tests/data/colliding_walls.json", colliding_walls_card()},
        {"tests/data/sticking_out_tent.json", sticking_out_tent_card()},
        {"tests/data/mechanisms/demo_card.json", demo_card()},
        {"tests/data/many_pieces.json", many_piece_card(4)},
    };
    // One card per mechanism type, made by the generators (tab joints where sheets meet).
    for (const NamedDesign& d : single_mechanism_cards()) {
        std::string file = d.name;
        std::replace(file.begin(), file.end(), ' ', '_');
        std::replace(file.begin(), file.end(), '-', '_');
        files.push_back({"tests/data/mechanisms/" + file + ".json", d.scaffold});
    }
    return files;
}

} // namespace popup::fixtures
