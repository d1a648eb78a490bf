// Checking a scaffold read from anywhere (a design file, the workbench, a generator) before
// anything simulates it: readable coordinates, simple loops, patches, base patches, joints. The
// phases run in order; a phase that finds the coordinates unusable ends the check.
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "../geometry/loop_crossings.hpp"
#include "../geometry/polygon_2d.hpp"
#include "millimetres.hpp"
#include "popup/model/scaffold.hpp"

namespace popup {

namespace {

constexpr double kLargestCoordinate = 1e6; // mm

// Within a kilometre of the origin: any paper design is, and squares of such coordinates (areas,
// normals) stay far from overflow.
bool finite(const Vec3& x)
{
    return x.allFinite() && x.cwiseAbs().maxCoeff() <= kLargestCoordinate;
}

// The first two vertices of a loop at the same point (to a nanometre), in O(n log n).
std::optional<std::pair<size_t, size_t>> repeated_vertex(const Loop3& loop)
{
    std::map<std::array<double, 3>, size_t> seen; // rounded as doubles: no integer overflow
    for (size_t i = 0; i < loop.size(); ++i) {
        const std::array<double, 3> key{std::round(loop[i].x() * 1e6),
                                        std::round(loop[i].y() * 1e6),
                                        std::round(loop[i].z() * 1e6)};
        const auto [at, fresh] = seen.emplace(key, i);
        if (!fresh)
            return std::make_pair(at->second, i);
    }
    return std::nullopt;
}

std::vector<Loop3*> loops_of(Patch& p)
{
    std::vector<Loop3*> loops{&p.outer};
    for (Loop3& h : p.holes)
        loops.push_back(&h);
    return loops;
}

std::vector<const Loop3*> loops_of(const Patch& p)
{
    std::vector<const Loop3*> loops{&p.outer};
    for (const Loop3& h : p.holes)
        loops.push_back(&h);
    return loops;
}

// "(x, y, z)" of a point in the patch's own frame, in world coordinates.
std::string where(const Patch& p, const Vec2& q)
{
    const Vec3 x = p.origin + q.x() * p.u + q.y() * p.v;
    std::ostringstream s;
    s.precision(6);
    s << "(" << x.x() << ", " << x.y() << ", " << x.z() << ")";
    return s.str();
}

/// The outline and each hole must be simple, the holes inside the outline and apart from it:
/// otherwise the cut paper is not the patch (a crossing outline has no one inside).
template <class Report> void check_loops(const Patch& p, Report&& report)
{
    const Loop2 outer = p.outer_local();
    const std::vector<Loop2> holes = p.holes_local();
    if (const auto at = first_loop_crossing({outer})) {
        report(DiagnosticCode::self_crossing_outline, p,
               "outline crosses itself at " + where(p, *at));
        return;
    }
    for (size_t h = 0; h < holes.size(); ++h) {
        const std::string hole = "hole " + std::to_string(h + 1);
        if (const auto at = first_loop_crossing({holes[h]}))
            report(DiagnosticCode::self_crossing_outline, p,
                   hole + " crosses itself at " + where(p, *at));
        else if (const auto at = first_loop_crossing({outer, holes[h]}))
            report(DiagnosticCode::hole_crosses_outline, p,
                   hole + " crosses or touches the outline at " + where(p, *at));
        else if (!point_in_polygon(outer, holes[h].front()))
            report(DiagnosticCode::hole_outside_outline, p,
                   hole + " lies outside the outline, at " + where(p, holes[h].front()));
        else
            for (size_t g = 0; g < h; ++g) {
                const std::string other = "hole " + std::to_string(g + 1);
                if (const auto at = first_loop_crossing({holes[g], holes[h]}))
                    report(DiagnosticCode::holes_overlap, p,
                           other + " and " + hole + " cross or touch at " + where(p, *at));
                else if (point_in_polygon(holes[g], holes[h].front()) ||
                         point_in_polygon(holes[h], holes[g].front()))
                    report(DiagnosticCode::holes_overlap, p,
                           other + " and " + hole + " lie one inside the other, at " +
                               where(p, holes[h].front()));
            }
    }
}

/// Gathers a validation's findings into its result; a finding about a patch names it first.
struct Findings {
    Result<Scaffold>& result;

    void operator()(DiagnosticCode code, const Patch& p, const std::string& what)
    {
        result.fail(code, patch_subject(p) + ": " + what, about_patches({p.id}));
    }
};

// Files from other tools often close a ring by repeating its first point: drop it.
void drop_closing_repeats(Scaffold& s)
{
    for (Patch& p : s.patches) {
        for (Loop3* loop : loops_of(p))
            if (loop->size() > 3 && loop->front() == loop->back())
                loop->pop_back();
    }
}

/// Every outline has three vertices or more, every coordinate is finite and within reach.
bool coordinates_readable(const Scaffold& s, Findings& patch_error)
{
    bool coordinates_ok = true;
    for (const Patch& p : s.patches) {
        if (p.outer.size() < 3) {
            patch_error(DiagnosticCode::too_few_vertices, p,
                        "outline has " + std::to_string(p.outer.size()) +
                            " vertices, needs at least 3");
            coordinates_ok = false;
        }
        bool ok = std::all_of(p.outer.begin(), p.outer.end(), finite);
        for (const Loop3& h : p.holes)
            ok = ok && std::all_of(h.begin(), h.end(), finite);
        if (!ok) {
            patch_error(DiagnosticCode::non_finite_coordinate, p,
                        "a vertex has a NaN or infinite coordinate, or one beyond ±1e6 mm");
            coordinates_ok = false;
        }
    }
    return coordinates_ok;
}

/// No loop visits one point twice, no two loops of a patch share a point.
bool loops_visit_each_point_once(const Scaffold& s, Findings& patch_error)
{
    bool coordinates_ok = true;
    // A loop visiting one point twice has no well-defined inside (and breaks the meshing).
    for (const Patch& p : s.patches) {
        const std::vector<const Loop3*> loops = loops_of(p);
        for (size_t l = 0; l < loops.size(); ++l)
            if (const auto twice = repeated_vertex(*loops[l])) {
                const Vec3& x = (*loops[l])[twice->first];
                std::ostringstream m;
                m << (l == 0 ? "outline" : "hole " + std::to_string(l)) << " visits (" << x.x()
                  << ", " << x.y() << ", " << x.z() << ") twice, as vertices " << twice->first
                  << " and " << twice->second;
                patch_error(DiagnosticCode::repeated_vertex, p, m.str());
                coordinates_ok = false;
            }
        // Two loops sharing a point: a hole touching the outline at a vertex.
        Loop3 all;
        for (const Loop3* loop : loops)
            all.insert(all.end(), loop->begin(), loop->end());
        if (coordinates_ok && p.holes.size() > 0)
            if (const auto twice = repeated_vertex(all)) {
                const Vec3& x = all[twice->first];
                std::ostringstream m;
                m << "a hole and the outline (or two holes) share the point (" << x.x() << ", "
                  << x.y() << ", " << x.z() << ")";
                patch_error(DiagnosticCode::hole_crosses_outline, p, m.str());
                coordinates_ok = false;
            }
    }
    return coordinates_ok;
}

/// Unique ids, an area, planarity (frames derived), holes turned clockwise, simple loops.
void check_patches(Scaffold& s, double tol, Findings& patch_error)
{
    std::set<int> ids;
    for (Patch& p : s.patches) {
        if (!ids.insert(p.id).second)
            patch_error(DiagnosticCode::duplicate_patch_id, p,
                        "id " + std::to_string(p.id) + " is used twice");
        const double deviation = p.derive_frame();
        if (!std::isfinite(deviation) || p.area() <= tol * tol) {
            patch_error(DiagnosticCode::degenerate_patch, p, "outline encloses no area");
            continue;
        }
        if (deviation > tol) {
            std::ostringstream m;
            m << "not planar: a vertex lies " << deviation << " mm off its plane (allowed " << tol
              << " mm)";
            patch_error(DiagnosticCode::non_planar_patch, p, m.str());
            continue;
        }
        // Holes run clockwise seen from the normal side; files from other tools may not care.
        for (Loop3& h : p.holes) {
            double twice_area = 0.0;
            for (size_t i = 0; i < h.size(); ++i) {
                const Vec2 a = p.to_local(h[i]), b = p.to_local(h[(i + 1) % h.size()]);
                twice_area += a.x() * b.y() - b.x() * a.y();
            }
            if (twice_area > 0.0)
                std::reverse(h.begin(), h.end());
        }
        check_loops(p, patch_error);
    }
}

/// The base patches exist, differ and lie where the design angle puts them; the angle and the
/// paper thickness are in range.
void check_base_patches(const Scaffold& s, double size, double tol, Result<Scaffold>& r)
{
    auto check_base = [&](int id, const char* which) {
        if (!s.find_patch(id))
            r.fail(DiagnosticCode::missing_base_patch,
                   std::string(which) + " = " + std::to_string(id) + " names no patch",
                   about_parameter(which));
    };
    check_base(s.ground, "ground");
    check_base(s.backdrop, "backdrop");
    if (s.ground == s.backdrop && s.find_patch(s.ground))
        r.fail(DiagnosticCode::missing_base_patch, "ground and backdrop are the same patch",
               about_parameter("backdrop"));
    if (!(s.design_angle > 0.0 && s.design_angle <= M_PI))
        r.fail(DiagnosticCode::bad_design_angle,
               "design angle " + std::to_string(s.design_angle * 180.0 / M_PI) +
                   "° must be > 0° and <= 180°",
               about_parameter("design_angle"));
    // The base patches must lie where the design angle puts them: opened flat (180°) the ground
    // lies on the page plane on the x > 0 side of the central fold, the backdrop on the other.
    if (r.ok) {
        auto check_on_page = [&](int id, const Pose& to_open, double side, const char* which) {
            const Patch& p = *s.find_patch(id);
            for (const Vec3& x : p.outer) {
                const Vec3 open = to_open.apply(x);
                const bool off_page = std::abs(open.z()) > 10 * tol;
                if (!off_page && side * open.x() >= -10 * tol)
                    continue;
                std::ostringstream m;
                m << which
                  << " does not lie where design_angle_deg = " << s.design_angle * 180.0 / M_PI
                  << "° puts it: its vertex (" << x.x() << ", " << x.y() << ", " << x.z() << ") "
                  << (off_page
                          ? "would stand " + millimetres(std::abs(open.z())) +
                                " off the page opened flat"
                          : std::string("lies on the ") + (side > 0 ? "backdrop's" : "ground's") +
                                " side of the central fold")
                  << " (the ground lies on the x > 0 side)";
                r.fail(DiagnosticCode::base_patch_misplaced, patch_subject(p) + ": " + m.str(),
                       {{id}, std::string("design_angle"), std::nullopt});
                return;
            }
        };
        check_on_page(s.ground, ground_pose(s, M_PI), 1.0, "the ground");
        check_on_page(s.backdrop, backdrop_pose(s, M_PI), -1.0, "the backdrop");
    }
    if (!(s.paper_thickness >= 0.0 && s.paper_thickness < 0.05 * std::max(size, 1.0)))
        r.fail(DiagnosticCode::bad_paper_thickness,
               "paper thickness " + std::to_string(s.paper_thickness) +
                   " mm must be >= 0 and below 5% of the model size",
               about_parameter("paper_thickness"));
}

/// Each hinge: a unique id, two different patches, a segment lying on both.
void check_hinges(const Scaffold& s, double tol, Result<Scaffold>& r)
{
    std::set<int> hinge_ids;
    for (const Hinge& h : s.hinges) {
        const std::string subject = "hinge " + std::to_string(h.id) + ": ";
        const DiagnosticSubject joined = about_patches({h.patch_a, h.patch_b});
        if (!hinge_ids.insert(h.id).second)
            r.fail(DiagnosticCode::duplicate_hinge_id, subject + "id is used twice", joined);
        const Patch* a = s.find_patch(h.patch_a);
        const Patch* b = s.find_patch(h.patch_b);
        if (!a || !b || h.patch_a == h.patch_b) {
            r.fail(DiagnosticCode::bad_hinge_patches,
                   subject + "joins patches " + std::to_string(h.patch_a) + " and " +
                       std::to_string(h.patch_b) + "; both must exist and differ",
                   joined);
            continue;
        }
        if (!finite(h.from) || !finite(h.to) || (h.to - h.from).norm() <= tol) {
            r.fail(DiagnosticCode::degenerate_hinge,
                   subject + "segment has a non-finite or zero-length end", joined);
            continue;
        }
        for (const Patch* p : {a, b}) {
            for (const Vec3& x : {h.from, h.to}) {
                if (!p->contains(x, 10 * tol)) {
                    std::ostringstream m;
                    m << subject << "segment end (" << x.x() << ", " << x.y() << ", " << x.z()
                      << ") is not on " << patch_subject(*p);
                    r.fail(DiagnosticCode::hinge_off_patch, m.str(), joined);
                }
            }
        }
    }
}

/// Each slit: a unique id, cut in one patch for another whose plane passes through it.
void check_slits(const Scaffold& s, double tol, Result<Scaffold>& r)
{
    std::set<int> slit_ids;
    for (const Slit& sl : s.slits) {
        const std::string subject = "slit " + std::to_string(sl.id) + ": ";
        const DiagnosticSubject joined = about_patches({sl.patch_cut, sl.patch_through});
        if (!slit_ids.insert(sl.id).second)
            r.fail(DiagnosticCode::duplicate_slit_id, subject + "id is used twice", joined);
        const Patch* cut = s.find_patch(sl.patch_cut);
        const Patch* through = s.find_patch(sl.patch_through);
        if (!cut || !through || sl.patch_cut == sl.patch_through) {
            r.fail(DiagnosticCode::bad_slit_patches,
                   subject + "is cut in patch " + std::to_string(sl.patch_cut) + " for patch " +
                       std::to_string(sl.patch_through) + "; both must exist and differ",
                   joined);
            continue;
        }
        if (!finite(sl.from) || !finite(sl.to) || (sl.to - sl.from).norm() <= tol) {
            r.fail(DiagnosticCode::degenerate_slit,
                   subject + "segment has a non-finite or zero-length end", joined);
            continue;
        }
        for (const Vec3& x : {sl.from, sl.to}) {
            if (!cut->contains(x, 10 * tol))
                r.fail(DiagnosticCode::slit_off_patch,
                       subject + "an end is not on " + patch_subject(*cut), joined);
            else if (std::abs((x - through->origin).dot(through->normal)) > 10 * tol)
                r.fail(DiagnosticCode::slit_off_plane,
                       subject + "an end is not in the plane of " + patch_subject(*through) +
                           ", which must pass through it",
                       joined);
        }
    }
}

/// Each glue joint joins two different patches that exist.
void check_glue(const Scaffold& s, Result<Scaffold>& r)
{
    for (size_t i = 0; i < s.glue.size(); ++i) {
        const Glue& g = s.glue[i];
        if (!s.find_patch(g.patch_a) || !s.find_patch(g.patch_b) || g.patch_a == g.patch_b)
            r.fail(DiagnosticCode::bad_glue_patches,
                   "glue[" + std::to_string(i) + "]: joins patches " + std::to_string(g.patch_a) +
                       " and " + std::to_string(g.patch_b) + "; both must exist and differ",
                   about_patches({g.patch_a, g.patch_b}));
    }
}

} // namespace

Result<Scaffold> validate_scaffold(Scaffold s)
{
    Result<Scaffold> r;
    Findings patch_error{r};
    if (s.patches.empty()) {
        r.fail(DiagnosticCode::empty_scaffold,
               "the scaffold has no patches; it needs at least the two base patches");
        return r;
    }
    drop_closing_repeats(s);
    if (!coordinates_readable(s, patch_error) || !loops_visit_each_point_once(s, patch_error))
        return r;
    const double size = s.size();
    const double tol = 1e-6 * std::max(size, 1.0);
    check_patches(s, tol, patch_error);
    check_base_patches(s, size, tol, r);
    check_hinges(s, tol, r);
    check_slits(s, tol, r);
    check_glue(s, r);
    r.value = std::move(s);
    return r;
}

} // namespace popup
