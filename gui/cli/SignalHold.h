#pragma once
// SignalHold: while it lives, SIGINT and SIGTERM hold the test out of band instead of killing
// the process (docs/cli.md): the handler only writes one byte to a self-pipe
// (async-signal-safe); a watcher thread reads it and calls HybridTest::emergencyHold(), which
// sends the hold to every site at once even while the run loop is blocked in a step. The run
// then ends as held (exit code 2) with its record, CSV and summary written. A second signal
// while the first is handled changes nothing; the destructor restores the previous handlers.
// The other constructor calls any action instead (`hsmu replay`: it sets the identification's
// cancel flag), on the watcher thread.
// Thread rules: construct and destroy on the run loop's thread; one instance at a time.

#include <atomic>
#include <functional>
#include <string>
#include <thread>

namespace hsmu {
class HybridTest;
}

namespace hsmu::gui {

class SignalHold {
public:
    explicit SignalHold(HybridTest& test);
    /// action("SIGINT received" / "SIGTERM received") once, on the watcher thread.
    explicit SignalHold(std::function<void(const std::string& reason)> action);
    ~SignalHold();
    SignalHold(const SignalHold&) = delete;
    SignalHold& operator=(const SignalHold&) = delete;

    /// Whether a signal held the test (the run loop must not resume it).
    bool signalled() const { return m_signal.load() != 0; }
    /// "SIGINT" or "SIGTERM" once signalled, "" before.
    std::string signalName() const;

private:
    void watch();
    std::function<void(const std::string&)> m_onSignal;
    int m_pipe[2] = {-1, -1};
    std::atomic<int> m_signal{0};
    std::thread m_watcher;
};

} // namespace hsmu::gui
