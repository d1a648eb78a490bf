#pragma once
// Internal: adds a mechanism's patches, hinges and glue to a scaffold, from coordinates in the
// host pair's local frame (x toward the host's ground side, y along its hinge, z up).
#include <string>
#include <vector>

#include "popup/mechanisms/mechanism.hpp"

namespace popup {

class MechanismBuilder {
public:
    MechanismBuilder(Scaffold& scaffold, const BasePatchPair& host, std::string name);

    /// A planar patch from local points (counter-clockwise seen from its printed side).
    int patch(const std::vector<Vec3>& local, PatchRole role, const std::string& part);
    void hinge(int a, int b, const Vec3& local_from, const Vec3& local_to,
               FoldDirection direction = FoldDirection::unspecified);
    /// A hinge where the two patches are on different sheets, joined by a glue tab.
    void tab(int a, int b, const Vec3& local_from, const Vec3& local_to,
             FoldDirection direction = FoldDirection::unspecified);
    void glue(int a, int b);
    Vec3 world(const Vec3& local) const { return host_.to_world(local.x(), local.y(), local.z()); }
    void offer(const BasePatchPair& pair) { parts_.offered.push_back(pair); }
    /// The interval along the host hinge the mechanism occupies over its whole motion.
    void sweeps(double from, double to)
    {
        parts_.sweep_from = from;
        parts_.sweep_to = to;
    }
    const BasePatchPair& host() const { return host_; }
    const std::string& name() const { return parts_.name; }
    /// The parts, after checking that every fold it added lies on both of its patches (a
    /// mechanism too big for its host would not); otherwise everything it added is taken out
    /// again and the error names the fold and the patch.
    Result<MechanismParts> finish();

private:
    Scaffold& scaffold_;
    BasePatchPair host_;
    size_t first_patch_, first_hinge_, first_glue_; ///< what the scaffold had before
    MechanismParts parts_;
};

} // namespace popup
