#include "child_process.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
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
        // Its length first, so the caller makes room once (a 4,500-frame capture is 48 MB).
        auto write_all = [&](const char* data, size_t size) {
            for (size_t at = 0; at < size;) {
                const ssize_t n = write(channel[1], data + at, size - at);
                if (n <= 0)
                    _exit(1);
                at += size_t(n);
            }
        };
        const std::uint64_t length = bytes.size();
        write_all(reinterpret_cast<const char*>(&length), sizeof length);
        write_all(bytes.data(), bytes.size());
        _exit(0);
    }
    close(channel[1]);
    const auto deadline =
        std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    bool timed_out = false;
    // Up to `room` bytes into `into`: how many (0 at the end or on an error), -1 past the deadline.
    auto read_some = [&](char* into, size_t room) -> long {
        for (;;) {
            const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
                deadline - std::chrono::steady_clock::now());
            pollfd ready{channel[0], POLLIN, 0};
            const int polled = poll(&ready, 1, int(std::max<long>(0, left.count())));
            if (polled < 0 && errno == EINTR)
                continue;
            if (polled == 0)
                return -1;
            const ssize_t n = read(channel[0], into, room);
            if (n < 0 && errno == EINTR)
                continue;
            return n < 0 ? 0 : long(n);
        }
    };
    // The answer's length first, so that it is read straight into place once.
    std::uint64_t length = 0;
    size_t got = 0;
    while (got < sizeof length) {
        const long n = read_some(reinterpret_cast<char*>(&length) + got, sizeof length - got);
        timed_out = n < 0;
        if (n <= 0)
            break;
        got += size_t(n);
    }
    if (got == sizeof length) {
        // A few GB at most: a length beyond that is not our child's; the answer then grows.
        answer.resize(length < (std::uint64_t(1) << 32) ? size_t(length) : size_t(1) << 16);
        size_t at = 0;
        for (;;) {
            if (at == answer.size())
                answer.resize(2 * answer.size() + (1 << 16));
            const long n = read_some(answer.data() + at, answer.size() - at);
            timed_out = n < 0;
            if (n <= 0)
                break;
            at += size_t(n);
        }
        answer.resize(at);
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
