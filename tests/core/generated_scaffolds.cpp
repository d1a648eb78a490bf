#include "generated_scaffolds.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "popup/mechanisms/box_fold.hpp"
#include "popup/model/card.hpp"
#include "test_support.hpp"

namespace popup::fixtures {

Scaffold generated_scaffold(int patch_count)
{
    // Every mechanism adds two patches to the card's two; round up so there are at least
    // `patch_count` patches.
    const int mechanisms = std::max(0, (patch_count - 2 + 1) / 2);
    // Mechanisms of 20 mm side by side with 10 mm gaps, so they never touch one another; the
    // card grows with them.
    const double width = 20.0;
    const double gap = 10.0;
    const double card_width = gap + mechanisms * (width + gap);
    Scaffold s = make_card(card_width, 140.0);
    s.name = "generated_" + std::to_string(patch_count);
    for (int k = 0; k < mechanisms; ++k) {
        const double y0 = gap + k * (width + gap);
        if (k % 2 == 0)
            add_tent_fold(s, y0, width, 20.0, 35.0);
        else
            add_step_fold(s, y0, width, 30.0, 20.0);
    }
    Result<Scaffold> valid = validate_scaffold(std::move(s));
    if (!valid.ok) {
        std::string why;
        for (const Diagnostic& d : valid.diagnostics)
            why += "\n  " + std::string(to_string(d.code)) + ": " + d.message;
        throw std::logic_error("generated_scaffold(" + std::to_string(patch_count) +
                               ") is invalid:" + why);
    }
    return valid.value;
}

Scaffold nested_boxes(int depth)
{
    Scaffold s = popup::make_card(CardParams{}).value;
    BasePatchPair host = central_fold(s);
    for (int k = 0; k < depth; ++k) {
        BoxFoldParams box;
        box.offset = k == 0 ? 40.0 : 2.0;
        box.width = 76.0 - 4.0 * k;
        box.height = box.depth_ground = box.depth_backdrop = 10.0;
        host = add_box_fold(s, host, box, "B" + std::to_string(k)).value.offered[0];
    }
    return s;
}

Scaffold box_with_panel_pairs(int panel_pairs)
{
    Scaffold s = popup::make_card(CardParams{}).value;
    BoxFoldParams box;
    box.offset = 60.0;
    box.width = 80.0;
    box.panel_pairs = panel_pairs;
    add_box_fold(s, central_fold(s), box, "B");
    return s;
}

} // namespace popup::fixtures
