#include "place_on_sheet.hpp"

#include <cmath>

#include "sheet_labels.hpp"

namespace popup::sheets {

namespace {

// Quarter turns are exact, so placed creases stay exactly on the placed patch edges.
Mat3 quarter_turn(double degrees)
{
    const double c = std::round(std::cos(degrees * M_PI / 180.0) * 1e12) / 1e12;
    const double s = std::round(std::sin(degrees * M_PI / 180.0) * 1e12) / 1e12;
    Mat3 r;
    r << c, -s, 0, s, c, 0, 0, 0, 1;
    return r;
}

struct SheetPlacement {
    Mat3 rotation;
    Vec2 translation;
    Vec2 operator()(const Vec2& p) const
    {
        return rotation.topLeftCorner<2, 2>() * p + translation;
    }
    Loop2 operator()(const Loop2& loop) const
    {
        Loop2 out;
        for (const Vec2& p : loop)
            out.push_back((*this)(p));
        return out;
    }
    std::vector<Region> operator()(const std::vector<Region>& regions) const
    {
        std::vector<Region> out;
        for (const Region& r : regions) {
            Region placed{(*this)(r.outer), {}};
            for (const Loop2& h : r.holes)
                placed.holes.push_back((*this)(h));
            out.push_back(placed);
        }
        return out;
    }
};

} // namespace

SheetPiece place_on_sheet(const Scaffold& s, const LocalPiece& local, const Placement& at,
                          const std::string& piece_id, std::vector<Pose>& to_sheet)
{
    const SheetPlacement place{quarter_turn(at.rotation_deg), at.translation};
    SheetPiece piece;
    piece.id = piece_id;
    piece.printed_side = local.printed_back ? PrintedSide::back : PrintedSide::front;
    piece.sheet = at.sheet;
    piece.rotation = at.rotation_deg;
    const Patch& root = *s.find_patch(local.flat.patches.front());
    // Design state → the root's plane → its 2D frame (z up = printed side) → the sheet.
    Pose frame;
    frame.rotation.row(0) = root.u.transpose();
    const double turned = local.printed_back ? -1.0 : 1.0; // turned over about u
    frame.rotation.row(1) = turned * root.v.transpose();
    frame.rotation.row(2) = turned * root.normal.transpose();
    frame.translation = -(frame.rotation * root.origin);
    const Pose onto{place.rotation, Vec3(at.translation.x(), at.translation.y(), 0.0)};
    for (size_t i = 0; i < local.flat.patches.size(); ++i) {
        const int id = local.flat.patches[i];
        const Patch& patch = *s.find_patch(id);
        FlatPatch fp{id, patch.name, place(local.flat.outlines[i]), {}};
        for (const Loop2& h : local.flat.holes[i])
            fp.holes.push_back(place(h));
        const Pose& pose = to_sheet[s.patch_index(id)] =
            local.flat.unfold[i].then(frame).then(onto);
        // (u, v) -> origin + u e_u + v e_v -> the sheet plane (z = 0 there).
        fp.to_sheet.col(0) = (pose.rotation * patch.u).head<2>();
        fp.to_sheet.col(1) = (pose.rotation * patch.v).head<2>();
        fp.to_sheet.col(2) = pose.apply(patch.origin).head<2>();
        piece.patches.push_back(std::move(fp));
    }
    piece.cut = place(local.cut);
    piece.cut_nominal = place(local.cut_nominal);
    for (FoldLine f : local.folds) {
        f.from = place(f.from);
        f.to = place(f.to);
        piece.folds.push_back(f);
    }
    for (GlueTab t : local.tabs) {
        t.polygon = place(t.polygon);
        piece.tabs.push_back(t);
    }
    for (GlueArea g : local.glue) {
        g.polygon = place(g.polygon);
        piece.glue.push_back(g);
    }
    for (SheetLabel l : local.labels) {
        l.position = place(l.position);
        l.angle = upright(l.angle + at.rotation_deg);
        piece.labels.push_back(l);
    }
    return piece;
}

} // namespace popup::sheets
