#pragma once
// SilentSite: a native-protocol peer for the emergency-hold tests and benchmark. It accepts
// one console, answers the hello and the configure, measures the first `answeredSteps`
// targets (force 0, the target as the measured deformation) and acknowledges their commits,
// then reads the next target and goes silent: a lab whose controller stops answering
// mid-step. Every Hold frame is noted with its arrival time and whether the watched step had
// returned by then (watch()); holds are acknowledged when ackHolds. After a Resume
// (acknowledged) it answers targets again. Plain POSIX sockets on a thread of its own;
// every wait is bounded.

#include "comms/protocol/FrameCodec.h"
#include "comms/protocol/FrameDecoder.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>

class SilentSite {
public:
    using Clock = std::chrono::steady_clock;

    SilentSite(int answeredSteps, bool ackHolds) : m_answered(answeredSteps), m_ackHolds(ackHolds) {
        m_listen = ::socket(AF_INET, SOCK_STREAM, 0);
        const int one = 1;
        ::setsockopt(m_listen, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
        sockaddr_in a{};
        a.sin_family = AF_INET;
        a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        ::bind(m_listen, reinterpret_cast<sockaddr*>(&a), sizeof a);
        ::listen(m_listen, 4);
        socklen_t n = sizeof a;
        ::getsockname(m_listen, reinterpret_cast<sockaddr*>(&a), &n);
        m_port = ntohs(a.sin_port);
        m_thread = std::thread([this] { run(); });
    }
    ~SilentSite() {
        m_stop = true;
        m_thread.join();
        ::close(m_listen);
    }

    std::uint16_t port() const { return m_port; }
    /// The step thread sets *done when its step() returned; read when a Hold arrives.
    void watch(const std::atomic<bool>* done) { m_watched = done; }

    /// Wait (at most `seconds`) until the site has gone silent on a target.
    bool waitSilent(double seconds) { return waitFor(seconds, [this] { return m_silent; }); }
    /// Wait (at most `seconds`) until `count` Hold frames arrived.
    bool waitHolds(int count, double seconds) {
        return waitFor(seconds, [this, count] { return m_holds >= count; });
    }
    int holds() const {
        std::lock_guard lock(m_mu);
        return m_holds;
    }
    /// Whether the watched step had returned when the first Hold arrived.
    bool stepReturnedAtFirstHold() const {
        std::lock_guard lock(m_mu);
        return m_returnedAtHold;
    }
    Clock::time_point firstHoldAt() const {
        std::lock_guard lock(m_mu);
        return m_holdAt;
    }
    int targetsMeasured() const {
        std::lock_guard lock(m_mu);
        return m_measured;
    }

private:
    template <class P> bool waitFor(double seconds, P pred) {
        std::unique_lock lock(m_mu);
        return m_cv.wait_for(lock, std::chrono::duration<double>(seconds), pred);
    }

    void send(int fd, const hsmu::comms::Message& m) {
        std::vector<std::uint8_t> bytes;
        hsmu::comms::encodeFrame(m, m_sequence++, bytes);
        std::size_t at = 0;
        while (at < bytes.size()) {
            const ssize_t k = ::send(fd, bytes.data() + at, bytes.size() - at, MSG_NOSIGNAL);
            if (k <= 0)
                return;
            at += std::size_t(k);
        }
    }

    void handle(int fd, const hsmu::comms::Message& m) {
        using namespace hsmu::comms;
        if (std::holds_alternative<HelloMsg>(m)) {
            HelloAckMsg a;
            a.element = std::get<HelloMsg>(m).element;
            a.description = "silent test site";
            send(fd, a);
        } else if (std::holds_alternative<ConfigureMsg>(m)) {
            send(fd, AckMsg{MessageType::Configure, m_committed});
        } else if (const auto* t = std::get_if<TargetMsg>(&m)) {
            std::lock_guard lock(m_mu);
            if (m_measured >= m_answered && !m_resumed) {
                m_silent = true; // read, never answered
                m_cv.notify_all();
                return;
            }
            ++m_measured;
            MeasurementMsg mm;
            mm.step = t->step;
            mm.deformation = t->deformation;
            mm.commanded = t->deformation;
            send(fd, mm);
        } else if (const auto* c = std::get_if<CommitMsg>(&m)) {
            m_committed = c->step;
            send(fd, AckMsg{MessageType::Commit, m_committed});
        } else if (std::holds_alternative<HoldMsg>(m)) {
            {
                std::lock_guard lock(m_mu);
                if (m_holds++ == 0) {
                    m_holdAt = Clock::now();
                    m_returnedAtHold = m_watched && m_watched->load();
                }
                m_cv.notify_all();
            }
            if (m_ackHolds)
                send(fd, AckMsg{MessageType::Hold, m_committed});
        } else if (std::holds_alternative<ResumeMsg>(m)) {
            {
                std::lock_guard lock(m_mu);
                m_resumed = true;
            }
            send(fd, AckMsg{MessageType::Resume, m_committed});
        }
    }

    void run() {
        int fd = -1;
        while (!m_stop && fd < 0) {
            pollfd p{m_listen, POLLIN, 0};
            if (::poll(&p, 1, 20) > 0)
                fd = ::accept(m_listen, nullptr, nullptr);
        }
        if (fd < 0)
            return;
        const int one = 1;
        ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
        hsmu::comms::FrameDecoder decoder;
        std::uint8_t buf[4096];
        while (!m_stop) {
            pollfd p{fd, POLLIN, 0};
            if (::poll(&p, 1, 20) <= 0)
                continue;
            const ssize_t n = ::recv(fd, buf, sizeof buf, 0);
            if (n <= 0)
                break;
            decoder.append(buf, std::size_t(n));
            hsmu::comms::Frame f;
            while (decoder.next(f) == hsmu::comms::FrameDecoder::Status::Frame)
                handle(fd, f.message);
        }
        ::close(fd);
    }

    int m_listen = -1;
    std::uint16_t m_port = 0;
    const int m_answered;
    const bool m_ackHolds;
    std::uint32_t m_sequence = 1;
    std::uint64_t m_committed = 0;
    const std::atomic<bool>* m_watched = nullptr;
    std::atomic<bool> m_stop{false};
    mutable std::mutex m_mu;
    std::condition_variable m_cv;
    int m_measured = 0, m_holds = 0;
    bool m_silent = false, m_resumed = false, m_returnedAtHold = false;
    Clock::time_point m_holdAt{};
    std::thread m_thread;
};
