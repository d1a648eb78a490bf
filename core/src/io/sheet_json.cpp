// The sheet set as JSON (docs/SHEET_FORMAT.md): the text of sheets.json and of a CuttingSheet's
// stored layout, and the paper, options and findings of report.json (sheet_json_reader.cpp reads
// it back).
#include <nlohmann/json.hpp>

#include "popup/io/sheet_json.hpp"
#include "popup/sheets/sheet_layout.hpp"

namespace popup {

namespace {

using nlohmann::json;

json point(const Vec2& p)
{
    return json::array({p.x(), p.y()});
}

json loop(const Loop2& l)
{
    json out = json::array();
    for (const Vec2& p : l)
        out.push_back(point(p));
    return out;
}

json loops(const std::vector<Loop2>& ls)
{
    json out = json::array();
    for (const Loop2& l : ls)
        out.push_back(loop(l));
    return out;
}

json regions(const std::vector<Region>& rs)
{
    json out = json::array();
    for (const Region& r : rs)
        out.push_back({{"outer", loop(r.outer)}, {"holes", loops(r.holes)}});
    return out;
}

const char* side(bool front)
{
    return front ? "front" : "back";
}

json piece_json(const SheetSet& set, const SheetPiece& p)
{
    json patches = json::array(), folds = json::array(), tabs = json::array(), glue = json::array(),
         labels = json::array();
    for (const FlatPatch& fp : p.patches) {
        json patch = {{"id", fp.id},
                      {"name", fp.name},
                      {"outer", loop(fp.outer)},
                      {"holes", loops(fp.holes)}};
        if (fp.has_to_sheet()) // a layout read from an older file may have none
            patch["to_sheet"] = {{fp.to_sheet(0, 0), fp.to_sheet(0, 1), fp.to_sheet(0, 2)},
                                 {fp.to_sheet(1, 0), fp.to_sheet(1, 1), fp.to_sheet(1, 2)}};
        patches.push_back(patch);
    }
    for (const FoldLine& f : p.folds)
        folds.push_back({{"hinge", f.hinge},
                         {"from", point(f.from)},
                         {"to", point(f.to)},
                         {"direction", to_string(f.direction)},
                         {"kind", to_string(f.kind)}});
    for (const GlueTab& t : p.tabs)
        tabs.push_back({{"code", t.code},
                        {"hinge", t.hinge},
                        {"patch", t.patch},
                        {"polygon", loop(t.polygon)},
                        {"width", t.width},
                        {"target_piece", set.pieces[t.target_piece].id},
                        {"target_patch", t.target_patch},
                        {"side", side(t.front)}});
    for (const GlueArea& g : p.glue)
        glue.push_back({{"code", g.code},
                        {"hinge", g.hinge},
                        {"patch", g.patch},
                        {"polygon", loop(g.polygon)},
                        {"tab_piece", set.pieces[g.tab_piece].id},
                        {"side", side(g.front)}});
    for (const SheetLabel& l : p.labels)
        labels.push_back({{"text", l.text},
                          {"kind", l.kind},
                          {"position", point(l.position)},
                          {"height", l.height},
                          {"angle", l.angle}});
    return {{"id", p.id},
            {"printed_side", to_string(p.printed_side)},
            {"sheet", p.sheet},
            {"rotation", p.rotation},
            {"patches", patches},
            {"cut", regions(p.cut)},
            {"cut_nominal", regions(p.cut_nominal)},
            {"folds", folds},
            {"tabs", tabs},
            {"glue", glue},
            {"labels", labels}};
}

} // namespace

std::string sheet_set_to_json(const SheetSet& set)
{
    const SheetOptions& o = set.options;
    json sheets = json::array();
    for (int k = 0; k < set.sheet_count; ++k) {
        json ids = json::array();
        for (const SheetPiece& p : set.pieces)
            if (p.sheet == k)
                ids.push_back(p.id);
        sheets.push_back({{"index", k}, {"pieces", ids}});
    }
    json pieces = json::array();
    for (const SheetPiece& p : set.pieces)
        pieces.push_back(piece_json(set, p));
    json assembly = json::array();
    for (size_t k = 0; k < set.assembly.size(); ++k) {
        const AssemblyStep& step = set.assembly[k];
        json joins = json::array();
        for (const AssemblyJoin& j : step.joins)
            joins.push_back({{"code", j.code},
                             {"tab_piece", set.pieces[j.tab_piece].id},
                             {"target_piece", set.pieces[j.target_piece].id},
                             {"side", side(j.front)}});
        assembly.push_back({{"step", k + 1},
                            {"piece", set.pieces[step.piece].id},
                            {"glue", joins},
                            {"text", step.text}});
    }
    json diagnostics = json::array();
    for (const Diagnostic& d : set.diagnostics)
        diagnostics.push_back({{"code", to_string(d.code)},
                               {"severity", to_string(d.severity)},
                               {"message", d.message},
                               {"patches", d.patches},
                               {"parameter", d.parameter ? json(*d.parameter) : json(nullptr)},
                               {"angle_deg", d.angle_deg ? json(*d.angle_deg) : json(nullptr)}});
    const json doc = {{"format", "popup-sheets"},
                      {"version", 1},
                      {"paper",
                       {{"name", o.nest.paper.name},
                        {"width", o.nest.paper.width},
                        {"height", o.nest.paper.height}}},
                      {"options",
                       {{"margin", o.nest.margin},
                        {"spacing", o.nest.spacing},
                        {"kerf", o.kerf},
                        {"min_gap", o.min_gap},
                        {"tab_width", o.tab_width},
                        {"tab_angle", o.tab_angle},
                        {"min_tab_width", o.min_tab_width},
                        {"min_feature", o.min_feature},
                        {"min_corner_angle", o.min_corner_angle},
                        {"paper_thickness", set.paper_thickness},
                        {"rotate", o.nest.rotate},
                        {"fold_hints", o.fold_hints}}},
                      {"card_size", set.card_size},
                      {"sheets", sheets},
                      {"shelf_sheet_count", set.shelf_sheet_count},
                      {"pieces", pieces},
                      {"assembly", assembly},
                      {"cut_length", set.cut_length},
                      {"stack_height", set.stack_height},
                      {"round_trip",
                       {{"max_error", set.round_trip.max_error},
                        {"tolerance", set.round_trip.tolerance},
                        {"angles", set.round_trip.angles},
                        {"ok", set.round_trip.ok}}},
                      {"diagnostics", diagnostics}};
    return doc.dump();
}

} // namespace popup
