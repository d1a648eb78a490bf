#include "popup/mechanisms/box_fold.hpp"

#include <cmath>
#include <sstream>

#include "mechanism_builder.hpp"
#include "parallel_box.hpp"

namespace popup {

BoxSection box_fold_section(const BoxFoldParams& p, double opening)
{
    // Sides stay parallel to C, which stays on the bisector; the end crease's foot sits where the
    // two end panels (rectangles g × c) meet (docs/MATH.md, Box fold).
    const double d = opening / 2, g = p.depth_ground;
    BoxSection s;
    s.top = {0, p.height};
    s.side_ground_top = Vec2(g * std::sin(d), g * std::cos(d) + p.height);
    s.side_backdrop_top = Vec2(-g * std::sin(d), g * std::cos(d) + p.height);
    s.crease_foot = {0, g * std::cos(d)};
    s.crease_out = g * std::cos(d);
    return s;
}

Result<MechanismParts> add_box_fold(Scaffold& scaffold, const BasePatchPair& host,
                                    const BoxFoldParams& p, const std::string& name)
{
    Result<MechanismParts> r;
    Diagnostics& e = r.diagnostics;
    check_placement(name, host, p, e);
    check_flat_host(name, host, "a box fold", e);
    check_run(e, name, "DepthGround", p.depth_ground, host.ground_depth, "ground", true);
    check_run(e, name, "DepthBackdrop", p.depth_backdrop, host.backdrop_depth, "backdrop", true);
    if (!(p.height > 0 && p.height <= 2000))
        range_error(e, name, "Height", p.height, "mm", "> 0 and <= 2000 mm");
    if (!(p.panel_pairs >= 1 && p.panel_pairs <= 10))
        range_error(e, name, "PanelPairs", p.panel_pairs, "", "1 to 10");
    if (e.empty() && (p.front || p.back) && p.depth_backdrop != p.depth_ground) {
        std::ostringstream m;
        m << "equal to DepthGround (" << p.depth_ground
          << " mm) while the box has front or back panels: otherwise C turns away from the page "
             "and the box cannot close (docs/MATH.md, Box fold)";
        range_error(e, name, "DepthBackdrop", p.depth_backdrop, "mm", m.str());
    }
    if (e.empty())
        check_part_sizes(scaffold, name,
                         {{"Width", p.width},
                          {"DepthGround", p.depth_ground},
                          {"DepthBackdrop", p.depth_backdrop},
                          {"Height", p.height}},
                         e);
    if (!e.empty()) {
        r.ok = false;
        return r;
    }
    MechanismBuilder m(scaffold, host, name);
    ParallelSection section;
    section.ground = p.depth_ground;
    section.backdrop = p.depth_backdrop;
    section.height = p.height;
    section.front = p.front;
    section.panel_pairs = p.panel_pairs;
    section.back = p.back;
    build_parallel_box(m, p.offset, p.offset + p.width, section);
    return m.finish();
}

} // namespace popup
