#pragma once
// Internal: a candidate prism judged against the samples: its score (estimated inliers, refused
// when it encloses the model), its growth along the hinge and its local refit.
#include <vector>

#include <Eigen/Geometry>

#include "popup/fitting/prism_types.hpp"
#include "popup/fitting/surface_samples.hpp"
#include "prism_faces.hpp"

namespace popup::prism_search {

/// A candidate and its score.
struct Scored {
    Prism prism;
    double score = -1; ///< estimated inliers among the remaining samples
};

/// The samples a search runs over, and what it does with a candidate prism.
class Search {
public:
    Search(const SurfaceSamples& samples, const RansacOptions& o);

    /// Every sample in host `h`'s coordinates.
    std::vector<Local> locals(const PrismHost& h) const;

    /// Estimated inliers of m among `subset` (remaining samples above its host, in its host's
    /// coordinates, sorted along the hinge; those that may carry m's faces suffice), or -1 when it
    /// encloses a sample of `guard` (all samples above the host, sorted along the hinge) deeper
    /// than ε. Candidates not beating `to_beat` are not guarded (they cannot become the best): most
    /// draws stop after the subset.
    double score(const Prism& m, const std::vector<Local>& subset, const std::vector<Local>& guard,
                 bool flat, double scale, double to_beat) const;

    /// True when m encloses more than one sample of `guard` (sorted along the hinge) deeper
    /// than ε, the room under a raised model aside.
    bool encloses(const Prism& m, const Section& sec, const std::vector<Local>& guard,
                  bool flat) const;

    /// Grows the prism along the hinge over the samples that carry its top, sides or slopes
    /// without a gap wider than `gap`: two or four points fix the section, not the length.
    /// `subset` needs only the scoring subset's samples that may_carry_box (a rectangular
    /// prism) or may_carry_slope (a triangular one), in any order.
    void extend_along(Prism& m, const std::vector<Local>& subset, double gap,
                      const PrismHost& h) const;

    /// Local optimisation: each face moves to the median of its inliers, slopes to their
    /// least-squares lines.
    void refit(Prism& m, const std::vector<Local>& l, const std::vector<int>& subset,
               const PrismHost& h) const;

private:
    const SurfaceSamples& s_;
    const RansacOptions& o_;
    Eigen::AlignedBox3d box_; ///< the samples' bounding box (card frame)
};

} // namespace popup::prism_search
