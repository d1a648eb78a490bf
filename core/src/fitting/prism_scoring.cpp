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
    int n = 0;
    for (const Local& q : subset)
        n += classify(m, sec, q, eps, flat) == Where::face;
    if (n * scale <= to_beat)
        return -1;
    std::vector<const Local*> inside;
    for (const Local& q : guard)
        if (classify(m, sec, q, eps, flat) == Where::inside)
            inside.push_back(&q);
    if (inside.size() > 1 && m.kind == Prism::Kind::rectangular && flat) {
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
    if (inside.size() > 1)
        return -1;
    return n * scale;
}

} // namespace popup::prism_search
