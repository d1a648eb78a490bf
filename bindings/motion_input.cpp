// Binding of the motion input (issue 13): animations, chains and target paths; conversions only.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "binding_support.hpp"
#include "point_rows.hpp"
#include "popup/motion/motion_targets.hpp"

namespace py = pybind11;
using namespace popup;
using namespace popup::bindings;

namespace {

/// A 3-sequence of numbers, or a named bad_option.
Vec3 vector_of(const py::object& value, const char* name)
{
    std::vector<double> v;
    try {
        v = value.cast<std::vector<double>>();
    } catch (const py::cast_error&) {
    }
    if (v.size() != 3)
        throw DesignFailure({Diagnostic::error(DiagnosticCode::bad_option,
                                               std::string("MotionView.") + name +
                                                   " must be a sequence of 3 numbers",
                                               about_parameter(name))});
    return Vec3(v[0], v[1], v[2]);
}

std::vector<Eigen::Matrix4d> matrices(const std::vector<Eigen::Isometry3d>& transforms)
{
    std::vector<Eigen::Matrix4d> out;
    for (const Eigen::Isometry3d& t : transforms)
        out.push_back(t.matrix());
    return out;
}

// Animations read from files and posed.
void bind_animation(py::module_& m)
{
    py::class_<Animation>(m, "Animation",
                          "An animated character (thesis ch. 6) in the file's units and axes: "
                          "bones (name, parent index, -1 for a root; parents first), one time "
                          "per frame, and the skinned mesh in its bind pose (None without one)")
        .def_readonly("source", &Animation::source)
        .def_property_readonly("bones",
                               [](const Animation& a) {
                                   py::list out;
                                   for (const Bone& b : a.bones)
                                       out.append(py::make_tuple(b.name, b.parent));
                                   return out;
                               })
        .def_property_readonly("frame_times_s",
                               [](const Animation& a) {
                                   return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(
                                       a.frame_times_s.data(), a.frame_times_s.size()));
                               })
        .def_property_readonly("frames", &Animation::frames)
        .def_property_readonly("mesh",
                               [](const Animation& a) -> py::object {
                                   if (a.mesh.vertices.empty())
                                       return py::none();
                                   return py::cast(a.mesh);
                               })
        .def("__repr__", [](const Animation& a) {
            return "<Animation " + a.source + ": " + std::to_string(a.bones.size()) + " bones, " +
                   std::to_string(a.frames()) + " frames" +
                   (a.mesh.vertices.empty()
                        ? std::string()
                        : ", " + std::to_string(a.mesh.vertices.size()) + " skinned vertices") +
                   ">";
        });

    m.def(
        "load_animation",
        [](const std::string& path, double timeout_s) {
            LoadAnimationOptions options;
            options.timeout_s = timeout_s;
            return unwrap(load_animation(path, options));
        },
        py::arg("path"), py::arg("timeout_s") = 120.0, py::call_guard<py::gil_scoped_release>(),
        "Reads an animated character through assimp (BVH, FBX, glTF/GLB with skins, Collada) in "
        "a child process stopped after timeout_s. DesignError: unreadable_model naming the file "
        "and the reason, then check_animation's codes.");
    m.def(
        "load_trajectories",
        [](const std::string& path) { return unwrap(load_trajectories(path)); }, py::arg("path"),
        "Reads the plain JSON of named end-effector trajectories (docs/ANIMATION_INPUT.md); "
        "DesignError names the malformed field.");
    m.def(
        "check_animation", [](const Animation& a) { return unwrap(check_animation(a)); },
        py::arg("animation"),
        "The animation, or DesignError (bad_animation, skeleton_cycle, no_animation, "
        "single_frame, non_finite_animation) naming what is wrong.");
    m.def(
        "forward_kinematics",
        [](const Animation& a, double frame) { return matrices(forward_kinematics(a, frame)); },
        py::arg("animation"), py::arg("frame"),
        "Each bone's 4x4 global transform (bone to the file's world) at a frame; fractional "
        "frames slerp rotations and lerp translations between their neighbours.");
    m.def("posed_mesh", &posed_mesh, py::arg("animation"), py::arg("frame"),
          "The skinned mesh at a frame (linear blend skinning).");
    m.def("character_root", &character_root, py::arg("animation"),
          "The character's own root bone: the first root, or below it while a bone stands still "
          "and has one child (a glTF or FBX armature node above the hips); what is above it is "
          "not drawn or measured as the character.");
}

// Linkage chains, the card's view and the target paths.
void bind_chains_and_targets(py::module_& m)
{
    py::class_<ChainOptions>(m, "ChainOptions", "Linkage segmentation options (thesis §6.1)")
        .def(py::init<>())
        .def_readwrite("prune_fraction", &ChainOptions::prune_fraction,
                       "τp: a leaf chain weighing less than this fraction of the mean bone "
                       "weight (vertices; bone length without a mesh) is pruned into its parent")
        .def_readwrite("min_chain_size", &ChainOptions::min_chain_size,
                       "a leaf chain reaching less than this fraction of the character's size "
                       "is part of the chain it hangs from (fingers, face bones), unless such "
                       "chains are all that moves; 0 keeps them");
    py::class_<LinkageChain>(m, "LinkageChain",
                             "A single chain of the bone tree: bones root to tip (indices)")
        .def_readonly("name", &LinkageChain::name)
        .def_readonly("bones", &LinkageChain::bones)
        .def_readonly("parent_chain", &LinkageChain::parent_chain)
        .def_readonly("vertices", &LinkageChain::vertices)
        .def_readonly("weight", &LinkageChain::weight)
        .def_readonly("pruned", &LinkageChain::pruned)
        .def_readonly("reach", &LinkageChain::reach)
        .def("__repr__", [](const LinkageChain& c) {
            return "<LinkageChain " + c.name + ": " + std::to_string(c.bones.size()) +
                   " bones, weight " + std::to_string(c.weight) + ">";
        });
    m.def(
        "linkage_chains",
        [](const Animation& a, const ChainOptions& options) { return linkage_chains(a, options); },
        py::arg("animation"), py::arg("options") = ChainOptions(),
        "Splits the skeleton into single chains and prunes small leaf chains.");

    py::class_<MotionView>(m, "MotionView",
                           "How the character sits on the card: view and up are 3-sequences in "
                           "the file's axes; scale (card mm per file unit) and centre (card x, "
                           "y) are None for the default fit; last_frame -1 is the last")
        .def(py::init<>())
        .def_property(
            "view",
            [](const MotionView& v) { return py::make_tuple(v.view.x(), v.view.y(), v.view.z()); },
            [](MotionView& v, const py::object& value) { v.view = vector_of(value, "view"); })
        .def_property(
            "up", [](const MotionView& v) { return py::make_tuple(v.up.x(), v.up.y(), v.up.z()); },
            [](MotionView& v, const py::object& value) { v.up = vector_of(value, "up"); })
        .def_readwrite("scale", &MotionView::scale)
        .def_property(
            "centre",
            [](const MotionView& v) -> py::object {
                if (!v.centre)
                    return py::none();
                return py::make_tuple(v.centre->x(), v.centre->y());
            },
            [](MotionView& v, const py::object& value) {
                if (value.is_none()) {
                    v.centre.reset();
                    return;
                }
                std::vector<double> c;
                try {
                    c = value.cast<std::vector<double>>();
                } catch (const py::cast_error&) {
                }
                if (c.size() != 2)
                    throw DesignFailure({Diagnostic::error(
                        DiagnosticCode::bad_option,
                        "MotionView.centre must be None or a sequence of 2 numbers (card mm)",
                        about_parameter("centre"))});
                v.centre = Vec2(c[0], c[1]);
            })
        .def_readwrite("margin", &MotionView::margin)
        .def_readwrite("card", &MotionView::card, "the card's width and depth (mm)")
        .def_property(
            "card_width", [](const MotionView& v) { return v.card.width; },
            [](MotionView& v, double w) { v.card.width = w; }, "card.width (mm)")
        .def_property(
            "card_depth", [](const MotionView& v) { return v.card.depth; },
            [](MotionView& v, double d) { v.card.depth = d; }, "card.depth (mm)")
        .def_readwrite("first_frame", &MotionView::first_frame)
        .def_readwrite("last_frame", &MotionView::last_frame)
        .def_readwrite("angle_tolerance", &MotionView::angle_tolerance)
        .def_readwrite("min_intervals", &MotionView::min_intervals)
        .def_readwrite("keep_travel", &MotionView::keep_travel)
        .def_readwrite("auto_frames", &MotionView::auto_frames);

    py::class_<ChainPath>(m, "ChainPath",
                          "A chain's target motion on the card: s in [0, 1] (θ = 180°·s), "
                          "effector and root Nx2 card mm, depth D (0 deepest .. 1 nearest)")
        .def_readonly("s", &ChainPath::s)
        .def_property_readonly("effector", [](const ChainPath& p) { return rows_of(p.effector); })
        .def_property_readonly("root", [](const ChainPath& p) { return rows_of(p.root); })
        .def_readonly("depth", &ChainPath::depth);
    py::class_<MotionTargets>(m, "MotionTargets")
        .def_readonly("animation_to_card", &MotionTargets::animation_to_card)
        .def_readonly("chains", &MotionTargets::chains)
        .def_readonly("paths", &MotionTargets::paths)
        .def_readonly("diagonal_mm", &MotionTargets::diagonal_mm)
        .def_readonly("first_frame", &MotionTargets::first_frame)
        .def_readonly("last_frame", &MotionTargets::last_frame)
        .def_readonly("travel_removed_mm", &MotionTargets::travel_removed_mm)
        .def_readonly("in_place", &MotionTargets::in_place)
        .def_property_readonly("window", [](const MotionTargets& t) {
            py::dict d;
            d["chosen"] = t.window.chosen;
            d["score"] = t.window.score;
            d["whole_score"] = t.window.whole_score;
            return d;
        });
    m.def("path_moves", &path_moves, py::arg("path"), py::arg("diagonal_mm"),
          "Whether a chain moves on the card: its end effector strays more than 1 % of the "
          "character's diagonal from its mean point (as the mapping decides what holds still).");
    m.def(
        "ground_travel",
        [](const Animation& a, const Vec3& up, int last_frame, double frame) {
            return ground_travel(a, up, last_frame, frame);
        },
        py::arg("animation"), py::arg("up"), py::arg("last_frame"), py::arg("frame"),
        "The first root's travel along the ground (across up) from last_frame to frame, file "
        "units: what motion_targets takes out of every pose when targets.in_place.");
    m.def(
        "motion_targets",
        [](const Animation& a, const MotionView& view, const ChainOptions& chains) {
            return unwrap(motion_targets(a, view, chains));
        },
        py::arg("animation"), py::arg("view") = MotionView(), py::arg("chains") = ChainOptions(),
        py::call_guard<py::gil_scoped_release>(),
        "Forward kinematics over the frame range, projection on the card, adaptive sampling "
        "(τangle); DesignError (bad_option) names a bad view option.");
}

} // namespace

void bind_motion_input(py::module_& m)
{
    bind_animation(m);
    bind_chains_and_targets(m);
}
