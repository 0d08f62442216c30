#pragma once
// SignalHold: while it lives, SIGINT and SIGTERM hold the test out of band instead of killing
// the process (docs/cli.md): the handler only writes one byte to a self-pipe
// (async-signal-safe); a watcher thread reads it and calls HybridTest::emergencyHold(), which
// sends the hold to every site at once even while the run loop is blocked in a step. The run
// then ends as held (exit code 2) with its record, CSV and summary written. A second signal
// while the first is handled changes nothing; the destructor restores the previous handlers.
// The other form takes the hold as an action (`hsmu rths --controller`: a hold frame to the
// controller that runs the RTHS loop), called once on the watcher thread with the sentence.
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
    explicit SignalHold(std::function<void(const std::string&)> hold);
    ~SignalHold();
    SignalHold(const SignalHold&) = delete;
    SignalHold& operator=(const SignalHold&) = delete;

    /// Whether a signal held the test (the run loop must not resume it).
    bool signalled() const { return m_signal.load() != 0; }
    /// "SIGINT" or "SIGTERM" once signalled, "" before.
    std::string signalName() const;

private:
    void watch();
    std::function<void(const std::string&)> m_hold;
    int m_pipe[2] = {-1, -1};
    std::atomic<int> m_signal{0};
    std::thread m_watcher;
};

} // namespace hsmu::gui
