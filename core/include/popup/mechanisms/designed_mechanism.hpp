#pragma once
// A mechanism as an automatic design states it: its kind, its typed parameters, the base patch
// pair it stands on and its name. What the pipelines pass between their stages and hand the
// Workbench; built on a scaffold by the catalogue's generator of its kind.
#include <map>
#include <string>

#include "popup/mechanisms/mechanism_catalogue.hpp"

namespace popup {

struct DesignedMechanism {
    MechanismKind kind = MechanismKind::box_fold;
    MechanismParams params = BoxFoldParams{};
    std::string host; ///< "central fold" or "<other name>.<part>"
    std::string name; ///< its name; the pairs it offers are "<name>.<part>"

    /// The mechanism of `kind` with its params struct's initial values.
    static DesignedMechanism of_kind(MechanismKind kind, std::string name = {},
                                     std::string host = {});

    /// Its params as the struct of its kind (std::bad_variant_access for another struct).
    template <class Params> Params& as() { return std::get<Params>(params); }
    template <class Params> const Params& as() const { return std::get<Params>(params); }

    /// A field by the catalogue's name, as a double (mm, radians, 0/1); std::out_of_range
    /// naming it when its kind has no such field.
    double value(const std::string& field) const;
    /// Every field of its kind by name (reports, the bindings' dict, tests).
    std::map<std::string, double> parameter_values() const;
    /// "box_fold"...: the catalogue's name of its kind.
    const std::string& kind_name() const;
    void set_value(const std::string& field, double value);
    /// Offset along the host's hinge, and the extent from there (width, or for a v-fold the
    /// spine's run along the hinge; 0 for a kind without one).
    double offset() const;
    double extent() const;
};

/// Builds `m` on `scaffold` standing on `host` with its kind's generator. A params struct that
/// is not its kind's is a bad_parameter error naming both.
Result<MechanismParts> add_mechanism(Scaffold& scaffold, const BasePatchPair& host,
                                     const DesignedMechanism& m);

} // namespace popup
