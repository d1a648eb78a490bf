// Binding of design_motion, the animated pop-up from an animation (thesis ch. 6): conversions
// only.
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <memory>

#include "binding_support.hpp"
#include "point_rows.hpp"
#include "popup/motion/design_motion.hpp"
#include "popup/motion/printed_parts.hpp"

namespace py = pybind11;
using namespace popup;
using namespace popup::bindings;

namespace {

/// What Python holds to watch a running design_motion: .value rises from 0 to 1.
struct MotionProgress {
    std::atomic<double> value{0.0};
};

MotionResult result_or_raise(Result<MotionResult> r)
{
    // No valid design is an answer (valid False, the reasons in the chains and diagnostics);
    // bad input and bad options are errors.
    return unwrap(std::move(r));
}

} // namespace

void bind_motion(py::module_& m)
{
    py::class_<MotionProgress, std::shared_ptr<MotionProgress>>(
        m, "MotionProgress",
        "Pass as progress= to design_motion; read .value (0..1) from another thread while it "
        "runs (mapping 0–0.2, annealing 0.2–0.85, building and the validity check after).")
        .def(py::init<>())
        .def_property_readonly("value", [](const MotionProgress& p) { return p.value.load(); });

    py::class_<MotionOptions>(m, "MotionOptions", "What the maker chooses (thesis §6.2–6.4)")
        .def(py::init<>())
        .def_readwrite("view", &MotionOptions::view)
        .def_readwrite("chains", &MotionOptions::chains)
        .def_readwrite("motion_weight", &MotionOptions::motion_weight, "w_m of eq 6.5 (85)")
        .def_readwrite("depth_weight", &MotionOptions::depth_weight, "w_d of eq 6.5 (15)")
        .def_readwrite("collision_weight", &MotionOptions::collision_weight, "w_c of eq 6.8 (1e5)")
        .def_readwrite("iterations", &MotionOptions::iterations,
                       "annealing iterations per search chain")
        .def_readwrite("search_chains", &MotionOptions::search_chains,
                       "independent annealing runs, one thread each, best kept")
        .def_readwrite("layer_height_max", &MotionOptions::layer_height_max,
                       "h_max (mm); <= 0: 25 mm on an A4 card, scaled")
        .def_readwrite("seed", &MotionOptions::seed)
        .def_readwrite("outlines", &MotionOptions::outlines)
        .def_readwrite("animate_only", &MotionOptions::animate_only,
                       "the chains to animate, by name (ChainReport.name); the others are held "
                       "still; [] (the default): all. Assign a whole list: appending to it "
                       "changes a copy")
        .def_static(
            "fields", [] { return motion_option_fields(); },
            "Every option's OptionField (name, doc, unit, default, range): its own, then the "
            "view's (group 'view') and the chains' (group 'chains').")
        .def(
            "check",
            [](const MotionOptions& o) { return diagnostic_list(check_motion_options(o)); },
            "The options' range errors as diagnostics (empty when every option is in range); the "
            "frame range against an animation is motion_targets' to check.");

    py::class_<ChainReport>(m, "ChainReport", "One chain of the result, as report.json lists it")
        .def_readonly("name", &ChainReport::name)
        .def_readonly("mapping", &ChainReport::mapping)
        .def_readonly("mechanisms", &ChainReport::mechanisms)
        .def_readonly("error", &ChainReport::error, "E_m (eq 6.6) / the character's diagonal")
        .def_readonly("error_mm", &ChainReport::error_mm)
        .def_readonly("floor", &ChainReport::floor,
                      "the lowest E_m any mechanism on the card could reach / the diagonal")
        .def_readonly("floor_mm", &ChainReport::floor_mm)
        .def_readonly("bound", &ChainReport::bound,
                      "the best one mechanism does on this chain alone, collisions ignored / the "
                      "diagonal")
        .def_readonly("bound_mm", &ChainReport::bound_mm)
        .def_readonly("bound_mechanism", &ChainReport::bound_mechanism)
        .def_readonly("weight", &ChainReport::weight)
        .def_readonly("status", &ChainReport::status, "animated, merged or stationary")
        .def_readonly("reason", &ChainReport::reason)
        .def_readonly("s", &ChainReport::s)
        .def_property_readonly("target", [](const ChainReport& c) { return rows_of(c.target); })
        .def_property_readonly("achieved",
                               [](const ChainReport& c) { return rows_of(c.achieved); });

    py::class_<MotionResult>(m, "MotionResult")
        .def_readonly("card", &MotionResult::card)
        .def_readonly("targets", &MotionResult::targets)
        .def_readonly("mechanisms", &MotionResult::mechanisms)
        .def_readonly("profiles", &MotionResult::profiles)
        .def_readonly("chains", &MotionResult::chains)
        .def_readonly("scaffold", &MotionResult::scaffold)
        .def_readonly("valid", &MotionResult::valid)
        .def_readonly("weighted_error", &MotionResult::weighted_error)
        .def_readonly("weighted_floor", &MotionResult::weighted_floor,
                      "Σ weight · floor: no design on this card scores a lower weighted_error")
        .def_readonly("weighted_bound", &MotionResult::weighted_bound,
                      "Σ weight · bound: each chain with its best mechanism alone")
        .def_readonly("iterations", &MotionResult::iterations)
        .def_readonly("cost", &MotionResult::cost)
        .def_readonly("timings", &MotionResult::timings)
        .def_property_readonly(
            "pops_up", &MotionResult::pops_up,
            "valid with at least one mechanism: with every chain printed on the page nothing "
            "stands up")
        .def_property_readonly(
            "diagnostics", [](const MotionResult& r) { return diagnostic_list(r.diagnostics); });

    m.def(
        "design_motion",
        [](const Animation& animation, const MotionOptions& options,
           std::shared_ptr<CancelFlag> cancel, std::shared_ptr<MotionProgress> progress) {
            return result_or_raise(design_motion(animation, options, cancel.get(),
                                                 progress ? &progress->value : nullptr));
        },
        py::arg("animation"), py::arg("options") = MotionOptions(), py::arg("cancel") = nullptr,
        py::arg("progress") = nullptr, py::call_guard<py::gil_scoped_release>(),
        "The animated pop-up of thesis ch. 6 (DesignError on bad input or options; valid False "
        "with diagnostics when the full simulator still refuses the card; popupcore.Cancelled "
        "when cancel is set).");

    py::class_<PrintedPart>(m, "PrintedPart",
                            "One piece of the character as the card prints it (thesis Fig 6.9)")
        .def_readonly("mechanism", &PrintedPart::mechanism,
                      "the mechanism carrying the limb; '' for the body")
        .def_readonly("parts", &PrintedPart::parts,
                      "that mechanism's parts it is printed on; empty for the body")
        .def_readonly("chains", &PrintedPart::chains, "the chains it shows; empty for the body")
        .def_readonly("mesh", &PrintedPart::mesh, "its triangles at the last frame, card mm");
    m.def("printed_parts", &printed_parts, py::arg("animation"), py::arg("result"),
          "The character split as the card prints it: the body first, then one limb per "
          "mechanism that carries chains (empty mesh when no triangle is skinned to them alone); "
          "[] without a skinned mesh.");
}
