// The plain JSON of named end-effector trajectories (docs/ANIMATION_INPUT.md).
#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "popup/motion/animation.hpp"

namespace popup {

namespace {

using nlohmann::json;

/// A malformed field: the code and a message naming the field, its value and what is allowed.
struct FieldError {
    DiagnosticCode code;
    std::string field;
    std::string why;
};

std::string shown(const json& value)
{
    std::string text = value.dump();
    return text.size() > 60 ? text.substr(0, 57) + "..." : text;
}

double number(const json& value, const std::string& field)
{
    if (value.is_null() || (value.is_string() && (value == "NaN" || value == "nan")))
        throw FieldError{DiagnosticCode::non_finite_animation, field,
                         "is " + shown(value) + ", a NaN (must be a finite number)"};
    if (!value.is_number())
        throw FieldError{DiagnosticCode::bad_animation, field,
                         "is " + shown(value) + ", must be a number"};
    const double x = value.get<double>();
    if (!std::isfinite(x))
        throw FieldError{DiagnosticCode::non_finite_animation, field,
                         "is " + shown(value) + ", must be finite"};
    return x;
}

/// [x, y] or [x, y, z] (z = 0 when left out).
Vec3 point(const json& value, const std::string& field)
{
    if (!value.is_array() || value.size() < 2 || value.size() > 3)
        throw FieldError{DiagnosticCode::bad_animation, field,
                         "is " + shown(value) + ", must be a point [x, y] or [x, y, z]"};
    Vec3 p = Vec3::Zero();
    for (size_t k = 0; k < value.size(); ++k)
        p[k] = number(value[k], field + "[" + std::to_string(k) + "]");
    return p;
}

std::vector<Vec3> track(const json& value, const std::string& field)
{
    if (!value.is_array())
        throw FieldError{DiagnosticCode::bad_animation, field,
                         "is " + shown(value) + ", must be a list of points, one per frame"};
    std::vector<Vec3> points;
    for (size_t i = 0; i < value.size(); ++i)
        points.push_back(point(value[i], field + "[" + std::to_string(i) + "]"));
    return points;
}

void refuse_unknown_keys(const json& object, const std::vector<std::string>& known,
                         const std::string& where)
{
    for (auto it = object.begin(); it != object.end(); ++it)
        if (std::find(known.begin(), known.end(), it.key()) == known.end()) {
            std::string list;
            for (const std::string& k : known)
                list += (list.empty() ? "" : ", ") + k;
            throw FieldError{DiagnosticCode::bad_animation, where + it.key(),
                             "is not a known field (known: " + list + ")"};
        }
}

struct Effector {
    std::string name;
    std::vector<Vec3> points;
    std::vector<Vec3> root; ///< empty when it hangs from a parent effector
    std::string parent;
    std::string field;
};

// The effectors of the document, checked one by one; `index`: each one's position by name.
std::vector<Effector> effectors_of(const json& doc, std::map<std::string, int>& index)
{
    if (!doc.is_object())
        throw FieldError{DiagnosticCode::bad_animation, "(top level)",
                         "is " + shown(doc) + ", must be an object"};
    refuse_unknown_keys(doc, {"format", "version", "frame_rate", "times", "effectors"}, "");
    if (doc.contains("format") && doc["format"] != "popup-trajectories")
        throw FieldError{DiagnosticCode::bad_animation, "format",
                         "is " + shown(doc["format"]) + ", must be \"popup-trajectories\""};
    if (doc.contains("version") && doc["version"] != 1)
        throw FieldError{DiagnosticCode::bad_animation, "version",
                         "is " + shown(doc["version"]) + ", must be 1"};
    if (!doc.contains("effectors"))
        throw FieldError{DiagnosticCode::no_animation, "effectors",
                         "is missing: there is no trajectory"};
    const json& list = doc["effectors"];
    if (!list.is_array())
        throw FieldError{DiagnosticCode::bad_animation, "effectors",
                         "is " + shown(list) + ", must be a list of effectors"};
    if (list.empty())
        throw FieldError{DiagnosticCode::no_animation, "effectors",
                         "is empty: there is no trajectory"};

    std::vector<Effector> effectors;
    for (size_t i = 0; i < list.size(); ++i) {
        const std::string at = "effectors[" + std::to_string(i) + "]";
        const json& e = list[i];
        if (!e.is_object())
            throw FieldError{DiagnosticCode::bad_animation, at,
                             "is " + shown(e) + ", must be an object"};
        refuse_unknown_keys(e, {"name", "points", "root", "parent"}, at + ".");
        Effector effector;
        effector.field = at;
        if (!e.contains("name") || !e["name"].is_string() || e["name"].get<std::string>().empty())
            throw FieldError{DiagnosticCode::bad_animation, at + ".name",
                             (e.contains("name") ? "is " + shown(e["name"]) : "is missing") +
                                 ", must be a non-empty string"};
        effector.name = e["name"];
        if (index.count(effector.name))
            throw FieldError{DiagnosticCode::bad_animation, at + ".name",
                             "is \"" + effector.name + "\", already the name of effectors[" +
                                 std::to_string(index[effector.name]) + "]; names must differ"};
        if (!e.contains("points"))
            throw FieldError{DiagnosticCode::bad_animation, at + ".points", "is missing"};
        effector.points = track(e["points"], at + ".points");
        const bool has_root = e.contains("root"), has_parent = e.contains("parent");
        if (has_root == has_parent)
            throw FieldError{DiagnosticCode::bad_animation, at,
                             "(" + effector.name + ") has " +
                                 (has_root ? "both root and parent" : "neither root nor parent") +
                                 "; give exactly one"};
        if (has_parent) {
            if (!e["parent"].is_string())
                throw FieldError{DiagnosticCode::bad_animation, at + ".parent",
                                 "is " + shown(e["parent"]) +
                                     ", must be the name of another effector"};
            effector.parent = e["parent"];
        } else if (e["root"].is_array() && !e["root"].empty() && e["root"][0].is_array()) {
            effector.root = track(e["root"], at + ".root");
        } else {
            effector.root = {point(e["root"], at + ".root")}; // a fixed root
        }
        index[effector.name] = int(i);
        effectors.push_back(std::move(effector));
    }
    return effectors;
}

// The frame times: the effectors' common frame count at `times` or `frame_rate` (25 per second
// when neither is given).
std::vector<double> frame_times(const json& doc, const std::vector<Effector>& effectors)
{
    // Frames: the longest track sets the count; every track must have it (a fixed root aside).
    const size_t frames = effectors[0].points.size();
    for (const Effector& e : effectors) {
        if (e.points.size() != frames)
            throw FieldError{DiagnosticCode::bad_animation, e.field + ".points",
                             "has " + std::to_string(e.points.size()) + " points, " +
                                 effectors[0].field + ".points has " + std::to_string(frames) +
                                 "; every track needs one point per frame"};
        if (e.root.size() > 1 && e.root.size() != frames)
            throw FieldError{DiagnosticCode::bad_animation, e.field + ".root",
                             "has " + std::to_string(e.root.size()) + " points for " +
                                 std::to_string(frames) +
                                 " frames; give one per frame or a single fixed point"};
    }
    std::vector<double> times;
    if (doc.contains("times") && doc.contains("frame_rate"))
        throw FieldError{DiagnosticCode::bad_animation, "times",
                         "and frame_rate are both given; give one"};
    if (doc.contains("times")) {
        const json& t = doc["times"];
        if (!t.is_array())
            throw FieldError{DiagnosticCode::bad_animation, "times",
                             "is " + shown(t) + ", must be a list of seconds, one per frame"};
        for (size_t f = 0; f < t.size(); ++f)
            times.push_back(number(t[f], "times[" + std::to_string(f) + "]"));
        if (times.size() != frames)
            throw FieldError{DiagnosticCode::bad_animation, "times",
                             "has " + std::to_string(times.size()) + " entries for " +
                                 std::to_string(frames) + " frames"};
    } else {
        double rate = 25.0;
        if (doc.contains("frame_rate")) {
            rate = number(doc["frame_rate"], "frame_rate");
            if (!(rate > 0.0))
                throw FieldError{DiagnosticCode::bad_animation, "frame_rate",
                                 "is " + shown(doc["frame_rate"]) +
                                     ", must be > 0 (frames per second)"};
        }
        for (size_t f = 0; f < frames; ++f)
            times.push_back(double(f) / rate);
    }
    return times;
}

// Bones, parents first: an effector after the effector it hangs from. A parent chain that
// comes back to an effector is a cycle, named in full.
std::vector<int> parents_first(const std::vector<Effector>& effectors,
                               const std::map<std::string, int>& index)
{
    std::vector<int> order, state(effectors.size(), 0); // 0 new, 1 on the path, 2 placed
    std::vector<int> path_names;
    std::function<void(int)> place = [&](int i) {
        if (state[i] == 2)
            return;
        if (state[i] == 1) {
            std::string cycle;
            auto from = std::find(path_names.begin(), path_names.end(), i);
            for (auto it = from; it != path_names.end(); ++it)
                cycle += effectors[*it].name + " -> ";
            throw FieldError{DiagnosticCode::skeleton_cycle, effectors[i].field + ".parent",
                             "closes a cycle: " + cycle + effectors[i].name +
                                 " (each effector's parent after the arrow); effectors must "
                                 "form a tree"};
        }
        state[i] = 1;
        path_names.push_back(i);
        if (!effectors[i].parent.empty()) {
            auto p = index.find(effectors[i].parent);
            if (p == index.end())
                throw FieldError{DiagnosticCode::bad_animation, effectors[i].field + ".parent",
                                 "is \"" + effectors[i].parent + "\", not an effector's name"};
            place(p->second);
        }
        path_names.pop_back();
        state[i] = 2;
        order.push_back(i);
    };
    for (size_t i = 0; i < effectors.size(); ++i)
        place(int(i));
    return order;
}

Animation animation_of(const json& doc, const std::string& path)
{
    std::map<std::string, int> index;
    const std::vector<Effector> effectors = effectors_of(doc, index);
    const std::vector<double> times = frame_times(doc, effectors);
    const size_t frames = effectors[0].points.size();
    Animation animation;
    animation.source = path;
    animation.frame_times_s = times;
    const std::vector<int> order = parents_first(effectors, index);

    std::vector<int> bone_of(effectors.size(), -1);
    std::vector<int> root_bone_of(effectors.size(), -1);
    for (int i : order) {
        const Effector& e = effectors[i];
        if (e.parent.empty()) {
            root_bone_of[i] = int(animation.bones.size());
            animation.bones.push_back({e.name + ".root", -1});
        }
        bone_of[i] = int(animation.bones.size());
        animation.bones.push_back(
            {e.name, e.parent.empty() ? root_bone_of[i] : bone_of[index[e.parent]]});
    }
    animation.local.assign(frames, std::vector<Eigen::Isometry3d>(animation.bones.size(),
                                                                  Eigen::Isometry3d::Identity()));
    for (size_t f = 0; f < frames; ++f)
        for (int i : order) {
            const Effector& e = effectors[i];
            Vec3 base;
            if (e.parent.empty()) {
                base = e.root.size() == 1 ? e.root[0] : e.root[f];
                animation.local[f][root_bone_of[i]].translation() = base;
            } else {
                base = effectors[index[e.parent]].points[f];
            }
            animation.local[f][bone_of[i]].translation() = e.points[f] - base;
        }
    animation.bind_inverse.assign(animation.bones.size(), Eigen::Isometry3d::Identity());
    return animation;
}

} // namespace

Result<Animation> load_trajectories(const std::string& path)
{
    Result<Animation> result;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        result.fail(DiagnosticCode::unreadable_model,
                    "trajectory file " + path + ": cannot be opened", about_parameter(path));
        return result;
    }
    std::stringstream text;
    text << in.rdbuf();
    const std::string bytes = text.str();
    json doc;
    try {
        doc = json::parse(bytes);
    } catch (const json::parse_error& e) {
        // JSON has no NaN or Infinity; a writer that emits them gets the finite-number error.
        const size_t at = e.byte > 0 ? e.byte - 1 : 0;
        const bool non_finite = at < bytes.size() && (bytes.compare(at, 3, "NaN") == 0 ||
                                                      bytes.compare(at, 8, "Infinity") == 0 ||
                                                      bytes.compare(at, 9, "-Infinity") == 0);
        if (non_finite)
            result.fail(DiagnosticCode::non_finite_animation,
                        "trajectory file " + path + ": a NaN or Infinity at byte " +
                            std::to_string(e.byte) + "; coordinates must be finite numbers",
                        about_parameter(path));
        else
            result.fail(DiagnosticCode::bad_json,
                        "trajectory file " + path + ": not JSON (" + e.what() + ")",
                        about_parameter(path));
        return result;
    } catch (const json::out_of_range& e) { // a number beyond double: 1e999
        result.fail(DiagnosticCode::non_finite_animation,
                    "trajectory file " + path + ": " + e.what() +
                        "; coordinates must be finite numbers",
                    about_parameter(path));
        return result;
    }
    try {
        return check_animation(animation_of(doc, path));
    } catch (const FieldError& e) {
        result.fail(e.code, "trajectory file " + path + ": " + e.field + " " + e.why,
                    about_parameter(e.field));
    }
    return result;
}

} // namespace popup
