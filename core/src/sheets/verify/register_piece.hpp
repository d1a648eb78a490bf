#pragma once
// Where a design's unfolded piece lies on a drawing: found from the drawing's own outline and
// fold lines, never from the transforms that wrote it.
#include <array>
#include <vector>

#include "drawn_piece.hpp"

namespace popup::sheets {

/// A rigid motion of the plane, no mirror: q = rotation p + translation.
struct Motion2 {
    Eigen::Matrix2d rotation = Eigen::Matrix2d::Identity();
    Vec2 translation = Vec2::Zero();
    Vec2 operator()(const Vec2& p) const { return rotation * p + translation; }
};

struct Registration {
    Motion2 motion;                    ///< design flat frame → drawing
    double outline_error = 0.0;        ///< farthest design outline corner from the drawn cut (mm)
    Vec2 outline_worst = Vec2::Zero(); ///< that corner, on the drawing
};

/// Lays the design piece (its patches' outlines, its outline regions, fold lines and the lines of
/// its joints with other pieces, in its flat frame, already turned over when printed on its back)
/// onto the drawn piece: every pairing of an edge of a large drawn face with an edge of about its
/// length of a design patch of about its area proposes a motion, each is refined by least squares
/// on nearest points, and the one whose outline and lines fit best wins, with every other that fits
/// within `tie` mm as well (a symmetric piece: its codes decide). Empty when no edge pairs up.
std::vector<Registration> register_piece(const std::vector<Loop2>& patch_outlines,
                                         const std::vector<Region>& design_outline,
                                         const std::vector<std::array<Vec2, 2>>& design_folds,
                                         const std::vector<std::array<Vec2, 2>>& design_joints,
                                         const DrawnPiece& drawn, double tie);

/// The larger of the distances from each end of `line` to the segment `onto`.
double segment_gap(const std::array<Vec2, 2>& line, const Vec2& from, const Vec2& to);

} // namespace popup::sheets
