#include "child_process.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <sstream>

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

namespace popup {

std::string run_in_child(const std::function<std::string()>& work, double timeout_s,
                         std::string& answer)
{
    answer.clear();
    int channel[2];
    if (pipe(channel) != 0)
        return std::string("cannot open a pipe: ") + std::strerror(errno);
    const pid_t child = fork();
    if (child < 0) {
        close(channel[0]);
        close(channel[1]);
        return std::string("cannot start the reader: ") + std::strerror(errno);
    }
    if (child == 0) {
        close(channel[0]);
        std::string bytes;
        try {
            bytes = work();
        } catch (...) {
            _exit(2); // the caller sees no whole answer
        }
        for (size_t at = 0; at < bytes.size();) {
            const ssize_t n = write(channel[1], bytes.data() + at, bytes.size() - at);
            if (n <= 0)
                _exit(1);
            at += size_t(n);
        }
        _exit(0);
    }
    close(channel[1]);
    char buffer[1 << 16];
    const auto deadline =
        std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    bool timed_out = false;
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        pollfd ready{channel[0], POLLIN, 0};
        const int polled = poll(&ready, 1, int(std::max<long>(0, left.count())));
        if (polled < 0 && errno == EINTR)
            continue;
        if (polled == 0) {
            timed_out = true;
            break;
        }
        const ssize_t n = read(channel[0], buffer, sizeof buffer);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break;
        answer.append(buffer, size_t(n));
    }
    close(channel[0]);
    if (timed_out)
        kill(child, SIGKILL);
    int status = 0;
    while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    if (timed_out) {
        std::ostringstream s;
        s << "assimp did not finish reading it within " << timeout_s << " s";
        return s.str();
    }
    if (WIFSIGNALED(status))
        return "assimp crashed reading it (signal " + std::to_string(WTERMSIG(status)) + ", " +
               strsignal(WTERMSIG(status)) + ")";
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return "the reader process ended without a whole answer (exit status " +
               std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")";
    return {};
}

} // namespace popup
