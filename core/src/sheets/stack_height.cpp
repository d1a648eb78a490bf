#include "stack_height.hpp"

#include "../geometry/polygon_2d.hpp"

namespace popup::sheets {

namespace {

constexpr int grid = 80;

} // namespace

double stack_height(const Scaffold& s, const SheetSet& sheets, const std::vector<Pose>& to_sheet,
                    const std::vector<Pose>& poses)
{
    const int ground = s.patch_index(s.ground);
    const Patch& g = s.patches[ground];
    const Pose& gp = poses[ground];
    const Vec3 origin = gp.apply(g.origin), u = gp.rotation * g.u, v = gp.rotation * g.v;
    auto flat = [&](const Vec3& x) { return Vec2((x - origin).dot(u), (x - origin).dot(v)); };

    std::vector<Loop2> layers;
    for (size_t i = 0; i < s.patches.size(); ++i) {
        Loop2 loop;
        for (const Vec3& x : s.patches[i].outer)
            loop.push_back(flat(poses[i].apply(x)));
        layers.push_back(loop);
    }
    for (const SheetPiece& piece : sheets.pieces)
        for (const GlueTab& t : piece.tabs) {
            // The tab lies on its glue area: that area, carried with the target patch.
            const int target = s.patch_index(t.target_patch);
            const Pose back = inverse(to_sheet[target]);
            for (const GlueArea& area : sheets.pieces[t.target_piece].glue)
                if (area.code == t.code) {
                    Loop2 loop;
                    for (const Vec2& p : area.polygon)
                        loop.push_back(flat(poses[target].apply(back.apply({p.x(), p.y(), 0.0}))));
                    layers.push_back(loop);
                }
        }
    Eigen::AlignedBox2d box;
    for (const Loop2& loop : layers)
        for (const Vec2& p : loop)
            box.extend(p);
    int most = 0;
    for (int i = 0; i <= grid; ++i)
        for (int j = 0; j <= grid; ++j) {
            // Cell centres, nudged off the edges where layers merely touch.
            const Vec2 q = box.min() + Vec2(box.sizes().x() * (i + 0.5) / (grid + 1),
                                            box.sizes().y() * (j + 0.5) / (grid + 1));
            int count = 0;
            for (const Loop2& loop : layers)
                count += point_in_polygon(loop, q) ? 1 : 0;
            most = std::max(most, count);
        }
    return most * s.paper_thickness;
}

} // namespace popup::sheets
