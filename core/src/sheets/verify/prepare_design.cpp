#include "prepare_design.hpp"

#include <algorithm>

#include "../assembly_order.hpp"
#include "popup/sheets/pieces.hpp"

namespace popup::sheets {

bool prepare_design(Verification& v, Result<RoundTrip>& r)
{
    const Scaffold& s = v.design;
    const auto groups = cut_pieces(s);
    Diagnostics order_notes;
    const std::vector<int> order = assembly_order(s, groups, order_notes);
    for (const auto& [id, side] : v.options.printed_sides) {
        const bool known = id.size() > 1 && id[0] == 'P' &&
                           id.find_first_not_of("0123456789", 1) == std::string::npos &&
                           std::stoul(id.substr(1)) >= 1 &&
                           std::stoul(id.substr(1)) <= order.size();
        if (!known)
            r.fail(DiagnosticCode::bad_option,
                   "printed side of " + id + ": there is no such piece; the pieces are P1 to P" +
                       std::to_string(order.size()),
                   about_parameter("printed_sides"));
    }
    if (!r.ok)
        return false;
    for (int g : order) {
        PieceCheck piece;
        piece.id = "P" + std::to_string(v.pieces.size() + 1);
        const auto side = v.options.printed_sides.find(piece.id);
        const bool back =
            side != v.options.printed_sides.end() && side->second == PrintedSide::back;
        Result<LocalPiece> flat = lay_flat(s, groups[g], 1e-6 * std::max(s.size(), 1.0), back);
        if (!flat.ok) {
            r.fail_with(flat.diagnostics);
            return false;
        }
        piece.local = std::move(flat.value);
        v.pieces.push_back(std::move(piece));
    }
    v.angles = sweep_angles(s, v.options.angles);
    for (int k = 0; k < v.options.angles; ++k)
        v.asked.push_back(s.design_angle * (1.0 - double(k) / (v.options.angles - 1)));
    SimulationOptions simulation;
    simulation.cancel = v.options.cancel;
    v.designed = simulate_fold(s, v.angles, simulation);
    if (!v.designed.ok) {
        r.fail(DiagnosticCode::round_trip_failed,
               "the design does not simulate: " + (v.designed.diagnostics.empty()
                                                       ? std::string("no reason given")
                                                       : v.designed.diagnostics.front().message));
        return false;
    }
    v.bends = sample_bends(s, v.designed.value.states);
    return true;
}

} // namespace popup::sheets
