#include "core/record/RecordProbe.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <exception>

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

namespace hsmu {

namespace {

void writeAll(int fd, const std::string& s) {
    const char* p = s.data();
    std::size_t left = s.size();
    while (left > 0) {
        const ssize_t n = ::write(fd, p, left);
        if (n <= 0 && errno != EINTR)
            return;
        if (n > 0) {
            p += n;
            left -= std::size_t(n);
        }
    }
}

} // namespace

std::optional<std::string> probeRecord(const std::string& path, double deadline,
                                       const std::function<void(const std::string&)>& read) {
    int fds[2];
    if (::pipe(fds) != 0)
        return path + ": cannot check the record (pipe: " + std::strerror(errno) + ")";
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        return path + ": cannot check the record (fork: " + std::strerror(errno) + ")";
    }
    if (pid == 0) { // the child: read, report, _exit (never return into the caller)
        ::close(fds[0]);
        int code = 0;
        try {
            read(path);
        } catch (const std::exception& e) {
            writeAll(fds[1], e.what());
            code = 1;
        } catch (...) {
            writeAll(fds[1], path + ": damaged record (unknown error)");
            code = 1;
        }
        ::_exit(code);
    }
    ::close(fds[1]);
    using Clock = std::chrono::steady_clock;
    const auto end = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                        std::chrono::duration<double>(deadline));
    std::string message;
    bool eof = false, timedOut = false;
    while (!eof) {
        const auto left =
            std::chrono::duration_cast<std::chrono::milliseconds>(end - Clock::now()).count();
        if (left <= 0) {
            timedOut = true;
            break;
        }
        pollfd p{fds[0], POLLIN, 0};
        const int r = ::poll(&p, 1, int(std::min<long long>(left, 1000)));
        if (r < 0 && errno != EINTR)
            break;
        if (r <= 0)
            continue;
        char buf[512];
        const ssize_t n = ::read(fds[0], buf, sizeof buf);
        if (n > 0)
            message.append(buf, std::size_t(n));
        else if (n == 0 || errno != EINTR)
            eof = true;
    }
    ::close(fds[0]);
    if (timedOut)
        ::kill(pid, SIGKILL);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    char buf[160];
    if (timedOut) {
        std::snprintf(buf, sizeof buf,
                      ": damaged record (reading it did not finish within %g s)", deadline);
        return path + buf;
    }
    if (WIFSIGNALED(status)) {
        std::snprintf(buf, sizeof buf, ": damaged record (the reader crashed with signal %d)",
                      WTERMSIG(status));
        return path + buf;
    }
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0)
        return std::nullopt;
    return message.empty() ? path + ": damaged record (the reader failed)" : message;
}

} // namespace hsmu
