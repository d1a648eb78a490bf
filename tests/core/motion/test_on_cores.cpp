// run_on_cores: every task runs once, on threads or not, and a task's exception reaches the
// caller after the threads ended.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include "motion/on_cores.hpp"

namespace popup::motion {
namespace {

TEST(OnCores, EveryTaskRunsOnce)
{
    for (bool threaded : {true, false}) {
        std::vector<std::atomic<int>> runs(1000);
        run_on_cores(
            runs.size(), [&](std::size_t task) { ++runs[task]; }, threaded);
        for (const std::atomic<int>& r : runs)
            EXPECT_EQ(r.load(), 1);
    }
    run_on_cores(0, [](std::size_t) { FAIL() << "no task to run"; });
}

TEST(OnCores, ATasksExceptionReachesTheCaller)
{
    for (bool threaded : {true, false}) {
        std::atomic<int> ran{0};
        auto work = [&](std::size_t task) {
            ++ran;
            if (task == 3)
                throw std::runtime_error("task 3 failed");
        };
        EXPECT_THROW(run_on_cores(1000, work, threaded), std::runtime_error);
        if (!threaded) {
            EXPECT_EQ(ran.load(), 4); // the tasks after the failed one were skipped
        }
    }
}

} // namespace
} // namespace popup::motion
