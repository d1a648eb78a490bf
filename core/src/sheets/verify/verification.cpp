#include "verification.hpp"

#include <algorithm>
#include <sstream>

namespace popup::sheets {

Verification::Verification(const Scaffold& s, const VerifyOptions& chosen, Diagnostics& found)
    : design(s), options(chosen), findings(found), tolerance(1e-6 * s.size())
{
}

void Verification::error(DiagnosticCode code, const std::string& message, std::vector<int> patches)
{
    findings.push_back(Diagnostic::error(code, message, about_patches(std::move(patches))));
}

const Hinge& Verification::hinge(int id) const
{
    return *std::find_if(design.hinges.begin(), design.hinges.end(),
                         [&](const Hinge& h) { return h.id == id; });
}

int Verification::piece_of(int patch) const
{
    for (size_t k = 0; k < pieces.size(); ++k)
        if (pieces[k].local.has(patch))
            return int(k);
    return -1;
}

bool Verification::joint_inside(int patch, const Hinge& h) const
{
    const int k = piece_of(patch);
    if (k < 0)
        return false;
    const LocalPiece& local = pieces[size_t(k)].local;
    const Vec2 a = local.flat_point(design, patch, h.from),
               b = local.flat_point(design, patch, h.to);
    const Vec2 across = left_normal((b - a).normalized());
    double lowest = 0.0, highest = 0.0;
    for (const Vec2& p : local.outline(patch)) {
        lowest = std::min(lowest, across.dot(p - a));
        highest = std::max(highest, across.dot(p - a));
    }
    return lowest < -tolerance && highest > tolerance;
}

std::string at(const Vec2& p)
{
    std::ostringstream s;
    s.precision(6);
    s << "(" << p.x() << ", " << p.y() << ")";
    return s.str();
}

const char* layer(FoldDirection d)
{
    return d == FoldDirection::mountain ? "MOUNTAIN" : "VALLEY";
}

std::string patch_name(const Scaffold& s, int id)
{
    const Patch* p = s.find_patch(id);
    return "'" + (p ? p->name : std::string("?")) + "' (" + std::to_string(id) + ")";
}

} // namespace popup::sheets
