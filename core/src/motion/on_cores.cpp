#include "on_cores.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace popup::motion {

void run_on_cores(std::size_t tasks, const std::function<void(std::size_t)>& work, bool threaded)
{
    std::atomic<std::size_t> next{0};
    std::mutex error_lock;
    std::exception_ptr error;
    auto take_tasks = [&] {
        for (std::size_t task; (task = next++) < tasks;) {
            try {
                work(task);
            } catch (...) {
                const std::lock_guard<std::mutex> hold(error_lock);
                if (!error)
                    error = std::current_exception();
                next = tasks; // the others stop at their next task
                return;
            }
        }
    };
    const std::size_t threads =
        threaded ? std::min<std::size_t>(tasks, std::max(1u, std::thread::hardware_concurrency()))
                 : 1;
    std::vector<std::thread> helpers;
    for (std::size_t k = 1; k < threads; ++k) {
        try {
            helpers.emplace_back(take_tasks);
        } catch (const std::system_error&) {
            break; // no more threads: those started, and this one, do the rest
        }
    }
    take_tasks();
    for (std::thread& helper : helpers)
        helper.join();
    if (error)
        std::rethrow_exception(error);
}

} // namespace popup::motion
