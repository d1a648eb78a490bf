// The baseline packer: each shape's bounding box, grown by half the spacing on every side, on
// shelves (rows) filled first-fit, tallest boxes first.
#include <algorithm>

#include "nest_input.hpp"
#include "popup/sheets/nest.hpp"
#include "quarter_turn.hpp"

namespace popup {

namespace {

using ClipperLib::cInt;
using nest_detail::Outline;

struct Box {
    std::size_t shape = 0;
    bool turned = false;
    cInt width = 0; ///< grown by the spacing
    cInt height = 0;
};

struct Shelf {
    int sheet = 0;
    cInt bottom = 0;
    cInt height = 0;
    cInt used_width = 0;
};

/// Turned a quarter when the box is taller than wide and fits turned, or fits only turned.
Box oriented_box(std::size_t shape, const Outline& outline, const nest_detail::Bounds& room,
                 cInt spacing, bool rotate)
{
    const bool fits_upright = outline.width <= room.width() && outline.height <= room.height();
    const bool fits_turned =
        rotate && outline.height <= room.width() && outline.width <= room.height();
    const bool turned = fits_turned && (!fits_upright || outline.height > outline.width);
    const cInt width = (turned ? outline.height : outline.width) + spacing;
    const cInt height = (turned ? outline.width : outline.height) + spacing;
    return {shape, turned, width, height};
}

} // namespace

Result<Nesting> shelf_pack(const std::vector<NestShape>& shapes, const NestOptions& options)
{
    const Result<std::vector<Outline>> prepared = nest_detail::prepare_outlines(shapes, options);
    if (!prepared.ok)
        return nest_detail::failed_nesting(prepared);
    const std::vector<Outline>& outlines = prepared.value;

    // Boxes carry half the spacing on each side, so the room grows by the same on each side.
    const cInt half_spacing = nest_detail::to_units(0.5 * options.spacing);
    const cInt spacing = 2 * half_spacing;
    const nest_detail::Bounds printable = nest_detail::printable_area(options);
    const cInt room_left = printable.left - half_spacing;
    const cInt room_bottom = printable.bottom - half_spacing;
    const cInt room_width = printable.width() + spacing;
    const cInt room_height = printable.height() + spacing;

    std::vector<Box> boxes;
    for (std::size_t i = 0; i < outlines.size(); ++i)
        boxes.push_back(oriented_box(i, outlines[i], printable, spacing, options.rotate));
    std::stable_sort(boxes.begin(), boxes.end(),
                     [](const Box& a, const Box& b) { return a.height > b.height; });

    Result<Nesting> result;
    result.value.placements.resize(shapes.size());
    std::vector<Shelf> shelves;
    std::vector<cInt> sheet_top; // the top of each sheet's highest shelf
    for (const Box& box : boxes) {
        // Tallest first: every box is no taller than any shelf opened before it.
        auto shelf = std::find_if(shelves.begin(), shelves.end(), [&](const Shelf& s) {
            return s.used_width + box.width <= room_width;
        });
        if (shelf == shelves.end()) {
            auto sheet = std::find_if(sheet_top.begin(), sheet_top.end(), [&](cInt top) {
                return top + box.height <= room_bottom + room_height;
            });
            if (sheet == sheet_top.end())
                sheet = sheet_top.insert(sheet_top.end(), room_bottom);
            shelves.push_back({static_cast<int>(sheet - sheet_top.begin()), *sheet, box.height, 0});
            *sheet += box.height;
            shelf = shelves.end() - 1;
        }

        // The outline's bounding box starts half a spacing inside its box.
        const ClipperLib::IntPoint corner{room_left + shelf->used_width + half_spacing,
                                          shelf->bottom + half_spacing};
        shelf->used_width += box.width;
        const Outline& outline = outlines[box.shape];
        const int quarter_turns = box.turned ? 1 : 0;
        // A quarter turn moves the bounding box [0, w] x [0, h] to [-h, 0] x [0, w].
        const ClipperLib::IntPoint turned_low{box.turned ? -outline.height : 0, 0};
        Placement& placement = result.value.placements[box.shape];
        placement.sheet = shelf->sheet;
        placement.rotation_deg = 90.0 * quarter_turns;
        placement.translation = to_vec2({corner.X - turned_low.X, corner.Y - turned_low.Y}) -
                                nest_detail::quarter_turn(outline.shift, quarter_turns);
    }
    result.value.sheet_count = static_cast<int>(sheet_top.size());
    return result;
}

} // namespace popup
