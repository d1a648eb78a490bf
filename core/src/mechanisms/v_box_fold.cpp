#include "popup/mechanisms/v_box_fold.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "mechanism_builder.hpp"
#include "popup/mechanisms/v_fold.hpp"

namespace popup {

Vec3 v_box_front_corner(const VBoxFoldParams& p, double opening)
{
    VFoldParams spine; // FL and FR are a v-fold whose spine stands vertical at 180°
    spine.offset = p.offset;
    spine.run = p.side;
    spine.hinge_angle = p.wall_angle;
    spine.spine = p.height;
    spine.spine_angle = M_PI / 2;
    return v_fold_tip(spine, M_PI, opening);
}

Result<MechanismParts> add_vertical_translation(Scaffold& scaffold, const BasePatchPair& host,
                                                VBoxFoldParams params, const std::string& name)
{
    params.back = false;
    return add_v_box_fold(scaffold, host, params, name);
}

namespace {
constexpr double min_crease = 1.0; // mm: the shortest crease of the top paper can fold along
} // namespace

Result<MechanismParts> add_v_box_fold(Scaffold& scaffold, const BasePatchPair& host,
                                      const VBoxFoldParams& p, const std::string& name)
{
    Result<MechanismParts> r;
    Diagnostics& e = r.diagnostics;
    check_flat_host(name, host, "a v-box", e);
    if (!(p.wall_angle > 0 && p.wall_angle < M_PI / 2))
        range_error(e, name, "WallAngle", p.wall_angle * 180 / M_PI, "°", "> 0° and < 90°");
    else if (2 * p.side > min_crease && !(2 * p.side * std::cos(p.wall_angle) >= min_crease)) {
        // Near 90° the top's crease (2·Side·cos WallAngle) vanishes: name WallAngle and its
        // bound, not a fold "shorter than" a tolerance.
        std::ostringstream m;
        m << "> 0° and <= " << std::acos(min_crease / (2 * p.side)) * 180 / M_PI << "° at Side "
          << p.side << " mm (the top's crease, 2·Side·cos(WallAngle), at least " << min_crease
          << " mm)";
        range_error(e, name, "WallAngle", p.wall_angle * 180 / M_PI, "°", m.str());
    }
    if (!(p.height > 0 && p.height <= 2000))
        range_error(e, name, "Height", p.height, "mm", "> 0 and <= 2000 mm");
    if (e.empty()) {
        // The walls reach Side·sin(WallAngle) into the host's depth and the v-box runs
        // 2·Side·cos(WallAngle) along its hinge: both bound Side, so a Side too long for the
        // hinge is named as Side, never as an Offset range that does not exist.
        const double reach = p.side * std::sin(p.wall_angle);
        const double length = 2 * p.side * std::cos(p.wall_angle);
        const double depth = std::min(host.ground_depth, host.backdrop_depth);
        if (!(p.side > 0 && reach < depth && length <= host.length)) {
            const double by_depth = depth / std::sin(p.wall_angle);
            const double by_length = host.length / (2 * std::cos(p.wall_angle));
            std::ostringstream m;
            m << "> 0 and " << (by_length < by_depth ? "<= " : "< ")
              << std::min(by_depth, by_length) << " mm at WallAngle " << p.wall_angle * 180 / M_PI
              << "° (Side·sin(WallAngle) < " << depth << " mm, the host's depth, and "
              << "2·Side·cos(WallAngle) <= " << host.length << " mm, the length of " << host.name
              << ")";
            range_error(e, name, "Side", p.side, "mm", m.str());
        }
    }
    const double along = p.side * std::cos(p.wall_angle);
    if (e.empty() && !(p.offset >= 0 && p.offset + 2 * along <= host.length)) {
        std::ostringstream m;
        m << ">= 0 and <= " << host.length - 2 * along << " mm (the v-box is " << 2 * along
          << " mm long on " << host.name << ")";
        range_error(e, name, "Offset", p.offset, "mm", m.str());
    }
    if (e.empty())
        check_part_sizes(scaffold, name, {{"Side", p.side}, {"Height", p.height}}, e);
    if (!e.empty()) {
        r.ok = false;
        return r;
    }
    const double across = p.side * std::sin(p.wall_angle), h = p.height, y0 = p.offset;
    const Vec3 F(0, y0, 0), Sg(across, y0 + along, 0), Bk(0, y0 + 2 * along, 0),
        Sb(-across, y0 + along, 0);
    auto up = [&](const Vec3& q) { return Vec3(q.x(), q.y(), h); };
    MechanismBuilder m(scaffold, host, name);
    // Walls wind so their normals face out of the box; the top faces up.
    const int FL = m.patch({F, Sg, up(Sg), up(F)}, PatchRole::front, "FL");
    const int FR = m.patch({Sb, F, up(F), up(Sb)}, PatchRole::front, "FR");
    const int TG = m.patch({up(F), up(Sg), up(Bk)}, PatchRole::top, "TG");
    const int TB = m.patch({up(F), up(Bk), up(Sb)}, PatchRole::top, "TB");
    m.tab(host.ground, FL, F, Sg);
    m.tab(host.backdrop, FR, F, Sb);
    m.hinge(FL, FR, F, up(F));
    m.hinge(FL, TG, up(F), up(Sg));
    m.tab(FR, TB, up(F), up(Sb));
    // Flat at the design state: the top creases down into the box (the lower of two branches
    // the simulator finds; both close to the same footprint).
    m.hinge(TG, TB, up(F), up(Bk), FoldDirection::valley);
    if (p.back) {
        // Back walls hang from the front walls and each other; the top is NOT joined to them.
        const int BL = m.patch({Sg, Bk, up(Bk), up(Sg)}, PatchRole::back, "BL");
        const int BR = m.patch({Bk, Sb, up(Sb), up(Bk)}, PatchRole::back, "BR");
        m.hinge(FL, BL, Sg, up(Sg));
        m.tab(FR, BR, Sb, up(Sb));
        m.hinge(BL, BR, Bk, up(Bk));
    }
    // The front corner leans out of the front when closing.
    double lo = y0;
    for (int k = 0; k <= 90; ++k)
        lo = std::min(lo, v_box_front_corner(p, M_PI * k / 90).y());
    m.sweeps(lo, y0 + 2 * along);
    return m.finish();
}

} // namespace popup
