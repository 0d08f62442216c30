// docs/openfresco.md "Tcl on the OpenSees / OpenFresco side", run verbatim against the real
// OpenSees 3.8 / OpenFresco 2.8 of ../shared/tools/opensees (skipped with the reason where
// absent; present in CI): every block marked <!-- file: NAME --> is written under NAME into a
// folder, every .sh block is run line by line there (hsmu-controller, hsmu and OpenSees are
// the built programs and the interpreter; "&" starts a server in the background; "printf
// '\n\n' | " feeds stdin), then the outputs are checked: the served OpenSees runs equal the
// zeroLength reference, the console's runs equal its built-in run. Every process has a deadline.
#include "OpenSeesRunner.h"

#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <fstream>
#include <map>
#include <memory>
#include <sstream>

namespace {

struct Block {
    QString name, language, text;
};

/// The marked blocks of the page, in order; *unmarked counts the tcl / sh / json fences
/// without a marker (the page must have none in the tested section).
std::vector<Block> markedBlocks(const QString& path, int* unmarked) {
    std::vector<Block> blocks;
    *unmarked = 0;
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly | QIODevice::Text))
        return blocks;
    const QStringList lines = QString::fromUtf8(f.readAll()).split('\n');
    const QRegularExpression marker(QStringLiteral("^<!-- file: (\\S+) -->$"));
    QString pending;
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const QString& line = lines[i];
        if (const auto m = marker.match(line); m.hasMatch()) {
            pending = m.captured(1);
            continue;
        }
        if (!line.startsWith(QStringLiteral("```")) || line.size() <= 3)
            continue;
        Block b{pending, line.mid(3), {}};
        for (++i; i < lines.size() && !lines[i].startsWith(QStringLiteral("```")); ++i)
            b.text += lines[i] + '\n';
        if (b.name.isEmpty()) {
            if (b.language == "tcl" || b.language == "sh" || b.language == "json")
                ++*unmarked;
        } else {
            blocks.push_back(b);
        }
        pending.clear();
    }
    return blocks;
}

[[maybe_unused]] std::vector<std::vector<double>> csvNumbers(const QString& path) {
    std::ifstream in(path.toStdString());
    std::vector<std::vector<double>> rows;
    std::string line;
    std::getline(in, line); // header
    while (std::getline(in, line)) {
        std::vector<double> row;
        std::stringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');)
            row.push_back(std::strtod(cell.c_str(), nullptr));
        rows.push_back(std::move(row));
    }
    return rows;
}

// Used only where hsmu (the console) is built.
[[maybe_unused]] double csvDifference(const std::vector<std::vector<double>>& a,
                                      const std::vector<std::vector<double>>& b) {
    if (a.empty() || a.size() != b.size())
        return INFINITY;
    double worst = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i].size() != b[i].size())
            return INFINITY;
        for (std::size_t c = 0; c < a[i].size(); ++c)
            if (!(std::isnan(a[i][c]) && std::isnan(b[i][c])))
                worst = std::max(worst, std::abs(a[i][c] - b[i][c]));
    }
    return worst;
}

} // namespace

class TestOpenFrescoDoc : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    std::vector<Block> m_blocks;

    QString program(const QString& name) const {
        if (name == "OpenSees")
            return opensees::interpreter();
        if (name == "hsmu-controller")
            return QStringLiteral(HSMU_CONTROLLER_EXE);
#ifdef HSMU_EXE
        if (name == "hsmu")
            return QStringLiteral(HSMU_EXE);
#endif
        return {};
    }

    /// Run the command lines of NAME.sh; the log of every process in *log.
    bool runScript(const QString& name, QString* log) {
        const auto it = std::find_if(m_blocks.begin(), m_blocks.end(),
                                     [&](const Block& b) { return b.name == name; });
        if (it == m_blocks.end()) {
            *log = name + " is not on the page";
            return false;
        }
        std::vector<std::unique_ptr<QProcess>> servers;
        bool ok = true;
        for (QString line : it->text.split('\n', Qt::SkipEmptyParts)) {
            line = line.trimmed();
            QByteArray input;
            if (line.startsWith(QStringLiteral("printf '\\n\\n' | "))) {
                input = "\n\n";
                line = line.mid(QStringLiteral("printf '\\n\\n' | ").size());
            }
            const bool background = line.endsWith('&');
            if (background)
                line.chop(1);
            QStringList args = line.split(' ', Qt::SkipEmptyParts);
            const QString exe = program(args.takeFirst());
            if (exe.isEmpty()) {
                *log += "no program for: " + line + "\n";
                ok = false;
                break;
            }
            auto p = std::make_unique<QProcess>();
            p->setProcessChannelMode(QProcess::MergedChannels);
            p->setWorkingDirectory(m_dir.path());
            p->start(exe, args);
            if (!p->waitForStarted(30000)) {
                *log += "cannot start: " + line + "\n";
                ok = false;
                break;
            }
            if (!input.isEmpty())
                p->write(input);
            p->closeWriteChannel();
            if (background) {
                // Ready when hsmu-controller listens or OpenSees waits for its client.
                QString seen;
                QDeadlineTimer deadline(30000);
                while (!deadline.hasExpired() && !seen.contains("listening on") &&
                       !seen.contains("Waiting for") && p->state() != QProcess::NotRunning)
                    if (p->waitForReadyRead(200))
                        seen += QString::fromUtf8(p->readAll());
                *log += "[" + line + "]\n" + seen;
                servers.push_back(std::move(p));
                continue;
            }
            const bool finished = p->waitForFinished(60000);
            if (!finished)
                p->kill();
            p->waitForFinished(5000);
            *log += "[" + line + "] exit " + QString::number(p->exitCode()) + "\n" +
                    QString::fromUtf8(p->readAll()).right(1500);
            ok = ok && finished && p->exitCode() == 0;
        }
        for (auto& p : servers) {
            // OpenSees servers end on the client's 99; hsmu-controller stops on SIGTERM.
            if (p->program() == QStringLiteral(HSMU_CONTROLLER_EXE))
                p->terminate();
            if (!p->waitForFinished(20000)) {
                p->kill();
                p->waitForFinished(5000);
            }
            *log += QString::fromUtf8(p->readAll()).right(1500);
        }
        return ok;
    }

    std::vector<std::vector<double>> out(const QString& name) {
        return opensees::table(QDir(m_dir.path()).filePath(name));
    }

private slots:
    void initTestCase() {
        if (!opensees::available())
            QSKIP(qPrintable(opensees::reason()));
        QVERIFY(m_dir.isValid());
        // The doc's controllers listen on fixed ports: their default state files go to this
        // run's folder, never a journal left by an earlier run.
        qputenv("XDG_STATE_HOME", m_dir.path().toUtf8());
        int unmarked = 0;
        m_blocks = markedBlocks(QStringLiteral(HSMU_SOURCE_DIR "/docs/openfresco.md"), &unmarked);
        QCOMPARE(unmarked, 0); // every Tcl, shell and JSON block of the page is tested
        QVERIFY(m_blocks.size() >= 14);
        for (const Block& b : m_blocks) {
            QFile f(QDir(m_dir.path()).filePath(b.name));
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(b.text.toUtf8());
        }
        QString log;
        QVERIFY2(runScript("reference.sh", &log), qPrintable(log));
        QCOMPARE(out("reference.out").size(), std::size_t(100));
        QVERIFY2(opensees::peak(out("reference.out")) > 0.02, "the spring yields");
    }

    void servedOpenSeesRunsEqualTheReference_data() {
        QTest::addColumn<QString>("script");
        QTest::addColumn<QString>("output");
        QTest::newRow("genericClient -> simapp") << "generic-client.sh"
                                                 << "generic-client.out";
        QTest::newRow("two-node genericClient -> serverDofs") << "two-node.sh"
                                                              << "two-node.out";
        QTest::newRow("expControl GenericTCP -> generictcp") << "generic-tcp.sh"
                                                             << "generic-tcp.out";
    }

    void servedOpenSeesRunsEqualTheReference() {
        QFETCH(QString, script);
        QFETCH(QString, output);
        QString log;
        QVERIFY2(runScript(script, &log), qPrintable(log));
        const double diff = opensees::maxDifference(out("reference.out"), out(output));
        QVERIFY2(diff <= 1e-12, qPrintable(QString::number(diff) + "\n" + log));
    }

    void consoleRunsEqualTheBuiltInRun_data() {
        QTest::addColumn<QString>("script");
        QTest::addColumn<QString>("folder");
        QTest::addColumn<double>("tolerance");
        QTest::newRow("simapp:// -> startSimAppSiteServer") << "lab-site.sh"
                                                            << "lab-site" << 1e-9;
        // The adapter's penalty, compensated by the console (docs/openfresco.md).
        QTest::newRow("adapter:// -> OpenSees adapter") << "adapter.sh"
                                                        << "adapter" << 1e-9;
    }

    void consoleRunsEqualTheBuiltInRun() {
#ifndef HSMU_EXE
        QSKIP("hsmu (the console) is not built (HSMU_BUILD_GUI off)");
#else
        QFETCH(QString, script);
        QFETCH(QString, folder);
        QFETCH(double, tolerance);
        QProcess builtIn;
        builtIn.setWorkingDirectory(m_dir.path());
        builtIn.start(QStringLiteral(HSMU_EXE), {"run", "sdof.json", "--out", "builtin"});
        QVERIFY(builtIn.waitForFinished(60000) && builtIn.exitCode() == 0);
        QString log;
        QVERIFY2(runScript(script, &log), qPrintable(log));
        const auto a = csvNumbers(m_dir.filePath("builtin/steps.csv"));
        const auto b = csvNumbers(m_dir.filePath(folder + "/steps.csv"));
        QCOMPARE(a.size(), std::size_t(101));
        const double diff = csvDifference(a, b);
        QVERIFY2(diff <= tolerance, qPrintable(QString::number(diff) + "\n" + log));
#endif
    }
};

QTEST_GUILESS_MAIN(TestOpenFrescoDoc)
#include "TestOpenFrescoDoc.moc"
