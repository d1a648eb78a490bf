#pragma once
#include <atomic>
#include <stdexcept>
#include <string>

namespace popup {

/// Set from another thread (a Cancel button while a worker thread runs the call) to stop a long
/// core call at its next checkpoint. The caller owns it and keeps it alive for the call.
class CancelFlag {
public:
    void cancel() { cancelled_.store(true, std::memory_order_relaxed); }
    bool cancelled() const { return cancelled_.load(std::memory_order_relaxed); }

private:
    std::atomic<bool> cancelled_{false};
};

/// Thrown at a checkpoint once the flag is set: the call gives up and returns nothing.
class Cancelled : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// A checkpoint: throws Cancelled naming `work` when `flag` is set (no flag: never).
inline void stop_if_cancelled(const CancelFlag* flag, const std::string& work)
{
    if (flag && flag->cancelled())
        throw Cancelled(work + ": cancelled");
}

} // namespace popup
