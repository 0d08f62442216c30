#include "ControllerProcess.h"

#include <QFile>

#include <QDeadlineTimer>
#include <QRegularExpression>

ControllerProcess::ControllerProcess(QStringList args) : m_args(std::move(args)) {
    m_process.setProgram(QStringLiteral(HSMU_CONTROLLER_EXE));
    m_process.setProcessChannelMode(QProcess::MergedChannels);
}

ControllerProcess::~ControllerProcess() {
    stop();
}

bool ControllerProcess::start(quint16 port, int timeoutMs) {
    stop();
    QStringList args = m_args;
    args << QStringLiteral("--port") << QString::number(port);
    // A state file only where the test names one: a restart on the same port must not pick
    // up a default journal (ControllerCommandLine::defaultStateFile) from another run.
    if (!args.contains(QStringLiteral("--state")) && !args.contains(QStringLiteral("--state-file")))
        args << QStringLiteral("--no-state-file");
    m_process.setArguments(args);
    m_process.start();
    if (!m_process.waitForStarted(timeoutMs))
        return false;
    const QRegularExpression re(QStringLiteral("listening on \\S+:(\\d+)"));
    QDeadlineTimer deadline(timeoutMs);
    QString seen;
    while (!deadline.hasExpired()) {
        if (m_process.bytesAvailable() == 0 && !m_process.waitForReadyRead(200)) {
            if (m_process.state() == QProcess::NotRunning)
                break;
            continue;
        }
        while (m_process.canReadLine()) {
            const QString line = QString::fromUtf8(m_process.readLine());
            m_log += line;
            const auto match = re.match(line);
            if (match.hasMatch()) {
                m_port = static_cast<quint16>(match.captured(1).toUInt());
                return true;
            }
        }
    }
    m_log += QString::fromUtf8(m_process.readAll());
    return false;
}

void ControllerProcess::kill() {
    if (m_process.state() == QProcess::NotRunning)
        return;
    m_process.kill(); // SIGKILL
    m_process.waitForFinished(30000);
    m_log += QString::fromUtf8(m_process.readAll());
}

void ControllerProcess::stop() {
    if (m_process.state() == QProcess::NotRunning)
        return;
    m_process.terminate(); // SIGTERM: the controller stops and prints its statistics
    if (!m_process.waitForFinished(10000)) {
        m_process.kill();
        m_process.waitForFinished(10000);
    }
    m_log += QString::fromUtf8(m_process.readAll());
}

QString ControllerProcess::log() {
    m_log += QString::fromUtf8(m_process.readAll());
    return m_log;
}

bool ControllerProcess::waitForLog(const QString& text, int timeoutMs) {
    QDeadlineTimer deadline(timeoutMs);
    while (!log().contains(text)) {
        if (deadline.hasExpired() || m_process.state() == QProcess::NotRunning)
            return log().contains(text);
        m_process.waitForReadyRead(200);
    }
    return true;
}

long ControllerProcess::rssKb(bool peak) const {
    QFile f(QStringLiteral("/proc/%1/status").arg(m_process.processId()));
    if (!f.open(QIODevice::ReadOnly))
        return -1;
    const QByteArray key = peak ? "VmHWM:" : "VmRSS:";
    for (const QByteArray& line : f.readAll().split('\n'))
        if (line.startsWith(key))
            return line.mid(key.size()).trimmed().split(' ').front().toLong();
    return -1;
}
