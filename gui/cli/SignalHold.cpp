#include "gui/cli/SignalHold.h"

#include "core/experiment/HybridTest.h"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <string>

namespace hsmu::gui {

namespace {

std::atomic<int> g_writeFd{-1};
struct sigaction g_oldInt, g_oldTerm;

void onSignal(int sig) {
    const int fd = g_writeFd.load();
    if (fd >= 0) {
        const unsigned char b = static_cast<unsigned char>(sig);
        const int saved = errno;
        [[maybe_unused]] const ssize_t n = ::write(fd, &b, 1);
        errno = saved;
    }
}

} // namespace

SignalHold::SignalHold(HybridTest& test)
    : SignalHold([&test](const std::string& why) { test.emergencyHold(why); }) {}

SignalHold::SignalHold(std::function<void(const std::string&)> hold) : m_hold(std::move(hold)) {
    if (::pipe2(m_pipe, O_CLOEXEC | O_NONBLOCK) != 0)
        return; // no out-of-band hold: the default handlers stay
    g_writeFd.store(m_pipe[1]);
    struct sigaction sa;
    std::memset(&sa, 0, sizeof sa);
    sa.sa_handler = onSignal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;
    ::sigaction(SIGINT, &sa, &g_oldInt);
    ::sigaction(SIGTERM, &sa, &g_oldTerm);
    m_watcher = std::thread([this] { watch(); });
}

SignalHold::~SignalHold() {
    if (m_pipe[1] < 0)
        return;
    ::sigaction(SIGINT, &g_oldInt, nullptr);
    ::sigaction(SIGTERM, &g_oldTerm, nullptr);
    g_writeFd.store(-1);
    const unsigned char stop = 0;
    [[maybe_unused]] const ssize_t n = ::write(m_pipe[1], &stop, 1);
    m_watcher.join();
    ::close(m_pipe[0]);
    ::close(m_pipe[1]);
}

std::string SignalHold::signalName() const {
    const int s = m_signal.load();
    return s == SIGINT ? "SIGINT" : s == SIGTERM ? "SIGTERM" : s ? "signal " + std::to_string(s) : "";
}

void SignalHold::watch() {
    for (;;) {
        pollfd p{m_pipe[0], POLLIN, 0};
        if (::poll(&p, 1, -1) < 0) {
            if (errno == EINTR)
                continue;
            return;
        }
        unsigned char b = 0;
        if (::read(m_pipe[0], &b, 1) != 1)
            continue;
        if (b == 0)
            return; // the destructor
        int expected = 0;
        if (m_signal.compare_exchange_strong(expected, int(b)))
            m_hold(signalName() + " received");
    }
}

} // namespace hsmu::gui
