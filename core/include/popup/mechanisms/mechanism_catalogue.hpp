#pragma once
// The mechanism kinds the library builds, listed once: per kind its parameters (name, FreeCAD
// property, unit, default, range, doc), the base patch pairs it offers, its parts' codes and the
// names a maker gives them, and its generator. The pipelines (fitting, motion), the bindings and
// the Workbench (its registry, the features' parameter tables, offered pairs and part titles)
// read this table; a new kind is one generator file and one row (docs/DESIGN.md, "Adding a
// mechanism kind").
#include <functional>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "popup/mechanisms/box_fold.hpp"
#include "popup/mechanisms/floating_layer.hpp"
#include "popup/mechanisms/horizontal_translation.hpp"
#include "popup/mechanisms/rotation_arm.hpp"
#include "popup/mechanisms/step_fold.hpp"
#include "popup/mechanisms/tent_fold.hpp"
#include "popup/mechanisms/v_box_fold.hpp"
#include "popup/mechanisms/v_fold.hpp"

namespace popup {

/// Toolbar order. A vertical translation is the v-box's triangular half (VBoxFoldParams).
enum class MechanismKind {
    tent_fold,
    step_fold,
    v_fold,
    box_fold,
    v_box_fold,
    rotation_arm,
    horizontal_translation,
    vertical_translation,
    floating_layer,
};

/// The parameters of any kind: one alternative per params struct.
using MechanismParams =
    std::variant<TentFoldParams, StepFoldParams, VFoldParams, BoxFoldParams, VBoxFoldParams,
                 RotationArmParams, HorizontalTranslationParams, FloatingLayerParams>;

/// How a parameter is measured: mm, radians (degrees in FreeCAD), a yes/no, a count.
enum class FieldUnit { length, angle, flag, count };

/// Which of the host's sizes bounds a parameter beyond its fixed range (the generator checks
/// it against the actual host and names it in its error).
enum class HostBound {
    none,
    along_hinge,   ///< offset and extent within the host's length
    ground_depth,  ///< below the depth of the host's ground side
    backdrop_depth ///< below the depth of the host's backdrop side
};

/// One parameter of a kind. Values cross as doubles: mm, radians, 0/1 for a flag.
struct ParameterField {
    std::string name;     ///< the params struct's field, e.g. "depth_ground"
    std::string property; ///< the FreeCAD feature's property, e.g. "DepthGround" (stored in files)
    FieldUnit unit = FieldUnit::length;
    double default_value = 0; ///< what a new feature starts with (the Workbench's default)
    double min = 0, max = 0;  ///< fixed bounds, whatever the host (mm, radians, count)
    HostBound bound = HostBound::none;
    std::string range; ///< the whole range as a maker reads it, host bounds included
    std::string doc;   ///< what it is, for the property editor and --help
    std::function<double(const MechanismParams&)> get;
    std::function<void(MechanismParams&, double)> set;
};

/// A part's code as the generator names its patch ("<mechanism>.<code>") and its maker title.
struct PartTitle {
    std::string code;  ///< "TG"
    std::string title; ///< "top, ground side"
};

using MechanismGenerator = std::function<Result<MechanismParts>(
    Scaffold&, const BasePatchPair&, const MechanismParams&, const std::string& name)>;

/// One row of the catalogue.
struct CatalogueEntry {
    MechanismKind kind;
    std::string name;       ///< "box_fold": the kind as the pipelines' results and files name it
    std::string feature;    ///< "BoxFold": the FreeCAD feature (its TYPE is "PopUp::BoxFold")
    std::string title;      ///< "Box fold": menus, property group, findings
    std::string params;     ///< "BoxFoldParams": the bound params class
    std::string short_name; ///< "B": automatic designs number mechanisms B1, B2...
    bool motion = false;    ///< a motion mechanism (thesis §4.3): its own toolbar group
    std::vector<ParameterField> fields; ///< in the task panel's order
    std::vector<std::string> offers;    ///< parts whose base patch pairs it offers, in order
    std::vector<PartTitle> parts;
    MechanismParams defaults; ///< the params struct as a C++ caller gets it (its initialisers)
    MechanismGenerator generate;
    /// Params struct members the generator fixes, with their only value: a design may state them
    /// (a vertical translation's `back` is 0), never with another value.
    std::vector<std::pair<std::string, double>> fixed = {};

    const ParameterField* field(const std::string& field_name) const;
};

/// Every kind, in MechanismKind order.
const std::vector<CatalogueEntry>& mechanism_catalogue();
const CatalogueEntry& catalogue_entry(MechanismKind kind);
/// The entry of "box_fold"..., or nullptr.
const CatalogueEntry* find_kind(const std::string& name);

/// What a maker calls part `code` of a mechanism of `kind`: its title, or for a strip of an end
/// of several panel pairs ("FL2") the title with ", strip 2"; the code itself when unknown.
std::string part_title(MechanismKind kind, const std::string& code);
/// The card's own parts (its two pages).
const std::vector<PartTitle>& card_part_titles();

} // namespace popup
