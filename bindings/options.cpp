// The option tables and stage timings the pipelines share: each options struct's fields (name,
// doc, unit, default, range), which popupwb/option_fields.py builds flags and panels from.
#include <cmath>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "binding_support.hpp"
#include "popup/model/option_field.hpp"
#include "popup/model/stage_timings.hpp"

namespace py = pybind11;
using namespace popup;

void bind_options(py::module_& m)
{
    py::class_<OptionField>(m, "OptionField",
                            "One option of an options struct: FitOptions.fields(), "
                            "MotionOptions.fields()")
        .def_readonly("name", &OptionField::name, "as the options struct and report.json call it")
        .def_readonly("group", &OptionField::group,
                      "the nested options it sits in ('view', 'chains'), '' at the top")
        .def_readonly("doc", &OptionField::doc)
        .def_readonly("unit", &OptionField::unit,
                      "'mm', '°', what a fraction is of, or '' (a count)")
        .def_property_readonly(
            "kind", [](const OptionField& f) { return std::string(to_string(f.kind)); },
            "number, count, flag, direction (3 numbers), point (2 numbers) or names (a list)")
        .def_property_readonly(
            "default",
            [](const OptionField& f) -> py::object {
                if (std::isnan(f.default_value))
                    return py::none();
                if (f.kind == OptionKind::count)
                    return py::int_(static_cast<long long>(f.default_value));
                if (f.kind == OptionKind::flag)
                    return py::bool_(f.default_value != 0.0);
                return py::float_(f.default_value);
            },
            "the options struct's own default; None for a vector or an option unset by default")
        .def_readonly("min", &OptionField::min, "-inf: no lower end")
        .def_readonly("max", &OptionField::max, "inf: no upper end")
        .def_readonly("min_open", &OptionField::min_open, "min itself is refused")
        .def_readonly("max_open", &OptionField::max_open, "max itself is refused")
        .def_readonly("optional", &OptionField::optional, "may be None: a rule then decides")
        .def_property_readonly("range", &OptionField::range,
                               "the range as errors state it: '1 to 32', '>= 20 and <= 2000 mm'")
        .def("accepts", &OptionField::accepts, py::arg("value"),
             "A finite value within the range (for number, count and flag).")
        .def("__repr__", [](const OptionField& f) {
            return "<OptionField " + (f.group.empty() ? "" : f.group + ".") + f.name + ": " +
                   f.range() + ">";
        });

    py::class_<StageTimings>(m, "StageTimings",
                             "What each stage of a pipeline took and the whole call; iterating "
                             "gives (stage, seconds) pairs and then ('total', total_s), as "
                             "report.json's timings_s lists them")
        .def_readonly("stages", &StageTimings::stages, "[(stage, seconds)] in order")
        .def_readonly("total_s", &StageTimings::total_s,
                      "the whole call: its stages and what lies between them")
        .def("__iter__",
             [](const StageTimings& t) {
                 auto rows = t.stages;
                 rows.emplace_back("total", t.total_s);
                 return py::iter(py::cast(rows));
             })
        .def("__len__", [](const StageTimings& t) { return t.stages.size() + 1; });
}
