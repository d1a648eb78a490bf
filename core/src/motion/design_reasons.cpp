#include "design_reasons.hpp"

#include <sstream>

namespace popup::motion {

std::string chain_names(const AnnealProblem& p, const Slot& s)
{
    std::string out;
    for (int j : s.chains)
        out += (out.empty() ? "" : ", ") + p.chains[j].name;
    return out;
}

std::string why_not_shared(const AnnealProblem& p, int j, const Slot& other)
{
    std::ostringstream why;
    const ChainTarget &a = p.chains[j], &b = p.chains[other.chains.front()];
    const double motions = motion_distance(a, b);
    const double apart =
        a.target.empty() || b.target.empty() ? 0.0 : (a.target.back() - b.target.back()).norm();
    if (motions > p.alike_fraction * p.diagonal)
        why << "they move too differently to share a patch (motions " << motions
            << " mm apart, RMS)";
    else if (apart > p.beside_fraction * p.diagonal)
        why << "their parts lie " << apart << " mm apart when open, too far to share a patch";
    else
        why << "they move alike (motions " << motions
            << " mm apart, RMS), but one patch carrying both collides or follows them worse";
    return why.str();
}

} // namespace popup::motion
