#include "popup/mechanisms/step_fold.hpp"

#include <cmath>
#include <sstream>

#include "mechanism_builder.hpp"

namespace popup {

Vec2 step_nose(const StepFoldParams& p, double opening)
{
    // The parallelogram's fourth corner: a·g + b·b (docs/MATH.md).
    const Vec2 g(std::sin(opening / 2), std::cos(opening / 2));
    const Vec2 b(-g.x(), g.y());
    return p.run_ground * g + p.run_backdrop * b;
}

Result<MechanismParts> add_step_fold(Scaffold& scaffold, const BasePatchPair& host,
                                     const StepFoldParams& p, const std::string& name)
{
    Result<MechanismParts> r;
    Diagnostics& e = r.diagnostics;
    check_placement(name, host, p, e);
    check_run(e, name, "RunGround", p.run_ground, host.ground_depth, "ground");
    check_run(e, name, "RunBackdrop", p.run_backdrop, host.backdrop_depth, "backdrop");
    if (e.empty())
        check_part_sizes(
            scaffold, name,
            {{"Width", p.width}, {"RunGround", p.run_ground}, {"RunBackdrop", p.run_backdrop}}, e);
    if (!e.empty()) {
        r.ok = false;
        return r;
    }
    const Vec2 A = p.run_ground * host.ground_direction();
    const Vec2 D = p.run_backdrop * host.backdrop_direction();
    const Vec2 C = A + D; // the parallelogram's fourth corner (docs/MATH.md)
    MechanismBuilder m(scaffold, host, name);
    const double y0 = p.offset, y1 = p.offset + p.width;
    auto at = [](const Vec2& q, double y) { return Vec3(q.x(), y, q.y()); };
    const int riser =
        m.patch({at(C, y0), at(A, y0), at(A, y1), at(C, y1)}, PatchRole::front, "riser");
    const int tread =
        m.patch({at(D, y0), at(C, y0), at(C, y1), at(D, y1)}, PatchRole::top, "tread");
    // Flat on an open host the fold can pop either way: riser and tread lift toward the host's
    // printed side and the nose is a mountain (the parallelogram branch).
    m.tab(host.ground, riser, at(A, y0), at(A, y1), FoldDirection::valley);
    m.tab(host.backdrop, tread, at(D, y0), at(D, y1), FoldDirection::valley);
    m.hinge(riser, tread, at(C, y0), at(C, y1), FoldDirection::mountain);
    m.sweeps(y0, y1); // it moves only across the hinge
    return m.finish();
}

} // namespace popup
