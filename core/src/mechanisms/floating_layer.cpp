#include "popup/mechanisms/floating_layer.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "parallel_box.hpp"

namespace popup {

BasePatchPair floating_layer_side(const FloatingLayerParams& p, LayerSide side, double angle)
{
    // The support stays parallel to the backbone, which stays on the host's bisector z; the
    // page turns by angle/2 from z. So the pair opens at angle/2 and its bisector leans angle/4
    // from z toward the page (docs/MATH.md, "A rotation arm on a floating layer's side").
    const double d = angle / 2, sign = side == LayerSide::ground ? 1.0 : -1.0;
    BasePatchPair pair;
    pair.name = side == LayerSide::ground ? "side_ground" : "side_backdrop";
    pair.origin = Vec3(sign * p.support * std::sin(d), p.offset, p.support * std::cos(d));
    pair.axis = Vec3::UnitY();
    pair.up = Vec3(sign * std::sin(d / 2), 0, std::cos(d / 2));
    pair.opening = d;
    pair.length = p.width;
    return pair;
}

Result<MechanismParts> add_floating_layer(Scaffold& scaffold, const BasePatchPair& host,
                                          const FloatingLayerParams& p, const std::string& name)
{
    Result<MechanismParts> r;
    Diagnostics& e = r.diagnostics;
    check_placement(name, host, p, e);
    check_flat_host(name, host, "a floating layer", e);
    const double depth = std::min(host.ground_depth, host.backdrop_depth);
    std::ostringstream smax;
    smax << "> 0 and < " << depth << " mm (the host's depth)";
    if (!(p.support > 0 && p.support < depth))
        range_error(e, name, "Support", p.support, "mm", smax.str());
    if (!(p.height > 0 && p.height <= 2000))
        range_error(e, name, "Height", p.height, "mm", "> 0 and <= 2000 mm");
    if (!(p.overhang >= 0 && p.overhang <= 2000))
        range_error(e, name, "Overhang", p.overhang, "mm", ">= 0 and <= 2000 mm");
    if (e.empty())
        check_part_sizes(scaffold, name,
                         {{"Width", p.width},
                          {"Support", p.support},
                          {"Height", p.height},
                          {"Overhang", p.overhang}},
                         e);
    if (!e.empty()) {
        r.ok = false;
        return r;
    }
    MechanismBuilder m(scaffold, host, name);
    ParallelSection section;
    section.ground = section.backdrop = p.support;
    section.height = p.height;
    section.overhang = p.overhang;
    build_parallel_box(m, p.offset, p.offset + p.width, section);
    return m.finish();
}

} // namespace popup
