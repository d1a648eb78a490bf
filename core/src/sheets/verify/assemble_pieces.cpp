#include "assemble_pieces.hpp"

#include <cmath>
#include <deque>

#include "../../geometry/turn_about.hpp"

namespace popup::sheets {

namespace {

// Signed angle of a rotation about `axis` (unit), read from how it turns a perpendicular.
double angle_about(const Mat3& rotation, const Vec3& axis)
{
    Vec3 u = axis.cross(std::abs(axis.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).normalized();
    const Vec3 turned = rotation * u;
    return std::atan2(axis.dot(u.cross(turned)), u.dot(turned));
}

double pose_gap(const Pose& a, const Pose& b, double scale)
{
    return (a.rotation - b.rotation).norm() * scale + (a.translation - b.translation).norm();
}

// Lays the patches of `piece` joined to `start` (already placed) by its drawn folds, each turned
// about its drawn line by the design's angle (the other way where the fold is drawn turned).
void fold_from(const Verification& v, std::map<int, Pose>& from_sheet, const PieceCheck& piece,
               int start)
{
    std::deque<int> queue{start};
    while (!queue.empty()) {
        const int a = queue.front();
        queue.pop_front();
        for (const auto& [hinge_id, drawn] : piece.fold_of) {
            const Hinge& h = v.hinge(hinge_id);
            if (h.patch_a != a && h.patch_b != a)
                continue;
            const int b = h.patch_a == a ? h.patch_b : h.patch_a;
            if (from_sheet.count(b))
                continue;
            const DrawnFold& f = piece.drawn->folds[size_t(drawn)];
            const Vec3 axis = lift(f.to - f.from).normalized();
            // As designed, b turned about the drawn crease; the other way if drawn so.
            const Pose design = inverse(piece.sheet_pose.at(b)).then(piece.sheet_pose.at(a));
            double angle = angle_about(design.rotation, axis);
            if (piece.fold_turned.at(hinge_id))
                angle = -angle;
            from_sheet[b] = turn_about(lift(f.from), axis, angle).then(from_sheet.at(a));
            queue.push_back(b);
        }
    }
}

// Brings `moving` (a patch of a piece not yet placed) onto `fixed`: its crease edge laid onto
// the fixed edge, then turned about it by the design's joint angle. Of the two ways round the
// edge, the one nearer the design's relative pose is the way the tab goes on.
void join(const Verification& v, std::map<int, Pose>& from_sheet, int moving,
          const PieceCheck& moving_piece, std::array<Vec2, 2> moving_edge, int fixed,
          const PieceCheck& fixed_piece, std::array<Vec2, 2> fixed_edge)
{
    const Scaffold& s = v.design;
    // moving sheet → design state → fixed sheet.
    const Pose relative =
        inverse(moving_piece.sheet_pose.at(moving)).then(fixed_piece.sheet_pose.at(fixed));
    Pose best;
    double best_gap = 1e300;
    for (int way = 0; way < 2; ++way) {
        if (way == 1)
            std::swap(moving_edge[0], moving_edge[1]);
        const Vec2 from_dir = moving_edge[1] - moving_edge[0];
        const Vec2 onto_dir = fixed_edge[1] - fixed_edge[0];
        Pose onto = turn_about(Vec3::Zero(), Vec3::UnitZ(),
                               std::atan2(onto_dir.y(), onto_dir.x()) -
                                   std::atan2(from_dir.y(), from_dir.x()));
        onto.translation = lift(fixed_edge[0]) - onto.rotation * lift(moving_edge[0]);
        const Pose rest = inverse(onto).then(relative);
        const Vec3 axis = lift(onto_dir).normalized();
        const Pose joint =
            onto.then(turn_about(lift(fixed_edge[0]), axis, angle_about(rest.rotation, axis)));
        const double gap = pose_gap(joint, relative, s.size());
        if (gap < best_gap) {
            best_gap = gap;
            best = joint;
        }
    }
    from_sheet[moving] = best.then(from_sheet.at(fixed));
}

} // namespace

bool assemble_pieces(Verification& v, std::map<int, Pose>& from_sheet)
{
    const Scaffold& s = v.design;
    PieceCheck& card = v.pieces.front();
    from_sheet[s.ground] = inverse(card.sheet_pose.at(s.ground));
    fold_from(v, from_sheet, card, s.ground);
    for (size_t k = 1; k < v.pieces.size(); ++k) {
        const PieceCheck& piece = v.pieces[k];
        int start = -1;
        for (const DrawnTab& t : v.tabs) {
            const DrawnArea& area = v.areas.at(t.code);
            const PieceCheck& carrier = v.pieces[t.piece];
            const DrawnFold& crease = carrier.drawn->folds[size_t(t.crease)];
            const std::array<Vec2, 2> crease_edge{crease.from, crease.to};
            const std::array<Vec2, 2> glue_edge{area.glue->polygon[0], area.glue->polygon[1]};
            if (t.piece == k && from_sheet.count(area.patch)) {
                join(v, from_sheet, t.patch, piece, crease_edge, area.patch, v.pieces[area.piece],
                     glue_edge);
                start = t.patch;
            } else if (area.piece == k && t.piece != k && from_sheet.count(t.patch)) {
                join(v, from_sheet, area.patch, piece, glue_edge, t.patch, carrier, crease_edge);
                start = area.patch;
            }
            if (start >= 0)
                break;
        }
        if (start < 0) {
            v.error(DiagnosticCode::round_trip_unplaced,
                    piece.id + " has no glue tab joining it to a piece placed before it",
                    piece.local.flat.patches);
            return false;
        }
        fold_from(v, from_sheet, piece, start);
    }
    for (const PieceCheck& piece : v.pieces)
        for (int id : piece.local.flat.patches)
            if (!from_sheet.count(id)) {
                v.error(DiagnosticCode::round_trip_unplaced,
                        piece.id + ": patch " + patch_name(s, id) +
                            " is joined to the rest by no fold line",
                        {id});
                return false;
            }
    return true;
}

} // namespace popup::sheets
