#include "prism_scoring.hpp"

#include <algorithm>
#include <cmath>

namespace popup::prism_search {

Search::Search(const SurfaceSamples& samples, const RansacOptions& o) : s_(samples), o_(o)
{
    for (const Vec3& p : samples.points)
        box_.extend(p);
}

std::vector<Local> Search::locals(const PrismHost& h) const
{
    std::vector<Local> out(s_.points.size());
    for (size_t i = 0; i < out.size(); ++i)
        out[i] = to_local(h, s_.points[i], s_.normals[i]);
    return out;
}

double Search::score(const Prism& m, const std::vector<Local>& subset,
                     const std::vector<Local>& guard, bool flat, double scale, double to_beat) const
{
    const Section sec = section_of(m);
    const double eps = o_.threshold;
    // Only samples within ε of the prism's stretch along the hinge can lie on a face; a
    // candidate that cannot beat `to_beat` even if all of them did stops early.
    const auto [first, last] = stretch(subset, m.a0 - eps, m.a1 + eps);
    int n = 0;
    for (const Local* q = first; q != last;) {
        if (double(n + (last - q)) * scale <= to_beat)
            return -1;
        const Local* block = q + std::min<std::ptrdiff_t>(64, last - q);
        for (; q != block; ++q)
            n += classify(m, sec, *q, eps, flat) == Where::face;
    }
    if (n * scale <= to_beat)
        return -1;
    return encloses(m, sec, guard, flat) ? -1 : n * scale;
}

bool Search::encloses(const Prism& m, const Section& sec, const std::vector<Local>& guard,
                      bool flat) const
{
    const double eps = o_.threshold;
    const bool on_page = m.kind == Prism::Kind::rectangular && flat;
    // Inside means deeper than ε within the prism's stretch.
    const auto [first, last] = stretch(guard, m.a0 + eps, m.a1 - eps);
    std::vector<const Local*> inside;
    int high = 0; // inside and above the box's half height: never the room under a model
    for (const Local* q = first; q != last; ++q) {
        if (classify(m, sec, *q, eps, flat) != Where::inside)
            continue;
        inside.push_back(q);
        if (!on_page || q->t > 0.5 * m.height + eps)
            ++high;
        if (high > 1)
            return true;
    }
    if (inside.size() > 1 && on_page) {
        // A box fold stands on its page: under a model that floats on legs or wheels (a
        // truck's chassis) it fills the room below the model's underside. What it encloses
        // there is the legs' side, not the model's inside, as long as the underside lies in
        // the box's lower half (docs/DESIGN.md, "Boxes under a raised model").
        double floor = -1e300;
        for (const Local* q : inside)
            if (q->nt < -kNormalAgreement)
                floor = std::max(floor, q->t);
        if (floor > 0 && floor <= 0.5 * m.height)
            inside.erase(std::remove_if(inside.begin(), inside.end(),
                                        [&](const Local* q) { return q->t <= floor + eps; }),
                         inside.end());
    }
    return inside.size() > 1;
}

} // namespace popup::prism_search
