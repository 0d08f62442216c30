#pragma once
// ControllerProcess: a real hsmu-controller started by a test (QProcess). start() waits
// (bounded) for its "listening on ADDR:PORT" line and keeps the port, so a restart can take
// the same port again; kill() is SIGKILL, stop() SIGTERM then SIGKILL. Never hangs: every
// wait has a deadline.

#include <QProcess>
#include <QString>
#include <QStringList>

class ControllerProcess {
public:
    /// args: everything but --port (e.g. --config F --pace fast --state S).
    explicit ControllerProcess(QStringList args);
    ~ControllerProcess();

    /// Start on port (0: any free one); false (see log()) if it did not listen within timeout.
    bool start(quint16 port = 0, int timeoutMs = 30000);
    quint16 port() const { return m_port; }
    void kill();
    void stop();
    bool running() const { return m_process.state() != QProcess::NotRunning; }
    qint64 pid() const { return m_process.processId(); }
    /// The process's resident set (VmRSS) and its peak (VmHWM) [kB] from /proc; -1 if unknown.
    long rssKb(bool peak = false) const;
    /// Everything it wrote (stdout and stderr), for failure messages.
    QString log();
    /// Wait (bounded by timeoutMs) until its output contains text; false if it did not.
    bool waitForLog(const QString& text, int timeoutMs = 30000);

private:
    QStringList m_args;
    QProcess m_process;
    quint16 m_port = 0;
    QString m_log;
};
