#pragma once
// The frames a card can show (issue 26 item 2; docs/MATH.md, "The frame window").
#include <vector>

#include "popup/motion/linkage_chains.hpp"

namespace popup {

struct FrameWindow {
    int first = 0, last = 0;  ///< the frames shown closed and open flat
    double score = 0.0;       ///< Σ v_j (chord − 2 · retreat), file units (below)
    double whole_score = 0.0; ///< the same for the whole take
    bool chosen = false;      ///< a window was chosen (false: the whole take)
};

/// The contiguous frames whose motion a card can follow best: each chain's tip, against the
/// joint it hangs from and seen along `projection`'s rows (the card's x and y in the file's
/// axes), should travel far from the window's first frame to its last (its chord) and never back
/// (its largest retreat along the chord). Score Σ v_j (chord_j − 2 · retreat_j) over the chains
/// that hang from another; at most about 120 frames are looked at, windows of at least
/// `min_seconds`. The whole take is kept unless a window scores a tenth more.
FrameWindow best_frame_window(const Animation& animation, const std::vector<LinkageChain>& chains,
                              const Eigen::Matrix<double, 2, 3>& projection,
                              double min_seconds = 0.25);

} // namespace popup
