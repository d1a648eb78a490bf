#pragma once
// Internal: the seconds each stage of fit_design took, added to FitResult::timings.
#include <chrono>
#include <string>

#include "popup/fitting/fit_types.hpp"

namespace popup {

/// Each lap() records the time since the previous lap (or since construction) under a stage;
/// finish() the time since construction as the total.
class StageTimer {
    using Clock = std::chrono::steady_clock;

public:
    explicit StageTimer(FitResult& r) : r_(r), begun_(Clock::now()), start_(begun_) {}
    void lap(const std::string& stage)
    {
        const auto now = Clock::now();
        r_.timings.add(stage, seconds(start_, now));
        start_ = now;
    }
    void finish() { r_.timings.total_s = seconds(begun_, Clock::now()); }

private:
    static double seconds(Clock::time_point from, Clock::time_point to)
    {
        return std::chrono::duration<double>(to - from).count();
    }

    FitResult& r_;
    Clock::time_point begun_;
    Clock::time_point start_;
};

} // namespace popup
