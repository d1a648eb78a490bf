#pragma once
// What each stage of a pipeline took, and the whole call: the automatic designs (fit_design,
// design_motion) hand it back, and report.json's timings_s is made from it.
#include <string>
#include <utility>
#include <vector>

namespace popup {

struct StageTimings {
    std::vector<std::pair<std::string, double>> stages; ///< stage -> seconds, in order
    double total_s = 0.0; ///< the whole call: its stages and what lies between them

    void add(std::string stage, double seconds) { stages.emplace_back(std::move(stage), seconds); }
    /// The stages' seconds added up (at most total_s).
    double stages_s() const
    {
        double sum = 0.0;
        for (const auto& stage : stages)
            sum += stage.second;
        return sum;
    }
};

} // namespace popup
