#pragma once
// Internal: the seconds each stage of fit_design took, appended to FitResult::timings_s.
#include <chrono>
#include <string>

#include "popup/fitting/fit_types.hpp"

namespace popup {

/// Each lap() records the time since the previous lap (or since construction) under a stage.
class StageTimer {
    using Clock = std::chrono::steady_clock;

public:
    explicit StageTimer(FitResult& r) : r_(r), start_(Clock::now()) {}
    void lap(const std::string& stage)
    {
        const auto now = Clock::now();
        r_.timings_s.push_back({stage, std::chrono::duration<double>(now - start_).count()});
        start_ = now;
    }

private:
    FitResult& r_;
    Clock::time_point start_;
};

} // namespace popup
