#include "popup/sheets/sheet_layout.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <sstream>

#include "assembly_order.hpp"
#include "clipper_ops.hpp"
#include "fold_directions.hpp"
#include "glue_tabs.hpp"
#include "local_piece.hpp"
#include "piece_outline.hpp"
#include "place_on_sheet.hpp"
#include "popup/sheets/pieces.hpp"
#include "popup/sheets/verify_sheets.hpp"
#include "popup/simulation/simulate_fold.hpp"
#include "sheet_labels.hpp"
#include "stack_height.hpp"

namespace popup {

using namespace sheets;

namespace {

std::string number(double value)
{
    std::ostringstream s;
    s << value;
    return s.str();
}

void check_range(Diagnostics& errors, const std::string& name, double value, double low,
                 double high, const std::string& range, bool low_open = false)
{
    const bool below = low_open ? !(value > low) : !(value >= low);
    if (below || !(value <= high))
        errors.push_back(Diagnostic::error(DiagnosticCode::bad_option,
                                           name + " = " + number(value) + ", must be " + range,
                                           about_parameter(name)));
}

double loop_length(const Loop2& loop)
{
    double length = 0.0;
    for (size_t i = 0; i < loop.size(); ++i)
        length += (loop[(i + 1) % loop.size()] - loop[i]).norm();
    return length;
}

void classify_folds(const Scaffold& s, LocalPiece& piece, const BendSamples& bends,
                    Diagnostics& diagnostics)
{
    for (size_t i = 0; i < piece.flat.folds.size(); ++i) {
        const Hinge& h = *std::find_if(s.hinges.begin(), s.hinges.end(),
                                       [&](const Hinge& x) { return x.id == piece.flat.folds[i]; });
        bool unspecified = false;
        const FoldDirection direction =
            drawn_direction(s, bends, h, piece.printed_normal(s, h.patch_a), unspecified);
        if (unspecified)
            diagnostics.push_back(
                Diagnostic::warning(DiagnosticCode::flat_fold,
                                    "hinge " + std::to_string(h.id) +
                                        " never bends and has no direction: drawn as a valley",
                                    about_patches({h.patch_a, h.patch_b})));
        const auto& line = piece.flat.fold_lines[i];
        piece.folds.push_back({h.id, line[0], line[1], direction, JointKind::fold});
    }
}

// Paper cannot overlap itself on the sheet: such a piece must be split at a tab joint.
void report_self_overlap(const Scaffold& s, const LocalPiece& piece, Diagnostics& diagnostics)
{
    const auto& ids = piece.flat.patches;
    for (size_t i = 0; i < ids.size(); ++i)
        for (size_t j = i + 1; j < ids.size(); ++j) {
            const double area = overlap_area({piece.flat.outlines[i]}, {piece.flat.outlines[j]});
            if (area > 1e-4)
                diagnostics.push_back(Diagnostic::error(
                    DiagnosticCode::piece_overlaps_itself,
                    "laid flat, patches " + std::to_string(ids[i]) + " (" +
                        s.find_patch(ids[i])->name + ") and " + std::to_string(ids[j]) + " (" +
                        s.find_patch(ids[j])->name + ") overlap by " + number(area) +
                        " mm²: make one of their folds a tab joint",
                    about_patches({ids[i], ids[j]})));
        }
}

std::string assembly_text(const SheetSet& set, const SheetPiece& piece,
                          const std::vector<AssemblyJoin>& joins)
{
    std::ostringstream t;
    t << "Glue " << piece.id << ":";
    for (size_t j = 0; j < joins.size(); ++j)
        t << (j ? ";" : "") << " tab " << joins[j].code << " of "
          << set.pieces[joins[j].tab_piece].id << " onto area " << joins[j].code << " on the "
          << (joins[j].front ? "front" : "back") << " of " << set.pieces[joins[j].target_piece].id;
    t << ".";
    return t.str();
}

// Pieces in assembly order, each laid flat in its own frame; `position` maps a patch id to its
// piece. False, with `r` failed, when a printed side names no piece or a piece cannot be laid
// flat.
bool lay_pieces_flat(const Scaffold& s, const SheetOptions& options, Result<SheetSet>& r,
                     std::vector<LocalPiece>& pieces, std::map<int, int>& position)
{
    const SheetSet& set = r.value;
    auto& notes = r.value.diagnostics;
    const std::vector<std::vector<int>> groups = cut_pieces(s);
    const std::vector<int> order = assembly_order(s, groups, notes);
    for (const auto& [id, side] : options.printed_sides) {
        const bool known = id.size() > 1 && id[0] == 'P' &&
                           id.find_first_not_of("0123456789", 1) == std::string::npos &&
                           std::stoul(id.substr(1)) >= 1 &&
                           std::stoul(id.substr(1)) <= order.size();
        if (!known) {
            r.fail(DiagnosticCode::bad_option,
                   "printed side of " + id + ": there is no such piece; the pieces are P1 to P" +
                       std::to_string(order.size()),
                   about_parameter("printed_sides"));
            return false;
        }
    }
    for (int g : order) {
        stop_if_cancelled(options.cancel, "the sheet layout");
        const auto side = options.printed_sides.find("P" + std::to_string(pieces.size() + 1));
        const bool back = side != options.printed_sides.end() && side->second == PrintedSide::back;
        Result<LocalPiece> flat = lay_flat(s, groups[g], 1e-6 * std::max(set.card_size, 1.0), back);
        if (!flat.ok) {
            r.fail_with(flat.diagnostics);
            return false;
        }
        report_self_overlap(s, flat.value, notes);
        for (int id : groups[g])
            position[id] = int(pieces.size());
        pieces.push_back(std::move(flat.value));
    }
    return true;
}

// One sweep of the design serves the fold directions, the round trip and the stack height.
Result<FoldSweep> sweep_design(const Scaffold& s, const SheetOptions& options, Diagnostics& notes)
{
    const std::vector<double> angles = sweep_angles(s, options.round_trip_angles);
    SimulationOptions simulation;
    simulation.cancel = options.cancel;
    Result<FoldSweep> designed = simulate_fold(s, angles, simulation);
    // A card whose fold never completes cannot be assembled into one that closes: an error here,
    // where the simulator alone only warns.
    for (const Diagnostic& d : designed.diagnostics)
        if (d.code == DiagnosticCode::motion_locked)
            notes.push_back(Diagnostic::error(d.code, "the fold never completes: " + d.message,
                                              {d.patches, d.parameter, d.angle_deg}));
    return designed;
}

// Patches of two pieces glued face to face get no tab.
void report_glue_without_tab(const Scaffold& s, const std::map<int, int>& position,
                             Diagnostics& notes)
{
    for (const Glue& g : s.glue)
        if (position.at(g.patch_a) != position.at(g.patch_b))
            notes.push_back(Diagnostic::warning(
                DiagnosticCode::glue_without_tab,
                "patches " + std::to_string(g.patch_a) + " and " + std::to_string(g.patch_b) +
                    " are glued face to face: no tab is drawn for them",
                about_patches({g.patch_a, g.patch_b})));
}

// Each piece's slots, cut outline (checked for the kerf and die cutting) and labels; its largest
// cut region is the shape the nesting places.
std::vector<NestShape> cut_and_label(const Scaffold& s, std::vector<LocalPiece>& pieces,
                                     const SheetOptions& options, Diagnostics& notes)
{
    std::vector<NestShape> shapes;
    for (size_t k = 0; k < pieces.size(); ++k) {
        LocalPiece& piece = pieces[k];
        const std::string id = "P" + std::to_string(k + 1);
        add_slit_slots(s, piece);
        cut_outline(piece, options.kerf);
        if (piece.cut_nominal.size() > 1)
            notes.push_back(Diagnostic::error(
                DiagnosticCode::piece_falls_apart,
                id + " falls apart into " + std::to_string(piece.cut_nominal.size()) +
                    " parts when cut: a slit or hole crosses it from edge to edge",
                about_patches(piece.flat.patches)));
        check_openings_survive_kerf(piece, id, options.kerf, notes);
        check_die_cutting(piece, id, options, notes);
        add_labels(piece, id, options.fold_hints);
        const Region* largest = &piece.cut.front();
        for (const Region& region : piece.cut)
            if (std::abs(loop_area(region.outer)) > std::abs(loop_area(largest->outer)))
                largest = &region;
        shapes.push_back({"piece " + id, largest->outer, largest->holes});
    }
    return shapes;
}

// Every piece after the card is glued on in turn: its joins with the pieces before it.
void add_assembly_steps(SheetSet& set)
{
    for (size_t k = 1; k < set.pieces.size(); ++k) {
        AssemblyStep step{int(k), {}, {}};
        for (const GlueTab& t : set.pieces[k].tabs)
            if (size_t(t.target_piece) < k)
                step.joins.push_back({t.code, int(k), t.target_piece, t.front});
        for (const GlueArea& g : set.pieces[k].glue)
            if (size_t(g.tab_piece) < k)
                step.joins.push_back({g.code, g.tab_piece, int(k), g.front});
        step.text = assembly_text(set, set.pieces[k], step.joins);
        set.assembly.push_back(std::move(step));
    }
}

// The round trip reads the sheets as a cutting file holds them, the way `popup verify` does.
void check_round_trip(const Scaffold& s, const SheetOptions& options, SheetSet& set)
{
    auto& notes = set.diagnostics;
    VerifyOptions check;
    check.printed_sides = options.printed_sides;
    check.angles = options.round_trip_angles;
    check.cancel = options.cancel;
    Result<RoundTrip> trip = verify_sheets(s, draw_sheets(set), check);
    set.round_trip = trip.value;
    set.round_trip.ok = trip.ok && trip.value.ok;
    for (const Diagnostic& d : trip.diagnostics)
        if (d.severity == Severity::error)
            notes.push_back(Diagnostic::error(d.code, "round trip: " + d.message,
                                              {d.patches, d.parameter, d.angle_deg}));
}

} // namespace

const char* to_string(PrintedSide side)
{
    return side == PrintedSide::back ? "back" : "front";
}

Diagnostics check_sheet_options(const SheetOptions& o)
{
    Diagnostics e;
    // A range that depends on another option is stated with that option's value only when the
    // value is itself in range: "at most tab_width = -inf mm" names a range that does not exist.
    check_range(e, "kerf", o.kerf, 0.0, 2.0, "0 to 2 mm");
    check_range(e, "min_gap", o.min_gap, 0.0, 50.0, "0 to 50 mm");
    if (e.empty())
        check_range(e, "spacing", o.nest.spacing, o.kerf + o.min_gap, 100.0,
                    "at least kerf + min_gap = " + number(o.kerf + o.min_gap) +
                        " mm, at most 100 mm");
    else
        check_range(e, "spacing", o.nest.spacing, 0.0, 100.0,
                    "at least kerf + min_gap, at most 100 mm");
    check_range(e, "margin", o.nest.margin, 0.0, 100.0, "0 to 100 mm");
    check_range(e, "tab_width", o.tab_width, 0.0, 50.0, "more than 0, at most 50 mm", true);
    check_range(e, "tab_angle", o.tab_angle, 0.0, 90.0, "more than 0, at most 90°", true);
    if (o.tab_width > 0 && o.tab_width <= 50.0)
        check_range(e, "min_tab_width", o.min_tab_width, 0.0, o.tab_width,
                    "more than 0, at most tab_width = " + number(o.tab_width) + " mm", true);
    else
        check_range(e, "min_tab_width", o.min_tab_width, 0.0, 50.0,
                    "more than 0, at most tab_width", true);
    check_range(e, "min_feature", o.min_feature, 0.0, 50.0, "0 to 50 mm");
    check_range(e, "min_corner_angle", o.min_corner_angle, 0.0, 90.0, "0 to 90°");
    check_range(e, "round_trip_angles", o.round_trip_angles, 2, 361, "2 to 361");
    return e;
}

Result<SheetSet> layout_sheets(const Scaffold& input, const SheetOptions& options)
{
    Result<SheetSet> r;
    r.diagnostics = check_sheet_options(options);
    if (!r.diagnostics.empty()) {
        r.ok = false;
        return r;
    }
    Result<Scaffold> checked = validate_scaffold(input);
    if (!checked.ok) {
        r.fail_with(checked.diagnostics);
        return r;
    }
    const Scaffold& s = checked.value;
    SheetSet& set = r.value;
    set.options = options;
    set.card_size = s.size();
    set.paper_thickness = s.paper_thickness;
    auto& notes = set.diagnostics;

    std::vector<LocalPiece> pieces;
    std::map<int, int> position;
    if (!lay_pieces_flat(s, options, r, pieces, position))
        return r;
    const Result<FoldSweep> designed = sweep_design(s, options, notes);
    const BendSamples bends = sample_bends(s, designed.value.states);
    for (LocalPiece& piece : pieces)
        classify_folds(s, piece, bends, notes);
    add_glue_tabs(s, pieces, position, bends, options, notes);
    report_glue_without_tab(s, position, notes);
    const std::vector<NestShape> shapes = cut_and_label(s, pieces, options, notes);

    stop_if_cancelled(options.cancel, "the sheet layout");
    Result<Nesting> nesting = nest_shapes(shapes, options.nest);
    if (!nesting.ok) {
        r.fail_with(nesting.diagnostics);
        return r;
    }
    set.sheet_count = nesting.value.sheet_count;
    const Result<Nesting> shelves = shelf_pack(shapes, options.nest);
    set.shelf_sheet_count = shelves.ok ? shelves.value.sheet_count : 0;
    std::vector<Pose> to_sheet(s.patches.size());
    for (size_t k = 0; k < pieces.size(); ++k) {
        SheetPiece piece = place_on_sheet(s, pieces[k], nesting.value.placements[k],
                                          "P" + std::to_string(k + 1), to_sheet);
        for (const Region& region : piece.cut) {
            set.cut_length += loop_length(region.outer);
            for (const Loop2& h : region.holes)
                set.cut_length += loop_length(h);
        }
        set.pieces.push_back(std::move(piece));
    }
    add_assembly_steps(set);
    check_round_trip(s, options, set);
    const auto& states = designed.value.states;
    if (designed.ok && !states.empty() && states.back().angle == 0.0)
        set.stack_height = stack_height(s, set, to_sheet, states.back().poses);
    return r;
}

} // namespace popup
