#include "popup/mechanisms/designed_mechanism.hpp"

#include <cmath>
#include <stdexcept>

namespace popup {

DesignedMechanism DesignedMechanism::of_kind(MechanismKind kind, std::string name, std::string host)
{
    DesignedMechanism m;
    m.kind = kind;
    m.params = catalogue_entry(kind).defaults;
    m.name = std::move(name);
    m.host = std::move(host);
    return m;
}

namespace {

const ParameterField& field_of(const DesignedMechanism& m, const std::string& field)
{
    const CatalogueEntry& entry = catalogue_entry(m.kind);
    const ParameterField* f = entry.field(field);
    if (!f)
        throw std::out_of_range(m.name + ": a " + entry.title + " has no parameter " + field);
    return *f;
}

} // namespace

double DesignedMechanism::value(const std::string& field) const
{
    return field_of(*this, field).get(params);
}

std::map<std::string, double> DesignedMechanism::parameter_values() const
{
    std::map<std::string, double> values;
    for (const ParameterField& f : catalogue_entry(kind).fields)
        values[f.name] = f.get(params);
    return values;
}

const std::string& DesignedMechanism::kind_name() const
{
    return catalogue_entry(kind).name;
}

void DesignedMechanism::set_value(const std::string& field, double value)
{
    field_of(*this, field).set(params, value);
}

double DesignedMechanism::offset() const
{
    return catalogue_entry(kind).field("offset") ? value("offset") : 0.0;
}

double DesignedMechanism::extent() const
{
    if (kind == MechanismKind::v_fold) {
        const VFoldParams& v = as<VFoldParams>();
        return v.spine * std::cos(v.spine_angle);
    }
    return catalogue_entry(kind).field("width") ? value("width") : 0.0;
}

Result<MechanismParts> add_mechanism(Scaffold& scaffold, const BasePatchPair& host,
                                     const DesignedMechanism& m)
{
    const CatalogueEntry& entry = catalogue_entry(m.kind);
    if (m.params.index() != entry.defaults.index()) {
        Result<MechanismParts> r;
        r.fail(DiagnosticCode::bad_parameter, m.name + ": a " + entry.title + " needs " +
                                                  entry.params +
                                                  ", not the parameters of another kind");
        return r;
    }
    return entry.generate(scaffold, host, m.params, m.name);
}

} // namespace popup
