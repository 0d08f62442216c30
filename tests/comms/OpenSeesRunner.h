#pragma once
// OpenSeesRunner: the real OpenSees 3.8 + OpenFresco 2.8 of ../shared/tools/opensees (relative
// to the source folder; absent on a user's machine: available() is false and the tests QSKIP
// with reason()). run() writes a Tcl script into a folder, starts the interpreter on it with
// the given stdin text, and waits at most timeoutMs; a run still going then is killed (OpenSees
// spins forever when its server closes; it also exits 0 on script errors, so a run is judged
// by its output files). Also: the table files its recorders write, and their comparison.

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QString>
#include <QStringList>
#include <QTextStream>

#include <cmath>
#include <limits>
#include <vector>

namespace opensees {

inline QString toolsDir() {
    return QDir(QStringLiteral(HSMU_SOURCE_DIR "/../shared/tools/opensees")).absolutePath();
}
inline QString interpreter() {
    return toolsDir() + QStringLiteral("/opensees");
}
inline bool available() {
    return QFileInfo(interpreter()).isExecutable();
}
inline QString reason() {
    return QStringLiteral("the real OpenSees is not at ") + interpreter() +
           QStringLiteral(" (../shared/tools/opensees; present in CI)");
}
/// El Centro 1940 N-S, one column in g at 0.02 s (the tools' example record).
inline QString elCentro() {
    return toolsDir() + QStringLiteral("/examples/elcentro_NS_accel_g.txt");
}

struct Result {
    bool finished = false; ///< exited before the timeout
    QString output;        ///< stdout and stderr
};

/// Run `script` (Tcl text, saved as dir/name) in the real OpenSees, stdin fed with `input`.
inline Result run(const QString& dir, const QString& name, const QString& script,
                  int timeoutMs = 60000, const QByteArray& input = {}) {
    Result r;
    const QString path = QDir(dir).filePath(name);
    {
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate))
            return r;
        f.write(script.toUtf8());
    }
    QProcess p;
    p.setProcessChannelMode(QProcess::MergedChannels);
    p.setWorkingDirectory(dir);
    p.start(interpreter(), {path});
    if (!p.waitForStarted(30000))
        return r;
    if (!input.isEmpty())
        p.write(input);
    p.closeWriteChannel();
    r.finished = p.waitForFinished(timeoutMs);
    if (!r.finished) {
        p.kill();
        p.waitForFinished(10000);
    }
    r.output = QString::fromUtf8(p.readAll());
    return r;
}

/// The rows of a recorder file (whitespace-separated numbers); empty when missing.
inline std::vector<std::vector<double>> table(const QString& path) {
    std::vector<std::vector<double>> rows;
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly | QIODevice::Text))
        return rows;
    QTextStream in(&f);
    while (!in.atEnd()) {
        const QStringList parts = in.readLine().split(QChar(' '), Qt::SkipEmptyParts);
        if (parts.isEmpty())
            continue;
        std::vector<double> row;
        for (const QString& s : parts)
            row.push_back(s.toDouble());
        rows.push_back(row);
    }
    return rows;
}

/// Largest |a - b| over column `col` of two tables; infinity when their row counts differ or
/// either is empty.
inline double maxDifference(const std::vector<std::vector<double>>& a,
                            const std::vector<std::vector<double>>& b, std::size_t col = 1) {
    if (a.empty() || a.size() != b.size())
        return std::numeric_limits<double>::infinity();
    double worst = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i].size() <= col || b[i].size() <= col)
            return std::numeric_limits<double>::infinity();
        worst = std::max(worst, std::abs(a[i][col] - b[i][col]));
    }
    return worst;
}

/// Largest |x| over column `col`.
inline double peak(const std::vector<std::vector<double>>& a, std::size_t col = 1) {
    double p = 0.0;
    for (const auto& row : a)
        if (row.size() > col)
            p = std::max(p, std::abs(row[col]));
    return p;
}

} // namespace opensees
