#include "round_trip.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "../../geometry/polygon_2d.hpp"
#include "../../model/millimetres.hpp"

namespace popup::sheets {

namespace {

constexpr double fold_snap = 1e-5; // mm: a drawn fold this near its designed line is on it

// Largest distance from a point of one loop to the other loop (both ways), in 3D.
double loop_gap(const Loop3& a, const Loop3& b)
{
    auto one_way = [](const Loop3& from, const Loop3& onto) {
        double worst = 0.0;
        for (const Vec3& q : from) {
            double near = 1e300;
            for (size_t i = 0; i < onto.size(); ++i) {
                const Vec3 &p0 = onto[i], &p1 = onto[(i + 1) % onto.size()];
                const Vec3 d = p1 - p0;
                const double t =
                    std::clamp((q - p0).dot(d) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
                near = std::min(near, (p0 + t * d - q).norm());
            }
            worst = std::max(worst, near);
        }
        return worst;
    };
    return std::max(one_way(a, b), one_way(b, a));
}

// The largest gap yet between the re-made card and the design, and where it is.
struct WorstGap {
    RoundTrip& out;
    std::string where;
    void note(double gap, const std::string& place)
    {
        if (gap > out.max_error) {
            out.max_error = gap;
            where = place;
        }
    }
};

// Every patch of the re-made card is its drawn face, placed by `from_sheet`; each is compared
// with the design's at the design angle.
void remake_patches(const Verification& v, const std::map<int, Pose>& from_sheet, Scaffold& remade,
                    WorstGap& worst)
{
    const Scaffold& s = v.design;
    for (const PieceCheck& piece : v.pieces)
        for (const auto& [id, face] : piece.face_of) {
            const Pose& f = from_sheet.at(id);
            const Region& drawn = piece.drawn->faces[size_t(face)];
            Patch& p = remade.patches[size_t(remade.patch_index(id))];
            // A slit's slot cut across the patch's edge notches the face; the slit itself lies
            // on the paper, so the notch is left out.
            std::vector<std::array<Vec2, 2>> slits;
            for (const Slit& sl : s.slits)
                if (piece.local.has(sl.patch_cut)) { // a slot on a fold notches both sides
                    const Vec3 a = piece.sheet_pose.at(sl.patch_cut).apply(sl.from);
                    const Vec3 b = piece.sheet_pose.at(sl.patch_cut).apply(sl.to);
                    slits.push_back({Vec2(a.x(), a.y()), Vec2(b.x(), b.y())});
                }
            p.outer.clear();
            for (const Vec2& q : drawn.outer)
                if (std::none_of(slits.begin(), slits.end(), [&](const auto& sl) {
                        return distance_to_segment(q, sl[0], sl[1]) <
                               1.01 * s.paper_thickness + v.tolerance;
                    }))
                    p.outer.push_back(f.apply(lift(q)));
            // The drawn holes, less the slots cut for slits (the slit lies on the paper).
            p.holes.clear();
            for (const Loop2& h : drawn.holes) {
                bool slot = false;
                for (const Slit& sl : s.slits)
                    if (sl.patch_cut == id) {
                        const Vec3 mid = piece.sheet_pose.at(id).apply(0.5 * (sl.from + sl.to));
                        slot = slot || point_in_polygon(h, Vec2(mid.x(), mid.y()));
                    }
                if (slot)
                    continue;
                Loop3 hole;
                for (const Vec2& q : h)
                    hole.push_back(f.apply(lift(q)));
                p.holes.push_back(std::move(hole));
            }
            // Loops run counter-clockwise seen from the patch's normal side (its folds' flat
            // branch is read from it): a piece printed on its back lies the other way up.
            const Patch& designed = s.patches[size_t(s.patch_index(id))];
            Vec3 newell = Vec3::Zero();
            for (size_t i = 0; i < p.outer.size(); ++i)
                newell += p.outer[i].cross(p.outer[(i + 1) % p.outer.size()]);
            if (newell.dot(designed.normal) < 0) {
                std::reverse(p.outer.begin(), p.outer.end());
                for (Loop3& hole : p.holes)
                    std::reverse(hole.begin(), hole.end());
            }
            worst.note(loop_gap(p.outer, designed.outer),
                       piece.id + " patch " + patch_name(s, id) + " at the design angle");
        }
}

// Every hinge of the re-made card is its drawn fold line or tab crease.
void remake_hinges(const Verification& v, const std::map<int, Pose>& from_sheet, Scaffold& remade)
{
    for (Hinge& h : remade.hinges) {
        for (const PieceCheck& piece : v.pieces) {
            if (auto fold = piece.fold_of.find(h.id); fold != piece.fold_of.end()) {
                const DrawnFold& line = piece.drawn->folds[size_t(fold->second)];
                h.from = from_sheet.at(h.patch_a).apply(lift(line.from));
                h.to = from_sheet.at(h.patch_a).apply(lift(line.to));
            }
        }
        for (const DrawnTab& t : v.tabs)
            if (t.hinge == h.id) {
                const DrawnFold& line = v.pieces[t.piece].drawn->folds[size_t(t.crease)];
                h.from = from_sheet.at(t.patch).apply(lift(line.from));
                h.to = from_sheet.at(t.patch).apply(lift(line.to));
            }
    }
}

// A drawn fold within fold_snap of its designed line is put onto that line (each end to its
// foot on it; along the line the drawing's ends stay). The drawing's last digits (a DXF
// re-saved at 6 decimals moves a fold by up to 5e-7 mm) otherwise tilt the parallel folds of
// a box fold, an over-constrained linkage that then locks a few degrees after the design
// angle (docs/DESIGN.md, "popup verify and a drawing's last digits").
void snap_folds_onto_design(const Scaffold& s, Scaffold& remade)
{
    for (size_t i = 0; i < remade.hinges.size(); ++i) {
        Hinge& h = remade.hinges[i];
        const Hinge& d = s.hinges[i];
        const Vec3 u = d.to - d.from;
        if (u.norm() < 1e-12)
            continue;
        const Vec3 n = u.normalized();
        auto foot = [&](const Vec3& x) { return Vec3(d.from + (x - d.from).dot(n) * n); };
        if ((h.from - foot(h.from)).norm() <= fold_snap &&
            (h.to - foot(h.to)).norm() <= fold_snap) {
            h.from = foot(h.from);
            h.to = foot(h.to);
        }
    }
}

} // namespace

RoundTrip compare_round_trip(Verification& v, const std::map<int, Pose>& from_sheet)
{
    const Scaffold& s = v.design;
    RoundTrip out;
    out.tolerance = v.tolerance;
    // The re-made card: every patch is its drawn face, every hinge its drawn line, re-folded.
    Scaffold remade = s;
    WorstGap worst{out, {}};
    remake_patches(v, from_sheet, remade, worst);
    remake_hinges(v, from_sheet, remade);
    snap_folds_onto_design(s, remade);

    SimulationOptions simulation;
    simulation.cancel = v.options.cancel;
    const Result<FoldSweep> refolded = simulate_fold(remade, v.angles, simulation);
    if (!refolded.ok) {
        const Diagnostics& why = refolded.diagnostics;
        const std::string message =
            "the card re-made from the sheets does not simulate: " +
            (why.empty() ? std::string("no reason given") : why.front().message);
        const std::vector<int> patches = why.empty() ? std::vector<int>{} : why.front().patches;
        if (has_errors(
                v.findings)) // a consequence of what is named above, not a finding of its own
            v.findings.push_back(Diagnostic::warning(
                DiagnosticCode::round_trip_failed, message + " (it follows from the errors above)",
                about_patches(patches)));
        else
            v.error(DiagnosticCode::round_trip_failed, message, patches);
        return out;
    }
    const auto& a = v.designed.value.states;
    const auto& b = refolded.value.states;
    for (size_t k = 0; k < std::min(a.size(), b.size()); ++k) {
        if (std::abs(a[k].angle - b[k].angle) > 1e-12)
            break;
        // The fold-direction samples among them count as checks, not as angles asked for.
        const bool asked = std::any_of(v.asked.begin(), v.asked.end(),
                                       [&](double x) { return std::abs(x - a[k].angle) < 1e-9; });
        out.angles += asked;
        for (size_t i = 0; i < s.patches.size(); ++i) {
            if (remade.patches[i].outer.empty())
                continue;
            std::ostringstream where;
            where << "patch " << patch_name(s, s.patches[i].id) << " at "
                  << std::round(a[k].angle * 180.0 / M_PI * 10.0) / 10.0 << "°";
            worst.note(loop_gap(posed_outline(s.patches[i], a[k].poses[i]),
                                posed_outline(remade.patches[i], b[k].poses[i])),
                       where.str());
        }
    }
    out.ok = out.max_error <= out.tolerance && out.angles == int(v.asked.size());
    if (!out.ok) {
        std::ostringstream m;
        m << "the card folded from the sheets misses the design by " << millimetres(out.max_error)
          << " (tolerance " << millimetres(out.tolerance) << "), worst at " << worst.where
          << ", over " << out.angles << " of " << v.asked.size() << " fold angles";
        v.error(DiagnosticCode::round_trip_mismatch, m.str());
    }
    return out;
}

} // namespace popup::sheets
