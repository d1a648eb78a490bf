// Bindings of profiles (outlines cut into patches) and the model silhouettes that make them:
// declarations and conversions only.
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "binding_support.hpp"
#include "point_rows.hpp"
#include "popup/fitting/depth_layers.hpp"
#include "popup/fitting/silhouette.hpp"
#include "popup/model/apply_profile.hpp"
#include "popup/simulation/simulate_fold.hpp"

namespace py = pybind11;
using namespace popup;
using namespace popup::bindings;

namespace {

// The loop overloads below add to the shared ones, not hide them.
using bindings::loop_of;
using bindings::rows_of;

std::vector<Rows2d> rows_of(const std::vector<Loop2>& loops)
{
    std::vector<Rows2d> out;
    for (const Loop2& loop : loops)
        out.push_back(rows_of(loop));
    return out;
}

std::vector<Loop2> loops_of(const std::vector<Rows2d>& rows)
{
    std::vector<Loop2> out;
    for (const Rows2d& m : rows)
        out.push_back(loop_of(m));
    return out;
}

// The pose of patch `patch` in `state` (a FoldState of the same scaffold), if one is given.
std::optional<Pose> pose_of(const Scaffold& s, int patch, const std::optional<FoldState>& state)
{
    if (!state)
        return std::nullopt;
    if (state->poses.size() != s.patches.size())
        throw std::invalid_argument("state has " + std::to_string(state->poses.size()) +
                                    " poses for " + std::to_string(s.patches.size()) +
                                    " patches: it is not a state of this scaffold");
    const int index = s.patch_index(patch);
    if (index < 0)
        return std::nullopt; // the core names the unknown patch
    return state->poses[index];
}

} // namespace

void bind_profiles(py::module_& m)
{
    py::class_<Profile>(m, "Profile",
                        "An outline to cut a patch to: outer loop and holes (Nx2, either "
                        "winding) in the patch's profile frame, mm (docs/DESIGN.md, Profiles)")
        .def(py::init([](const Rows2d& outer, const std::vector<Rows2d>& holes, std::string name) {
                 Profile p;
                 p.outer = loop_of(outer);
                 p.holes = loops_of(holes);
                 p.name = std::move(name);
                 return p;
             }),
             py::arg("outer"), py::arg("holes") = std::vector<Rows2d>{},
             py::arg("name") = "profile")
        .def_readwrite("name", &Profile::name)
        .def_property(
            "outer", [](const Profile& p) { return rows_of(p.outer); },
            [](Profile& p, const Rows2d& m) { p.outer = loop_of(m); })
        .def_property(
            "holes", [](const Profile& p) { return rows_of(p.holes); },
            [](Profile& p, const std::vector<Rows2d>& h) { p.holes = loops_of(h); });

    py::class_<ProfileFrame>(m, "ProfileFrame",
                             "A patch's profile frame: origin mid base hinge, u along it, v "
                             "across the patch, design-state world coordinates (mm)")
        .def_readonly("patch", &ProfileFrame::patch)
        .def_readonly("hinge", &ProfileFrame::hinge)
        .def_property_readonly("origin", [](const ProfileFrame& f) { return Vec3(f.origin); })
        .def_property_readonly("u", [](const ProfileFrame& f) { return Vec3(f.u); })
        .def_property_readonly("v", [](const ProfileFrame& f) { return Vec3(f.v); })
        .def_property_readonly("normal", [](const ProfileFrame& f) { return Vec3(f.normal); });

    py::class_<ProfileApplied>(m, "ProfileApplied")
        .def_readonly("patch", &ProfileApplied::patch)
        .def_readonly("frame", &ProfileApplied::frame)
        .def_readonly("area_before", &ProfileApplied::area_before)
        .def_readonly("area_after", &ProfileApplied::area_after)
        .def_readonly("hinges", &ProfileApplied::hinges)
        .def_readonly("dropped_pieces", &ProfileApplied::dropped_pieces)
        .def_property_readonly(
            "warnings",
            [](const ProfileApplied& a) { return bindings::diagnostic_list(a.warnings); },
            "Warnings as dicts (loose paper dropped)");

    m.def(
        "profile_frame",
        [](const Scaffold& s, int patch) { return bindings::unwrap(profile_frame(s, patch)); },
        py::arg("scaffold"), py::arg("patch"), "The profile frame of patch id `patch`.");
    m.def(
        "check_profile", [](const Profile& p) { return bindings::unwrap(checked_profile(p)); },
        py::arg("profile"),
        "The profile without repeated points; DesignError (bad_profile) names a bad loop.");
    m.def(
        "apply_profile",
        [](Scaffold& s, int patch, const Profile& p) {
            return bindings::unwrap(apply_profile(s, patch, p));
        },
        py::arg("scaffold"), py::arg("patch"), py::arg("profile"),
        "Cuts patch id `patch` of `scaffold` (in place) to its outline ∩ the profile and clips "
        "its folds and slits to the paper left. DesignError (bad_profile, profile_misses_hinge, "
        "unknown_patch) leaves the scaffold unchanged.");
    m.def(
        "apply_profile",
        [](Scaffold& s, const std::string& mechanism, const std::string& part, const Profile& p) {
            return bindings::unwrap(apply_profile(s, mechanism, part, p));
        },
        py::arg("scaffold"), py::arg("mechanism"), py::arg("part"), py::arg("profile"),
        "The same for the patch named '<mechanism>.<part>' (e.g. 'B1', 'FL').");

    py::class_<Silhouette>(m, "Silhouette",
                           "A model's orthographic silhouette on a patch, in its profile frame")
        .def_readonly("profile", &Silhouette::profile, "The largest piece, ready for apply_profile")
        .def_readonly("area", &Silhouette::area, "mm², of that piece")
        .def_readonly("left_out", &Silhouette::left_out, "mm², of the smaller pieces")
        .def_readonly("pieces", &Silhouette::pieces)
        .def_readonly("triangles", &Silhouette::triangles);
    m.def(
        "silhouette_profile",
        [](const ModelMesh& model, const Scaffold& s, int patch, std::optional<double> depth_near,
           std::optional<double> depth_far, bool facing_only, std::optional<FoldState> state) {
            SilhouetteOptions o;
            o.depth_near = depth_near;
            o.depth_far = depth_far;
            o.facing_only = facing_only;
            o.pose = pose_of(s, patch, state);
            return bindings::unwrap(silhouette_profile(model, s, patch, o));
        },
        py::arg("model"), py::arg("scaffold"), py::arg("patch"), py::arg("depth_near") = py::none(),
        py::arg("depth_far") = py::none(), py::arg("facing_only") = false,
        py::arg("state") = py::none(), py::call_guard<py::gil_scoped_release>(),
        "Orthographic silhouette of `model` (card frame, mm) on patch id `patch`, optionally "
        "only between depth_near and depth_far (mm along the patch normal); exact union of the "
        "projected triangles (Clipper). `state`: a FoldState of the scaffold (simulate_fold) "
        "where the patch stands as the model does (a step at 90°); default the design state.");

    py::class_<DepthLayer>(m, "DepthLayer")
        .def_readonly("depth", &DepthLayer::depth, "area-weighted mean depth of its faces (mm)")
        .def_readonly("depth_near", &DepthLayer::depth_near)
        .def_readonly("depth_far", &DepthLayer::depth_far)
        .def_readonly("silhouette", &DepthLayer::silhouette);
    m.def(
        "depth_layers",
        [](const ModelMesh& model, const Scaffold& s, int patch, double min_gap, int max_layers,
           double min_area_fraction, std::optional<FoldState> state) {
            DepthLayerOptions o;
            o.min_gap = min_gap;
            o.max_layers = max_layers;
            o.min_area_fraction = min_area_fraction;
            o.pose = pose_of(s, patch, state);
            return bindings::unwrap(depth_layers(model, s, patch, o));
        },
        py::arg("model"), py::arg("scaffold"), py::arg("patch"), py::arg("min_gap") = 0.0,
        py::arg("max_layers") = 4, py::arg("min_area_fraction") = 0.02,
        py::arg("state") = py::none(), py::call_guard<py::gil_scoped_release>(),
        "The model's faces facing patch id `patch`, clustered by depth (1-D gaps wider than "
        "min_gap, default 2 % of the model's diagonal), nearest first, one silhouette each; "
        "`state` as for silhouette_profile.");
}
