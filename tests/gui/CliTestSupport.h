#pragma once
// Shared by the command-line tests: start the hsmu executable (QProcess, bounded), read its
// outputs (JSON, CSV lines, CSV as numbers) and judge a PNG as drawn (not blank).

#include <QFile>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSet>
#include <QString>
#include <QStringList>

#include <vector>

namespace clitest {

struct Result {
    int exitCode = -1;
    QString out, err;
};

/// env: variables added to the test's own environment for this run.
inline Result hsmu(const QStringList& args, int timeoutMs = 120000,
                   const QList<QPair<QString, QString>>& env = {}) {
    QProcess p;
    if (!env.isEmpty()) {
        QProcessEnvironment e = QProcessEnvironment::systemEnvironment();
        for (const auto& [name, value] : env)
            e.insert(name, value);
        p.setProcessEnvironment(e);
    }
    p.start(QStringLiteral(HSMU_EXE), args);
    Result r;
    if (!p.waitForFinished(timeoutMs)) {
        p.kill();
        p.waitForFinished();
        r.err = QStringLiteral("timeout");
        return r;
    }
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2; // -2: crashed
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

inline QString report(const Result& r) {
    return QStringLiteral("exit %1\nstdout:\n%2\nstderr:\n%3").arg(r.exitCode).arg(r.out, r.err);
}

inline QJsonObject readJson(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(f.readAll()).object();
}

inline QStringList readLines(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly | QIODevice::Text))
        return {};
    QStringList lines = QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'));
    if (!lines.isEmpty() && lines.back().isEmpty())
        lines.removeLast();
    return lines;
}

/// A PNG that exists, has a plot's size and is drawn on: several colours and enough ink.
inline QString blankReason(const QString& path) {
    const QImage image(path);
    if (image.isNull())
        return path + QStringLiteral(": missing or unreadable");
    if (image.width() < 400 || image.height() < 250)
        return path + QStringLiteral(": too small");
    QSet<QRgb> colours;
    qsizetype inked = 0;
    for (int y = 0; y < image.height(); y += 2)
        for (int x = 0; x < image.width(); x += 2) {
            const QRgb c = image.pixel(x, y);
            colours.insert(c & 0xF0F0F0); // coarse: ignore antialiasing shades
            inked += c != qRgb(255, 255, 255);
        }
    if (colours.size() < 4)
        return path + QStringLiteral(": %1 colours").arg(colours.size());
    if (inked <= image.width() * image.height() / 400)
        return path + QStringLiteral(": almost blank");
    return {};
}

} // namespace clitest
