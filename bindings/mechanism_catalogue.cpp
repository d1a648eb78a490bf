// Bindings of the mechanism catalogue (core/include/popup/mechanisms/mechanism_catalogue.hpp):
// what the Workbench's registry, parameter tables, offered pairs and part titles read.
#include <map>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "binding_support.hpp"
#include "popup/mechanisms/designed_card.hpp"

namespace py = pybind11;
using namespace popup;

namespace {

const char* unit_name(FieldUnit unit)
{
    switch (unit) {
    case FieldUnit::length:
        return "length";
    case FieldUnit::angle:
        return "angle";
    case FieldUnit::flag:
        return "flag";
    case FieldUnit::count:
        return "count";
    }
    return "length";
}

const char* bound_name(HostBound bound)
{
    switch (bound) {
    case HostBound::none:
        return "none";
    case HostBound::along_hinge:
        return "along_hinge";
    case HostBound::ground_depth:
        return "ground_depth";
    case HostBound::backdrop_depth:
        return "backdrop_depth";
    }
    return "none";
}

const CatalogueEntry& entry_named(const std::string& kind)
{
    if (const CatalogueEntry* e = find_kind(kind))
        return *e;
    std::string known;
    for (const CatalogueEntry& e : mechanism_catalogue())
        known += (known.empty() ? "" : ", ") + e.name;
    throw py::value_error("mechanism kind '" + kind + "' is not in the catalogue (known: " + known +
                          ")");
}

std::vector<std::pair<std::string, std::string>> title_pairs(const std::vector<PartTitle>& parts)
{
    std::vector<std::pair<std::string, std::string>> out;
    for (const PartTitle& p : parts)
        out.emplace_back(p.code, p.title);
    return out;
}

/// {field: value} of a designed mechanism, mm, radians, 0/1 (reports and FreeCAD features).
py::dict parameter_dict(const DesignedMechanism& m)
{
    py::dict out;
    for (const ParameterField& f : catalogue_entry(m.kind).fields)
        out[py::str(f.name)] = f.get(m.params);
    return out;
}

} // namespace

void bind_mechanism_catalogue(py::module_& m)
{
    py::class_<ParameterField>(m, "ParameterField", "One parameter of a mechanism kind")
        .def_readonly("name", &ParameterField::name, "the params struct's field")
        .def_readonly("property", &ParameterField::property, "the FreeCAD feature's property")
        .def_property_readonly(
            "unit", [](const ParameterField& f) { return unit_name(f.unit); },
            "length (mm), angle (radians), flag (0/1) or count")
        .def_readonly("default", &ParameterField::default_value, "a new feature's value")
        .def_readonly("min", &ParameterField::min, "fixed lower bound")
        .def_readonly("max", &ParameterField::max, "fixed upper bound")
        .def_property_readonly(
            "bound", [](const ParameterField& f) { return bound_name(f.bound); },
            "which of the host's sizes bounds it further")
        .def_readonly("range", &ParameterField::range, "the whole range in a maker's words")
        .def_readonly("doc", &ParameterField::doc);
    py::class_<CatalogueEntry>(m, "CatalogueEntry", "One mechanism kind of the catalogue")
        .def_readonly("kind", &CatalogueEntry::name, "box_fold, tent_fold...")
        .def_readonly("feature", &CatalogueEntry::feature, "the FreeCAD feature class")
        .def_readonly("title", &CatalogueEntry::title)
        .def_readonly("params", &CatalogueEntry::params, "the bound params class")
        .def_property_readonly("generator", [](const CatalogueEntry& e) { return "add_" + e.name; })
        .def_readonly("short_name", &CatalogueEntry::short_name)
        .def_readonly("motion", &CatalogueEntry::motion)
        .def_readonly("fields", &CatalogueEntry::fields)
        .def_readonly("offers", &CatalogueEntry::offers, "parts whose base patch pairs it offers")
        .def_property_readonly(
            "fixed",
            [](const CatalogueEntry& e) {
                return std::map<std::string, double>(e.fixed.begin(), e.fixed.end());
            },
            "params members the generator fixes, with their only value")
        .def_property_readonly(
            "parts", [](const CatalogueEntry& e) { return title_pairs(e.parts); },
            "(code, maker title) of each part");
    m.def("mechanism_catalogue", &mechanism_catalogue, py::return_value_policy::reference,
          "Every mechanism kind, in toolbar order.");
    m.def("catalogue_entry", &entry_named, py::arg("kind"), py::return_value_policy::reference,
          "The catalogue's row of a kind (ValueError naming the known kinds otherwise).");
    m.def(
        "part_title",
        [](const std::string& kind, const std::string& code) {
            return part_title(entry_named(kind).kind, code);
        },
        py::arg("kind"), py::arg("code"),
        "What a maker calls part `code` of a mechanism of `kind` (strips FL2... included).");
    m.def(
        "card_part_titles", [] { return title_pairs(card_part_titles()); },
        "(code, maker title) of the card's own parts.");

    py::class_<DesignedMechanism>(m, "DesignedMechanism",
                                  "A mechanism as an automatic design states it")
        .def_property_readonly(
            "kind", [](const DesignedMechanism& d) { return catalogue_entry(d.kind).name; })
        .def_property_readonly(
            "type", [](const DesignedMechanism& d) { return catalogue_entry(d.kind).name; },
            "the kind, as kind")
        .def_readonly("name", &DesignedMechanism::name)
        .def_readonly("host", &DesignedMechanism::host)
        .def_readonly("params", &DesignedMechanism::params, "its kind's params struct")
        .def_property_readonly("parameters", &parameter_dict,
                               "{field: value} in mm and radians, flags 0/1");
    py::class_<FittedMechanism, DesignedMechanism>(m, "FittedMechanism")
        .def_readonly("primitive", &FittedMechanism::primitive)
        .def_readonly("coverage_error", &FittedMechanism::coverage_error);
}
