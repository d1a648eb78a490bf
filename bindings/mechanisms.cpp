// Bindings of the card and the mechanism generators: declarations only.
#include <cmath>
#include <stdexcept>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "binding_support.hpp"
#include "popup/mechanisms/box_fold.hpp"
#include "popup/mechanisms/floating_layer.hpp"
#include "popup/mechanisms/horizontal_translation.hpp"
#include "popup/mechanisms/rotation_arm.hpp"
#include "popup/mechanisms/step_fold.hpp"
#include "popup/mechanisms/tent_fold.hpp"
#include "popup/mechanisms/v_box_fold.hpp"
#include "popup/mechanisms/v_fold.hpp"
#include "popup/model/card.hpp"

namespace py = pybind11;
using namespace popup;

namespace {

// Mechanism errors already name the mechanism and the parameter in their message.
MechanismParts added(Result<MechanismParts> r)
{
    return bindings::unwrap(std::move(r));
}

template <class Params, class Add>
void def_generator(py::module_& m, const char* function, Add add, const char* doc)
{
    m.def(
        function,
        [add](Scaffold& s, const BasePatchPair& host, const Params& p, const std::string& name) {
            return added(add(s, host, p, name));
        },
        py::arg("scaffold"), py::arg("host"), py::arg("params"), py::arg("name"), doc);
}

// Closed forms hold for openings 0..π and give numbers only for parameters in range: anything
// else is a named ValueError, never a silent NaN.
void check_opening(double opening, const char* name)
{
    if (!(opening >= 0.0 && opening <= M_PI))
        throw std::invalid_argument(std::string(name) + " = " + std::to_string(opening) +
                                    " rad, must be 0 to π");
}

bool finite(const Vec2& v)
{
    return v.allFinite();
}
bool finite(const Vec3& v)
{
    return v.allFinite();
}
bool finite(const BoxSection& b)
{
    return b.top.allFinite() && b.side_ground_top.allFinite() && b.side_backdrop_top.allFinite() &&
           b.crease_foot.allFinite() && std::isfinite(b.crease_out);
}
bool finite(const BasePatchPair& p)
{
    return p.origin.allFinite() && p.axis.allFinite() && p.up.allFinite() &&
           std::isfinite(p.opening) && std::isfinite(p.length);
}

template <class T> T checked(T value, const char* function)
{
    if (!finite(value))
        throw std::invalid_argument(std::string(function) +
                                    ": no closed form for these parameters (a NaN or infinite "
                                    "parameter, or one out of its range)");
    return value;
}

/// A closed form f(params, opening), its opening and result checked.
template <class Params, class Result>
auto closed_form(Result (*f)(const Params&, double), const char* name)
{
    return [f, name](const Params& p, double opening) {
        check_opening(opening, "opening");
        return checked(f(p, opening), name);
    };
}

/// The same for f(params, design_opening, opening).
template <class Params, class Result>
auto closed_form(Result (*f)(const Params&, double, double), const char* name)
{
    return [f, name](const Params& p, double design_opening, double opening) {
        check_opening(design_opening, "design_opening");
        check_opening(opening, "opening");
        return checked(f(p, design_opening, opening), name);
    };
}
// The card, its base patch pairs and what a mechanism adds.
void bind_card_and_hosts(py::module_& m)
{
    py::class_<CardParams>(m, "CardParams")
        .def(py::init<>())
        .def_readwrite("width", &CardParams::width)
        .def_readwrite("depth", &CardParams::depth)
        .def_readwrite("paper_thickness", &CardParams::paper_thickness)
        .def_readwrite("name", &CardParams::name);
    m.def(
        "make_card", [](const CardParams& p) { return bindings::unwrap(make_card(p)); },
        py::arg("params"), "A card open flat: ground id 0, backdrop id 1 (DesignError if bad).");

    py::class_<BasePatchPair>(m, "BasePatchPair")
        .def_readonly("name", &BasePatchPair::name)
        .def_readonly("ground", &BasePatchPair::ground)
        .def_readonly("backdrop", &BasePatchPair::backdrop)
        .def_readonly("origin", &BasePatchPair::origin)
        .def_readonly("axis", &BasePatchPair::axis)
        .def_readonly("up", &BasePatchPair::up)
        .def_readonly("opening", &BasePatchPair::opening)
        .def_readonly("length", &BasePatchPair::length)
        .def_readonly("ground_depth", &BasePatchPair::ground_depth)
        .def_readonly("backdrop_depth", &BasePatchPair::backdrop_depth);
    m.def("central_fold", &central_fold, py::arg("card"), "The card's central fold as a pair.");

    py::class_<MechanismParts>(m, "MechanismParts")
        .def_readonly("name", &MechanismParts::name)
        .def_readonly("patches", &MechanismParts::patches)
        .def_readonly("offered", &MechanismParts::offered)
        .def_readonly("host", &MechanismParts::host)
        .def_readonly("sweep_from", &MechanismParts::sweep_from)
        .def_readonly("sweep_to", &MechanismParts::sweep_to);
    m.def("placement_conflicts", &placement_conflicts, py::arg("mechanisms"),
          "Thesis §4.2.2 pre-check: pairs of mechanism names on one host whose swept intervals "
          "overlap.");
}

// Every mechanism kind's parameters and closed forms.
void bind_mechanism_parameters(py::module_& m)
{
    py::class_<Placement1D>(m, "Placement1D")
        .def_readwrite("offset", &Placement1D::offset)
        .def_readwrite("width", &Placement1D::width);
    py::class_<TentFoldParams, Placement1D>(m, "TentFoldParams")
        .def(py::init<>())
        .def_readwrite("foot", &TentFoldParams::foot)
        .def_readwrite("foot_backdrop", &TentFoldParams::foot_backdrop)
        .def_readwrite("slope", &TentFoldParams::slope);
    m.def("tent_backdrop_slope", &tent_backdrop_slope, py::arg("params"));
    py::class_<StepFoldParams, Placement1D>(m, "StepFoldParams")
        .def(py::init<>())
        .def_readwrite("run_ground", &StepFoldParams::run_ground)
        .def_readwrite("run_backdrop", &StepFoldParams::run_backdrop);
    py::class_<VFoldParams>(m, "VFoldParams")
        .def(py::init<>())
        .def_readwrite("offset", &VFoldParams::offset)
        .def_readwrite("run", &VFoldParams::run)
        .def_readwrite("hinge_angle", &VFoldParams::hinge_angle)
        .def_readwrite("spine", &VFoldParams::spine)
        .def_readwrite("spine_angle", &VFoldParams::spine_angle);
    py::class_<BoxFoldParams, Placement1D>(m, "BoxFoldParams")
        .def(py::init<>())
        .def_readwrite("depth_ground", &BoxFoldParams::depth_ground)
        .def_readwrite("depth_backdrop", &BoxFoldParams::depth_backdrop)
        .def_readwrite("height", &BoxFoldParams::height)
        .def_readwrite("panel_pairs", &BoxFoldParams::panel_pairs)
        .def_readwrite("front", &BoxFoldParams::front)
        .def_readwrite("back", &BoxFoldParams::back);

    py::class_<FloatingLayerParams, Placement1D>(m, "FloatingLayerParams")
        .def(py::init<>())
        .def_readwrite("height", &FloatingLayerParams::height)
        .def_readwrite("support", &FloatingLayerParams::support)
        .def_readwrite("overhang", &FloatingLayerParams::overhang);
    py::enum_<LayerSide>(m, "LayerSide")
        .value("ground", LayerSide::ground)
        .value("backdrop", LayerSide::backdrop);
    m.def(
        "floating_layer_side",
        [](const FloatingLayerParams& p, LayerSide side, double angle) {
            check_opening(angle, "angle");
            return checked(floating_layer_side(p, side, angle), "floating_layer_side");
        },
        py::arg("params"), py::arg("side"), py::arg("angle"),
        "Closed form: the layer's side pair (origin, axis, up, opening angle/2) posed when its "
        "host is open at `angle`, in the host's frame.");
    py::class_<HorizontalTranslationParams, StepFoldParams>(m, "HorizontalTranslationParams")
        .def(py::init<>())
        .def_readwrite("reach", &HorizontalTranslationParams::reach);
    m.def("horizontal_translation_tip",
          closed_form(&horizontal_translation_tip, "horizontal_translation_tip"), py::arg("params"),
          py::arg("opening"), "Closed form: M's far end P (x, z) in the host's section.");
    py::class_<RotationArmParams>(m, "RotationArmParams")
        .def(py::init<>())
        .def_readwrite("offset", &RotationArmParams::offset)
        .def_readwrite("spine", &RotationArmParams::spine)
        .def_readwrite("run", &RotationArmParams::run)
        .def_readwrite("arm", &RotationArmParams::arm);
    m.def("rotation_arm_tip", closed_form(&rotation_arm_tip, "rotation_arm_tip"), py::arg("params"),
          py::arg("opening"),
          "Closed form: the arm's tip P (x, y, z) in the host's frame at that opening.");
    m.def(
        "rotation_arm_tip_on_layer_side",
        [](const RotationArmParams& arm, const FloatingLayerParams& layer, LayerSide side,
           double angle) {
            check_opening(angle, "angle");
            return checked(rotation_arm_tip_on_layer_side(arm, layer, side, angle),
                           "rotation_arm_tip_on_layer_side");
        },
        py::arg("arm"), py::arg("layer"), py::arg("side"), py::arg("angle"),
        "Closed form: the tip of an arm on a floating layer's side pair, in the layer host's "
        "frame when that host is open at `angle` (thesis §4.3.4, off the central fold).");
    py::class_<VBoxFoldParams>(m, "VBoxFoldParams")
        .def(py::init<>())
        .def_readwrite("offset", &VBoxFoldParams::offset)
        .def_readwrite("side", &VBoxFoldParams::side)
        .def_readwrite("height", &VBoxFoldParams::height)
        .def_readwrite("wall_angle", &VBoxFoldParams::wall_angle)
        .def_readwrite("back", &VBoxFoldParams::back);
    m.def("v_box_front_corner", closed_form(&v_box_front_corner, "v_box_front_corner"),
          py::arg("params"), py::arg("opening"),
          "Closed form: the v-box's front top corner in the host's frame at that opening.");
    py::class_<BoxSection>(m, "BoxSection")
        .def_readonly("top", &BoxSection::top)
        .def_readonly("side_ground_top", &BoxSection::side_ground_top)
        .def_readonly("side_backdrop_top", &BoxSection::side_backdrop_top)
        .def_readonly("crease_foot", &BoxSection::crease_foot)
        .def_readonly("crease_out", &BoxSection::crease_out);
    m.def("tent_apex", closed_form(&tent_apex, "tent_apex"), py::arg("params"), py::arg("opening"),
          "Closed form: apex (x, z) in the host's section at that opening.");
    m.def("step_nose", closed_form(&step_nose, "step_nose"), py::arg("params"), py::arg("opening"));
    m.def("v_fold_tip", closed_form(&v_fold_tip, "v_fold_tip"), py::arg("params"),
          py::arg("design_opening"), py::arg("opening"));
    m.def("v_fold_wings", closed_form(&v_fold_wings, "v_fold_wings"), py::arg("params"),
          py::arg("design_opening"), py::arg("opening"),
          "Closed form: the wings' base patch pair, posed at that opening.");
    m.def("box_fold_section", closed_form(&box_fold_section, "box_fold_section"), py::arg("params"),
          py::arg("opening"));

    def_generator<TentFoldParams>(m, "add_tent_fold", &add_tent_fold,
                                  "Adds a tent fold on `host`; DesignError names a bad parameter.");
    def_generator<StepFoldParams>(m, "add_step_fold", &add_step_fold,
                                  "Adds a parallelogram step fold on `host`.");
    def_generator<VFoldParams>(m, "add_v_fold", &add_v_fold, "Adds a type-2 v-fold on `host`.");
    def_generator<BoxFoldParams>(m, "add_box_fold", &add_box_fold,
                                 "Adds a box fold; its parts offer the top and both sides.");
    def_generator<FloatingLayerParams>(m, "add_floating_layer", &add_floating_layer,
                                       "Adds a floating layer; its platform is offered first.");
    def_generator<HorizontalTranslationParams>(
        m, "add_horizontal_translation", &add_horizontal_translation,
        "Adds a horizontal translation: a step fold and a patch M through a slit at its nose.");
    def_generator<RotationArmParams>(
        m, "add_rotation_arm", &add_rotation_arm,
        "Adds a rotation arm (extended v-fold, thesis §4.3.4) on a flat host or a "
        "floating layer's side pair.");
    m.def(
        "add_vertical_translation",
        [](Scaffold& s, const BasePatchPair& host, const VBoxFoldParams& p,
           const std::string& name) { return added(add_vertical_translation(s, host, p, name)); },
        py::arg("scaffold"), py::arg("host"), py::arg("params"), py::arg("name"),
        "Adds a vertical translation (the v-box's triangular half, thesis §4.3.2).");
    def_generator<VBoxFoldParams>(m, "add_v_box_fold", &add_v_box_fold,
                                  "Adds a type-1 v-fold (v-box) on a host open flat.");
}

} // namespace

void bind_mechanisms(py::module_& m)
{
    bind_card_and_hosts(m);
    bind_mechanism_parameters(m);
}
