// The sheet set read back from its JSON (docs/SHEET_FORMAT.md): a CuttingSheet's stored layout or
// a sheets.json, as the SheetSet the writers take. Checked as it is read, so a malformed document
// fails once, naming the key path ("sheet set: pieces[2].cut missing").
#include <climits>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "popup/io/sheet_json.hpp"

namespace popup {

namespace {

using nlohmann::json;

// Thrown inside the reader only; sheet_set_from_json turns it into a diagnostic.
struct SheetFieldError {
    std::string path;
    std::string problem;
};

// A value as the messages quote it: text in single quotes, anything else as JSON.
std::string shown(const json& value)
{
    return value.is_string() ? "'" + value.get<std::string>() + "'" : value.dump();
}

std::string shown_number(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

/// A value of the document and its key path.
class Node {
public:
    Node(const json& value, std::string path) : value_(value), path_(std::move(path)) {}

    const json& value() const { return value_; }

    [[noreturn]] void fail(const std::string& problem) const
    {
        throw SheetFieldError{path_, problem};
    }

    bool has(const char* key) const { return value_.is_object() && value_.contains(key); }

    Node operator[](const char* key) const
    {
        if (!value_.is_object())
            fail("is not an object");
        const std::string path = path_.empty() ? key : path_ + "." + key;
        const auto it = value_.find(key);
        if (it == value_.end())
            throw SheetFieldError{path, "missing"};
        return Node(*it, path);
    }

    std::vector<Node> items() const
    {
        if (!value_.is_array())
            fail("is not a list");
        std::vector<Node> out;
        for (size_t i = 0; i < value_.size(); ++i)
            out.emplace_back(value_[i], path_ + "[" + std::to_string(i) + "]");
        return out;
    }

    double number() const
    {
        if (!value_.is_number() || !std::isfinite(value_.get<double>()))
            fail("is not a number: " + shown(value_));
        return value_.get<double>();
    }

    double positive() const
    {
        const double x = number();
        if (x <= 0.0)
            fail("must be positive, not " + shown(value_));
        return x;
    }

    int integer() const
    {
        const bool fits = value_.is_number_unsigned()
                              ? value_.get<std::uint64_t>() <= std::uint64_t(INT_MAX)
                              : value_.is_number_integer() &&
                                    value_.get<std::int64_t>() >= INT_MIN &&
                                    value_.get<std::int64_t>() <= INT_MAX;
        if (!fits)
            fail("is not an integer: " + shown(value_));
        return value_.get<int>();
    }

    bool boolean() const
    {
        if (!value_.is_boolean())
            fail("is not true or false: " + shown(value_));
        return value_.get<bool>();
    }

    std::string text() const
    {
        if (!value_.is_string())
            fail("is not a string: " + shown(value_));
        return value_.get<std::string>();
    }

    /// The text, one of `choices`; its position among them.
    int choice(std::initializer_list<const char*> choices) const
    {
        const std::string t = text();
        std::string listed;
        int k = 0;
        for (const char* c : choices) {
            if (t == c)
                return k;
            listed += (k++ ? ", " : "") + std::string(c);
        }
        fail("is " + shown(value_) + ", expected one of " + listed);
    }

    Vec2 point() const
    {
        if (!value_.is_array() || value_.size() != 2)
            fail("is not a point [x, y]: " + shown(value_));
        const std::vector<Node> xy = items();
        return Vec2(xy[0].number(), xy[1].number());
    }

    Loop2 loop() const
    {
        Loop2 points;
        for (const Node& p : items())
            points.push_back(p.point());
        if (points.size() < 3)
            fail("has " + std::to_string(points.size()) + " points, a loop needs at least 3");
        return points;
    }

    std::vector<Loop2> loops() const
    {
        std::vector<Loop2> out;
        for (const Node& l : items())
            out.push_back(l.loop());
        return out;
    }

private:
    const json& value_;
    std::string path_;
};

// A field the drawings do not need, or that a later version added: `fallback` when absent.
template <class Read, class T> T optional(const Node& n, const char* key, Read read, T fallback)
{
    return n.has(key) ? read(n[key]) : fallback;
}

// Node's readers as functions, for optional().
double number_of(const Node& n)
{
    return n.number();
}
int integer_of(const Node& n)
{
    return n.integer();
}
bool boolean_of(const Node& n)
{
    return n.boolean();
}
Loop2 loop_of(const Node& n)
{
    return n.loop();
}

bool front_side(const Node& n)
{
    return n.choice({"front", "back"}) == 0;
}

/// Piece ids to their index in SheetSet::pieces: tabs, glue areas and steps name pieces by id.
class PieceIndex {
public:
    void add(const Node& id_node)
    {
        const std::string id = id_node.text();
        if (!index_.emplace(id, int(index_.size())).second)
            id_node.fail("repeats piece id " + shown(id_node.value()));
    }
    int of(const Node& id_node) const
    {
        const auto it = index_.find(id_node.text());
        if (it == index_.end())
            id_node.fail("names unknown piece " + shown(id_node.value()));
        return it->second;
    }

private:
    std::map<std::string, int> index_;
};

Eigen::Matrix<double, 2, 3> read_to_sheet(const Node& n)
{
    const std::vector<Node> rows = n.items();
    if (rows.size() != 2)
        n.fail("is not a 2 x 3 matrix: " + shown(n.value()));
    Eigen::Matrix<double, 2, 3> m;
    for (int r = 0; r < 2; ++r) {
        const std::vector<Node> values = rows[r].items();
        if (values.size() != 3)
            rows[r].fail("has " + std::to_string(values.size()) + " numbers, expected 3");
        for (int c = 0; c < 3; ++c)
            m(r, c) = values[c].number();
    }
    const double det = m.leftCols<2>().determinant();
    if (std::abs(std::abs(det) - 1.0) > 1e-6)
        n.fail("is not a rotation or reflection: determinant " + shown_number(det));
    return m;
}

FlatPatch read_flat_patch(const Node& n)
{
    FlatPatch p;
    p.id = n["id"].integer();
    p.name = n["name"].text();
    p.outer = n["outer"].loop();
    p.holes = n["holes"].loops();
    p.to_sheet = n.has("to_sheet") ? read_to_sheet(n["to_sheet"])
                                   : Eigen::Matrix<double, 2, 3>::Zero().eval();
    return p;
}

std::vector<Region> read_regions(const Node& n)
{
    std::vector<Region> out;
    for (const Node& r : n.items())
        out.push_back({r["outer"].loop(), r["holes"].loops()});
    return out;
}

FoldLine read_fold(const Node& n)
{
    FoldLine f;
    f.hinge = optional(n, "hinge", integer_of, 0);
    f.from = n["from"].point();
    f.to = n["to"].point();
    f.direction = n["direction"].choice({"mountain", "valley"}) == 0 ? FoldDirection::mountain
                                                                     : FoldDirection::valley;
    f.kind = n["kind"].choice({"fold", "tab"}) == 0 ? JointKind::fold : JointKind::tab;
    return f;
}

GlueTab read_tab(const Node& n, const PieceIndex& pieces)
{
    GlueTab t;
    t.code = n["code"].text();
    t.hinge = optional(n, "hinge", integer_of, 0);
    t.patch = optional(n, "patch", integer_of, 0);
    t.polygon = optional(n, "polygon", loop_of, Loop2{});
    t.width = optional(n, "width", number_of, 0.0);
    t.target_piece = pieces.of(n["target_piece"]);
    t.target_patch = optional(n, "target_patch", integer_of, 0);
    t.front = front_side(n["side"]);
    return t;
}

GlueArea read_glue_area(const Node& n, const PieceIndex& pieces)
{
    GlueArea g;
    g.code = n["code"].text();
    g.hinge = optional(n, "hinge", integer_of, 0);
    g.patch = optional(n, "patch", integer_of, 0);
    g.polygon = n["polygon"].loop();
    g.tab_piece = pieces.of(n["tab_piece"]);
    g.front = front_side(n["side"]);
    return g;
}

SheetLabel read_label(const Node& n)
{
    SheetLabel l;
    l.text = n["text"].text();
    const Node kind = n["kind"];
    kind.choice({"piece", "tab", "glue", "fold"});
    l.kind = kind.text();
    l.position = n["position"].point();
    l.height = n["height"].positive();
    l.angle = n["angle"].number();
    return l;
}

SheetPiece read_piece(const Node& n, const PieceIndex& pieces)
{
    SheetPiece p;
    p.id = n["id"].text();
    const bool front = optional(n, "printed_side", front_side, true);
    p.printed_side = front ? PrintedSide::front : PrintedSide::back;
    p.sheet = n["sheet"].integer();
    p.rotation = optional(n, "rotation", number_of, 0.0);
    if (n.has("patches"))
        for (const Node& fp : n["patches"].items())
            p.patches.push_back(read_flat_patch(fp));
    p.cut = read_regions(n["cut"]);
    if (n.has("cut_nominal"))
        p.cut_nominal = read_regions(n["cut_nominal"]);
    for (const Node& f : n["folds"].items())
        p.folds.push_back(read_fold(f));
    for (const Node& t : n["tabs"].items())
        p.tabs.push_back(read_tab(t, pieces));
    for (const Node& g : n["glue"].items())
        p.glue.push_back(read_glue_area(g, pieces));
    for (const Node& l : n["labels"].items())
        p.labels.push_back(read_label(l));
    return p;
}

/// The sheet count, after checking that "sheets" lists every piece once, on the sheet it says,
/// sheets in index order.
int read_sheets(const Node& n, const std::vector<SheetPiece>& pieces, const PieceIndex& index)
{
    const std::vector<Node> sheets = n.items();
    std::set<int> placed;
    for (size_t k = 0; k < sheets.size(); ++k) {
        const Node at = sheets[k]["index"];
        if (at.integer() != int(k))
            at.fail("is " + shown(at.value()) + ", expected " + std::to_string(k) +
                    " (sheets in index order)");
        for (const Node& id_node : sheets[k]["pieces"].items()) {
            const int piece = index.of(id_node);
            if (!placed.insert(piece).second)
                id_node.fail("places piece " + shown(id_node.value()) + " a second time");
            if (pieces[piece].sheet != int(k))
                throw SheetFieldError{"pieces[" + std::to_string(piece) + "].sheet",
                                      "is " + std::to_string(pieces[piece].sheet) + " but sheets[" +
                                          std::to_string(k) + "] lists " + shown(id_node.value())};
        }
    }
    if (sheets.empty())
        n.fail("is empty");
    for (size_t k = 0; k < pieces.size(); ++k)
        if (!placed.count(int(k)))
            throw SheetFieldError{"pieces[" + std::to_string(k) + "]",
                                  "('" + pieces[k].id + "') is on no sheet"};
    return int(sheets.size());
}

AssemblyStep read_step(const Node& n, size_t k, const PieceIndex& pieces)
{
    const Node number = n["step"];
    if (number.integer() != int(k + 1))
        number.fail("is " + shown(number.value()) + ", expected " + std::to_string(k + 1) +
                    " (steps in order)");
    AssemblyStep step;
    step.piece = pieces.of(n["piece"]);
    for (const Node& j : n["glue"].items()) {
        AssemblyJoin join;
        join.code = j["code"].text();
        // Older files leave it out: the piece the step glues on carries the tab.
        join.tab_piece = j.has("tab_piece") ? pieces.of(j["tab_piece"]) : step.piece;
        join.target_piece = pieces.of(j["target_piece"]);
        join.front = front_side(j["side"]);
        step.joins.push_back(join);
    }
    step.text = n["text"].text();
    return step;
}

Diagnostic read_diagnostic(const Node& n)
{
    Diagnostic d;
    d.severity = Severity(n["severity"].choice({"error", "warning", "info"}));
    const Node code = n["code"];
    const std::optional<DiagnosticCode> known = diagnostic_code_named(code.text());
    if (!known)
        code.fail("is " + shown(code.value()) + ", not a code of docs/DIAGNOSTICS.md");
    d.code = *known;
    d.message = n["message"].text();
    for (const Node& id : n["patches"].items())
        d.patches.push_back(id.integer());
    const Node parameter = n["parameter"];
    if (!parameter.value().is_null())
        d.parameter = parameter.text();
    const Node angle = n["angle_deg"];
    if (!angle.value().is_null())
        d.angle_deg = angle.number();
    return d;
}

void read_options(const Node& paper, const Node& o, SheetSet& set)
{
    SheetOptions& options = set.options;
    options.nest.paper = {paper["name"].text(), paper["width"].positive(),
                          paper["height"].positive()};
    options.nest.margin = o["margin"].number();
    options.nest.spacing = optional(o, "spacing", number_of, options.nest.spacing);
    options.nest.rotate = optional(o, "rotate", boolean_of, options.nest.rotate);
    options.kerf = o["kerf"].number();
    options.min_gap = optional(o, "min_gap", number_of, options.min_gap);
    options.tab_width = optional(o, "tab_width", number_of, options.tab_width);
    options.tab_angle = optional(o, "tab_angle", number_of, options.tab_angle);
    options.min_tab_width = optional(o, "min_tab_width", number_of, options.min_tab_width);
    options.min_feature = optional(o, "min_feature", number_of, options.min_feature);
    options.min_corner_angle = optional(o, "min_corner_angle", number_of, options.min_corner_angle);
    options.fold_hints = optional(o, "fold_hints", boolean_of, options.fold_hints);
    set.paper_thickness = o["paper_thickness"].positive();
}

RoundTrip read_round_trip(const Node& n)
{
    RoundTrip r;
    r.max_error = n["max_error"].number();
    r.tolerance = n["tolerance"].number();
    r.angles = n["angles"].integer();
    r.ok = n["ok"].boolean();
    return r;
}

SheetSet read_sheet_set(const Node& root)
{
    const Node format = root["format"];
    if (format.text() != "popup-sheets")
        format.fail("is " + shown(format.value()) + ", expected 'popup-sheets'");
    const Node version = root["version"];
    if (version.integer() != 1)
        version.fail("is " + shown(version.value()) + ", this reader knows 1");
    SheetSet set;
    const Node pieces = root["pieces"];
    PieceIndex index;
    for (const Node& p : pieces.items())
        index.add(p["id"]);
    for (const Node& p : pieces.items())
        set.pieces.push_back(read_piece(p, index));
    read_options(root["paper"], root["options"], set);
    set.card_size = optional(root, "card_size", number_of, 0.0);
    set.sheet_count = read_sheets(root["sheets"], set.pieces, index);
    set.shelf_sheet_count = optional(root, "shelf_sheet_count", integer_of, 0);
    const std::vector<Node> steps = root["assembly"].items();
    for (size_t k = 0; k < steps.size(); ++k)
        set.assembly.push_back(read_step(steps[k], k, index));
    set.cut_length = root["cut_length"].number();
    set.stack_height = root["stack_height"].number();
    if (root.has("round_trip"))
        set.round_trip = read_round_trip(root["round_trip"]);
    for (const Node& d : root["diagnostics"].items())
        set.diagnostics.push_back(read_diagnostic(d));
    return set;
}

} // namespace

Result<SheetSet> sheet_set_from_json(const std::string& text)
{
    Result<SheetSet> r;
    json document;
    try {
        document = json::parse(text);
    } catch (const json::exception& e) { // syntax errors, and numbers beyond double range
        r.fail(DiagnosticCode::bad_json, std::string("sheet set: not valid JSON: ") + e.what());
        return r;
    }
    try {
        r.value = read_sheet_set(Node(document, ""));
    } catch (const SheetFieldError& e) {
        r.fail(DiagnosticCode::bad_field,
               "sheet set: " + (e.path.empty() ? std::string("top level") : e.path) + " " +
                   e.problem,
               about_parameter(e.path));
    }
    return r;
}

} // namespace popup
