#include "popup/io/design_file.hpp"
#include "popup/refers_into_argument.hpp"

#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace popup {

using nlohmann::json;

namespace {

constexpr const char* kFormatName = "popup-design";
constexpr size_t kMaxDesignFileBytes = size_t(256) << 20; // 256 MiB: far beyond any real design

// The parser quotes the bytes it stopped at; a UTF-16 or binary file must not turn the message
// itself into invalid UTF-8 (Python could not even show it).
std::string printable_ascii(const std::string& text)
{
    std::string out;
    for (unsigned char c : text) {
        if (c >= 0x20 && c < 0x7f) {
            out += char(c);
        } else {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
            out += escaped;
        }
    }
    return out;
}

// Thrown inside the reader only; turned into a diagnostic naming the field.
struct FieldError {
    std::string field;
    std::string message;
};

POPUP_REFERS_INTO_ARGUMENT const json& member(const json& object, const std::string& key,
                                              const std::string& path)
{
    if (!object.is_object())
        throw FieldError{path, "must be an object"};
    auto it = object.find(key);
    if (it == object.end())
        throw FieldError{path + "." + key, "is missing"};
    return *it;
}

double read_number(const json& value, const std::string& path)
{
    if (!value.is_number())
        throw FieldError{path, "must be a number, got " + std::string(value.type_name())};
    const double x = value.get<double>();
    if (!std::isfinite(x))
        throw FieldError{path, "must be finite"};
    return x;
}

int read_int(const json& value, const std::string& path)
{
    if (!value.is_number_integer())
        throw FieldError{path, "must be an integer, got " + std::string(value.type_name())};
    // Ids are 32-bit: a larger one must not wrap onto another patch (2^32 is not patch 0).
    const bool in_range =
        value.is_number_unsigned()
            ? value.get<std::uint64_t>() <= std::uint64_t(INT_MAX)
            : value.get<std::int64_t>() >= INT_MIN && value.get<std::int64_t>() <= INT_MAX;
    if (!in_range)
        throw FieldError{path, "is " + value.dump() + ", out of range: must be between " +
                                   std::to_string(INT_MIN) + " and " + std::to_string(INT_MAX)};
    return value.get<int>();
}

Vec3 read_point(const json& value, const std::string& path)
{
    if (!value.is_array() || value.size() != 3)
        throw FieldError{path, "must be an array of 3 numbers [x, y, z]"};
    Vec3 p;
    for (int k = 0; k < 3; ++k) {
        // JSON has no NaN; `null` is what writers emit for it.
        if (value[k].is_null())
            throw FieldError{path + "[" + std::to_string(k) + "]", "is null (NaN or infinite?)"};
        p[k] = read_number(value[k], path + "[" + std::to_string(k) + "]");
        if (std::abs(p[k]) > 1e6) // a kilometre: no paper design reaches it
            throw FieldError{path + "[" + std::to_string(k) + "]",
                             "is " + value[k].dump() + " mm, must be within ±1e6 mm"};
    }
    return p;
}

Loop3 read_loop(const json& value, const std::string& path)
{
    if (!value.is_array())
        throw FieldError{path, "must be an array of points"};
    Loop3 loop;
    for (size_t i = 0; i < value.size(); ++i)
        loop.push_back(read_point(value[i], path + "[" + std::to_string(i) + "]"));
    if (loop.size() < 3)
        throw FieldError{path, "needs at least 3 points, has " + std::to_string(loop.size())};
    return loop;
}

std::pair<int, int> read_pair(const json& value, const std::string& path)
{
    if (!value.is_array() || value.size() != 2)
        throw FieldError{path, "must be an array of 2 patch ids"};
    return {read_int(value[0], path + "[0]"), read_int(value[1], path + "[1]")};
}

Scaffold read_scaffold(const json& j)
{
    if (!j.is_object())
        throw FieldError{"(root)", "must be a JSON object"};
    const json& format = member(j, "format", "(root)");
    if (format != kFormatName)
        throw FieldError{"format", std::string("must be \"") + kFormatName + "\""};
    const int version = read_int(member(j, "version", "(root)"), "version");
    if (version < 1 || version > kDesignFormatVersion)
        throw FieldError{"version", "is " + std::to_string(version) + ", this build reads 1.." +
                                        std::to_string(kDesignFormatVersion)};
    if (j.contains("units") && j["units"] != "mm")
        throw FieldError{"units", "must be \"mm\""};

    Scaffold s;
    if (j.contains("name")) {
        if (!j["name"].is_string())
            throw FieldError{"name", "must be a string"};
        s.name = j["name"].get<std::string>();
    }
    if (j.contains("design_angle_deg"))
        s.design_angle = read_number(j["design_angle_deg"], "design_angle_deg") * M_PI / 180.0;
    if (j.contains("paper_thickness"))
        s.paper_thickness = read_number(j["paper_thickness"], "paper_thickness");
    s.ground = read_int(member(j, "ground", "(root)"), "ground");
    s.backdrop = read_int(member(j, "backdrop", "(root)"), "backdrop");

    const json& patches = member(j, "patches", "(root)");
    if (!patches.is_array())
        throw FieldError{"patches", "must be an array"};
    for (size_t i = 0; i < patches.size(); ++i) {
        const std::string path = "patches[" + std::to_string(i) + "]";
        const json& pj = patches[i];
        Patch p;
        p.id = read_int(member(pj, "id", path), path + ".id");
        if (pj.contains("name")) {
            if (!pj["name"].is_string())
                throw FieldError{path + ".name", "must be a string"};
            p.name = pj["name"].get<std::string>();
        }
        if (pj.contains("role")) {
            if (!pj["role"].is_string() || !parse_patch_role(pj["role"].get<std::string>(), p.role))
                throw FieldError{path + ".role", "must be one of ground, backdrop, support, top, "
                                                 "front, back, tab, other"};
        }
        p.outer = read_loop(member(pj, "outline", path), path + ".outline");
        if (pj.contains("holes")) {
            if (!pj["holes"].is_array())
                throw FieldError{path + ".holes", "must be an array of loops"};
            for (size_t h = 0; h < pj["holes"].size(); ++h)
                p.holes.push_back(
                    read_loop(pj["holes"][h], path + ".holes[" + std::to_string(h) + "]"));
        }
        s.patches.push_back(std::move(p));
    }

    if (j.contains("hinges")) {
        const json& hinges = j["hinges"];
        if (!hinges.is_array())
            throw FieldError{"hinges", "must be an array"};
        for (size_t i = 0; i < hinges.size(); ++i) {
            const std::string path = "hinges[" + std::to_string(i) + "]";
            const json& hj = hinges[i];
            Hinge h;
            h.id = hj.contains("id") ? read_int(hj["id"], path + ".id") : int(i);
            std::tie(h.patch_a, h.patch_b) =
                read_pair(member(hj, "patches", path), path + ".patches");
            h.from = read_point(member(hj, "from", path), path + ".from");
            h.to = read_point(member(hj, "to", path), path + ".to");
            if (hj.contains("fold")) {
                const json& f = hj["fold"];
                if (f == "valley")
                    h.direction = FoldDirection::valley;
                else if (f == "mountain")
                    h.direction = FoldDirection::mountain;
                else if (f != "unspecified")
                    throw FieldError{path + ".fold",
                                     "must be \"valley\", \"mountain\" or \"unspecified\""};
            }
            if (hj.contains("joint")) {
                const json& k = hj["joint"];
                if (k == "tab")
                    h.kind = JointKind::tab;
                else if (k != "fold")
                    throw FieldError{path + ".joint", "must be \"fold\" or \"tab\""};
            }
            s.hinges.push_back(h);
        }
    }
    if (j.contains("slits")) {
        const json& slits = j["slits"];
        if (!slits.is_array())
            throw FieldError{"slits", "must be an array"};
        for (size_t i = 0; i < slits.size(); ++i) {
            const std::string path = "slits[" + std::to_string(i) + "]";
            const json& sj = slits[i];
            Slit sl;
            sl.id = sj.contains("id") ? read_int(sj["id"], path + ".id") : int(i);
            std::tie(sl.patch_cut, sl.patch_through) =
                read_pair(member(sj, "patches", path), path + ".patches");
            sl.from = read_point(member(sj, "from", path), path + ".from");
            sl.to = read_point(member(sj, "to", path), path + ".to");
            s.slits.push_back(sl);
        }
    }
    if (j.contains("glue")) {
        const json& glue = j["glue"];
        if (!glue.is_array())
            throw FieldError{"glue", "must be an array"};
        for (size_t i = 0; i < glue.size(); ++i) {
            const std::string path = "glue[" + std::to_string(i) + "]";
            Glue g;
            std::tie(g.patch_a, g.patch_b) =
                read_pair(member(glue[i], "patches", path), path + ".patches");
            s.glue.push_back(g);
        }
    }
    return s;
}

json write_point(const Vec3& p)
{
    return json::array({p.x(), p.y(), p.z()});
}

json write_loop(const Loop3& loop)
{
    json out = json::array();
    for (const Vec3& p : loop)
        out.push_back(write_point(p));
    return out;
}

} // namespace

Result<Scaffold> scaffold_from_json(const std::string& text)
{
    Result<Scaffold> r;
    json j;
    try {
        j = json::parse(text);
    } catch (const json::exception& e) { // syntax errors, and numbers beyond double range
        r.fail(DiagnosticCode::bad_json,
               "not valid JSON (a design file is UTF-8 text): " + printable_ascii(e.what()));
        return r;
    }
    Scaffold s;
    try {
        s = read_scaffold(j);
    } catch (const FieldError& e) {
        r.fail(DiagnosticCode::bad_field, e.field + ": " + e.message, about_parameter(e.field));
        return r;
    } catch (const json::exception& e) {
        r.fail(DiagnosticCode::bad_field, e.what());
        return r;
    }
    return validate_scaffold(std::move(s));
}

std::string scaffold_to_json(const Scaffold& s)
{
    json j;
    j["format"] = kFormatName;
    j["version"] = kDesignFormatVersion;
    j["name"] = s.name;
    j["units"] = "mm";
    j["design_angle_deg"] = s.design_angle * 180.0 / M_PI;
    j["paper_thickness"] = s.paper_thickness;
    j["ground"] = s.ground;
    j["backdrop"] = s.backdrop;
    j["patches"] = json::array();
    for (const Patch& p : s.patches) {
        json pj = {{"id", p.id}, {"name", p.name}, {"role", to_string(p.role)}};
        pj["outline"] = write_loop(p.outer);
        if (!p.holes.empty()) {
            pj["holes"] = json::array();
            for (const Loop3& h : p.holes)
                pj["holes"].push_back(write_loop(h));
        }
        j["patches"].push_back(pj);
    }
    j["hinges"] = json::array();
    for (const Hinge& h : s.hinges)
        j["hinges"].push_back({{"id", h.id},
                               {"patches", {h.patch_a, h.patch_b}},
                               {"from", write_point(h.from)},
                               {"to", write_point(h.to)},
                               {"fold", to_string(h.direction)},
                               {"joint", to_string(h.kind)}});
    if (!s.slits.empty()) {
        j["slits"] = json::array();
        for (const Slit& sl : s.slits)
            j["slits"].push_back({{"id", sl.id},
                                  {"patches", {sl.patch_cut, sl.patch_through}},
                                  {"from", write_point(sl.from)},
                                  {"to", write_point(sl.to)}});
    }
    j["glue"] = json::array();
    for (const Glue& g : s.glue)
        j["glue"].push_back({{"patches", {g.patch_a, g.patch_b}}});
    return j.dump(1);
}

Result<Scaffold> load_scaffold(const std::string& path)
{
    Result<Scaffold> r;
    // A NUL would end the name the system sees early: "a.json\0.evil" must not open a.json.
    if (path.find('\0') != std::string::npos) {
        r.fail(DiagnosticCode::unreadable_file, "design file name contains a NUL character");
        return r;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        r.fail(DiagnosticCode::unreadable_file, "cannot open design file '" + path + "'");
        return r;
    }
    // Read at most the limit and one byte more: /dev/zero or a huge file must not run forever.
    std::string text;
    std::string chunk(size_t(1) << 20, '\0');
    while (in && text.size() <= kMaxDesignFileBytes) {
        in.read(chunk.data(), std::streamsize(chunk.size()));
        text.append(chunk.data(), size_t(in.gcount()));
    }
    if (text.size() > kMaxDesignFileBytes) {
        r.fail(DiagnosticCode::unreadable_file, "design file '" + path + "' is larger than " +
                                                    std::to_string(kMaxDesignFileBytes >> 20) +
                                                    " MiB, the largest design PopUp reads");
        return r;
    }
    return scaffold_from_json(text);
}

void save_scaffold(const Scaffold& scaffold, const std::string& path)
{
    std::ofstream out(path);
    if (!out)
        throw std::runtime_error("cannot write design file '" + path + "'");
    out << scaffold_to_json(scaffold) << "\n";
    if (!out)
        throw std::runtime_error("failed while writing design file '" + path + "'");
}

} // namespace popup
