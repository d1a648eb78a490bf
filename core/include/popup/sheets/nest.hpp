#pragma once
#include <string>
#include <vector>

#include "popup/model/patch.hpp"
#include "popup/model/result.hpp"

namespace popup {

/// A paper size in mm (portrait: width ≤ height for the presets).
struct Paper {
    std::string name;
    double width = 0.0;
    double height = 0.0;
};

/// The presets A4, A3, Letter and Tabloid (case-insensitive), or "<w>x<h>" in mm (e.g.
/// "300x200"); an unknown name or a non-positive size is an error naming the allowed values.
Result<Paper> paper_by_name(const std::string& name);

/// Where the pieces may go and how far apart.
struct NestOptions {
    Paper paper{"A4", 210.0, 297.0};
    double margin = 10.0; ///< no cut closer than this to the paper's edge (mm)
    double spacing = 2.0; ///< least distance between two pieces' outlines (mm)
    bool rotate = true;   ///< allow quarter turns (0°, 90°, 180°, 270°)
};

/// One shape to place: a closed outer loop (either winding) and its holes, in its own frame.
struct NestShape {
    std::string name; ///< for error messages ("piece P3")
    Loop2 outer;
    std::vector<Loop2> holes;
};

/// Where a shape went: sheet point = rotation(rotation_deg) · shape point + translation; sheet
/// origin at the paper's lower-left corner, y up.
struct Placement {
    int sheet = 0;
    double rotation_deg = 0.0;
    Vec2 translation = Vec2::Zero();
};

struct Nesting {
    std::vector<Placement> placements; ///< one per shape, same order
    int sheet_count = 0;
};

/// True-shape nesting: each shape keeps at least `spacing` from every other shape's outline and
/// `margin` from the paper edge; shapes may nest into each other's concavities. Deterministic.
/// A shape that fits no empty sheet in any allowed rotation, or bad options, is an error that
/// names the shape (or option), its size and the printable area.
Result<Nesting> nest_shapes(const std::vector<NestShape>& shapes, const NestOptions& options);

/// The baseline: bounding boxes on shelves (rows), tallest first, each box turned so that it is
/// no taller than wide when that fits. Same options, same errors.
Result<Nesting> shelf_pack(const std::vector<NestShape>& shapes, const NestOptions& options);

} // namespace popup
