#include "popup/model/profile.hpp"

#include <cmath>
#include <sstream>

#include "../geometry/loop_crossings.hpp"
#include "../geometry/polygon_2d.hpp"

namespace popup {

namespace {

std::string patch_title(const Patch& p)
{
    return p.name.empty() ? "patch " + std::to_string(p.id) : p.name;
}

double loop_signed_area(const Loop2& loop)
{
    double twice = 0.0;
    for (size_t i = 0, n = loop.size(); i < n; ++i)
        twice += loop[i].x() * loop[(i + 1) % n].y() - loop[(i + 1) % n].x() * loop[i].y();
    return 0.5 * twice;
}

// Sketch wires repeat points (an arc's end is the next line's start, the last point closes the
// loop); they are not errors.
Loop2 without_repeats(const Loop2& loop)
{
    Loop2 out;
    for (const Vec2& p : loop)
        if (out.empty() || (p - out.back()).norm() > 1e-9)
            out.push_back(p);
    while (out.size() > 1 && (out.front() - out.back()).norm() <= 1e-9)
        out.pop_back();
    return out;
}

} // namespace

Result<ProfileFrame> profile_frame(const Scaffold& scaffold, int patch_id)
{
    Result<ProfileFrame> r;
    const Patch* patch = scaffold.find_patch(patch_id);
    if (!patch) {
        r.fail(DiagnosticCode::unknown_patch,
               "profile: the design has no patch " + std::to_string(patch_id));
        return r;
    }
    const Hinge* base = nullptr;
    for (const Hinge& h : scaffold.hinges) {
        const int other = h.patch_a == patch_id   ? h.patch_b
                          : h.patch_b == patch_id ? h.patch_a
                                                  : -1;
        if (other < 0)
            continue;
        if (!base)
            base = &h; // fallback: the card's own pages have no older neighbour
        if (other < patch_id) {
            base = &h;
            break;
        }
    }
    if (!base) {
        r.fail(DiagnosticCode::bad_profile,
               patch_title(*patch) + " has no fold to measure a profile from",
               about_patches({patch_id}));
        return r;
    }
    Patch p = *patch;
    p.derive_frame();
    ProfileFrame& f = r.value;
    f.patch = patch_id;
    f.hinge = base->id;
    f.normal = p.normal;
    f.origin = 0.5 * (base->from + base->to);
    f.u = (base->to - base->from).normalized();
    f.v = f.normal.cross(f.u);
    // The patch on v >= 0: turn u round when it lies on the other side.
    double side = 0.0;
    for (const Vec3& x : p.outer)
        side += (x - f.origin).dot(f.v);
    if (side < 0) {
        f.u = -f.u;
        f.v = -f.v;
    }
    return r;
}

Result<Profile> checked_profile(const Profile& profile)
{
    Result<Profile> r;
    r.value.name = profile.name;
    const std::string& name = profile.name;
    std::vector<Loop2> loops{profile.outer};
    loops.insert(loops.end(), profile.holes.begin(), profile.holes.end());
    auto loop_title = [&](size_t k) {
        return k == 0 ? name + ": the outer loop" : name + ": hole " + std::to_string(k);
    };
    for (size_t k = 0; k < loops.size(); ++k) {
        const Loop2& loop = loops[k];
        for (size_t i = 0; i < loop.size(); ++i)
            if (!loop[i].allFinite() || loop[i].cwiseAbs().maxCoeff() > 1e6) {
                std::ostringstream m;
                m << loop_title(k) << " has point " << i << " at (" << loop[i].x() << ", "
                  << loop[i].y() << "): coordinates must be finite and within ±1e6 mm";
                r.fail(DiagnosticCode::bad_profile, m.str());
                return r;
            }
        loops[k] = without_repeats(loop);
    }
    for (size_t k = 0; k < loops.size(); ++k) {
        const Loop2& loop = loops[k];
        if (loop.size() < 3) {
            r.fail(DiagnosticCode::bad_profile, loop_title(k) + " has " +
                                                    std::to_string(loop.size()) +
                                                    " distinct points, needs 3 or more");
            return r;
        }
        if (const auto at = first_loop_crossing({loop})) {
            std::ostringstream m;
            m << loop_title(k) << " crosses itself at (" << at->x() << ", " << at->y() << ")";
            r.fail(DiagnosticCode::bad_profile, m.str());
            return r;
        }
        const double area = std::abs(loop_signed_area(loop));
        if (!(area > 1e-6)) {
            std::ostringstream m;
            m << loop_title(k) << " encloses " << area << " mm², must enclose more than 1e-6 mm²";
            r.fail(DiagnosticCode::bad_profile, m.str());
            return r;
        }
    }
    for (size_t k = 1; k < loops.size(); ++k) {
        std::optional<Vec2> at = first_loop_crossing({loops[0], loops[k]});
        for (size_t j = 1; j < k && !at; ++j)
            at = first_loop_crossing({loops[j], loops[k]});
        if (at) {
            std::ostringstream m;
            m << loop_title(k) << " crosses or touches another loop at (" << at->x() << ", "
              << at->y() << ")";
            r.fail(DiagnosticCode::bad_profile, m.str());
            return r;
        }
        if (!point_in_polygon(loops[0], loops[k].front())) {
            r.fail(DiagnosticCode::bad_profile, loop_title(k) + " lies outside the outer loop");
            return r;
        }
    }
    r.value.outer = loops[0];
    r.value.holes.assign(loops.begin() + 1, loops.end());
    return r;
}

} // namespace popup
