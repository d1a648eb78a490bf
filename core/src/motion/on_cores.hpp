#pragma once
#include <cstddef>
#include <functional>

namespace popup::motion {

/// Runs work(task) once for each task in 0..tasks-1, shared out among the machine's cores (the
/// calling thread among them; one thread when `threaded` is false). Tasks must not depend on
/// each other's order. The first exception a task throws is rethrown once every thread ended,
/// the tasks not yet begun then skipped; a thread that cannot be started leaves its tasks to
/// the others.
void run_on_cores(std::size_t tasks, const std::function<void(std::size_t)>& work,
                  bool threaded = true);

} // namespace popup::motion
