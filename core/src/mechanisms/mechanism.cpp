#include "popup/mechanisms/mechanism.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace popup {

void check_part_sizes(const Scaffold& scaffold, const std::string& mechanism,
                      std::initializer_list<std::pair<const char*, double>> lengths,
                      Diagnostics& errors)
{
    const double shortest = shortest_fold(scaffold);
    for (const auto& [parameter, value] : lengths) {
        if (!(value > 0 && value < shortest))
            continue;
        std::ostringstream range;
        range << ">= " << shortest << " mm (the shortest fold on this card: 1e-5 of its size)";
        range_error(errors, mechanism, parameter, value, "mm", range.str());
    }
}

void check_flat_host(const std::string& mechanism, const BasePatchPair& host,
                     const std::string& kind, Diagnostics& errors)
{
    if (std::abs(host.opening - M_PI) <= 1e-9)
        return;
    std::ostringstream m;
    m << mechanism << ": host " << host.name << " is open " << host.opening * 180 / M_PI
      << "° at the design state; " << kind << " needs a host open flat (180°)";
    errors.push_back(Diagnostic::error(DiagnosticCode::bad_host, m.str(), about_parameter("Host")));
}

void check_run(Diagnostics& errors, const std::string& mechanism, const std::string& parameter,
               double value, double limit, const std::string& side, bool inclusive)
{
    if (value > 0 && (inclusive ? value <= limit : value < limit))
        return;
    std::ostringstream range;
    range << "> 0 and " << (inclusive ? "<= " : "< ") << limit << " mm (the depth of the host's "
          << side << ")";
    range_error(errors, mechanism, parameter, value, "mm", range.str());
}

void check_placement(const std::string& mechanism, const BasePatchPair& host, const Placement1D& p,
                     Diagnostics& errors)
{
    std::ostringstream range;
    if (!(p.width > 0 && p.width <= host.length)) {
        range << "> 0 and <= " << host.length << " mm (the length of " << host.name << ")";
        range_error(errors, mechanism, "Width", p.width, "mm", range.str());
        return;
    }
    if (!(p.offset >= 0 && p.offset + p.width <= host.length)) {
        range << ">= 0 and <= " << host.length - p.width << " mm (" << host.name << " is "
              << host.length << " mm long, the mechanism " << p.width << " mm wide)";
        range_error(errors, mechanism, "Offset", p.offset, "mm", range.str());
    }
}

std::vector<std::pair<std::string, std::string>>
placement_conflicts(const std::vector<MechanismParts>& mechanisms)
{
    std::vector<std::pair<std::string, std::string>> conflicts;
    for (size_t i = 0; i < mechanisms.size(); ++i)
        for (size_t j = i + 1; j < mechanisms.size(); ++j) {
            const MechanismParts& a = mechanisms[i];
            const MechanismParts& b = mechanisms[j];
            if (a.host == b.host && a.sweep_from < b.sweep_to && b.sweep_from < a.sweep_to)
                conflicts.push_back({a.name, b.name});
        }
    return conflicts;
}

} // namespace popup
