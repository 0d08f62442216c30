#pragma once
// ConsoleSettings: what the console remembers between sessions, in QSettings (organization
// "HSMU", application "hsmu"): the main window's geometry and dock layout, the recent
// record folder, the recent configuration files (newest first, at most kMaxRecent, missing files
// dropped on reading), the last controller address ("builtin" or "tcp://HOST:PORT") and the
// language ("" = the system's locale, else a code such as "en", "zh_CN"). Thread rules: GUI thread
// only.

#include <QByteArray>
#include <QString>
#include <QStringList>
#include <QVariantMap>

namespace hsmu::gui {

class ConsoleSettings {
public:
    static constexpr int kMaxRecent = 8;

    static QStringList recentFiles();
    /// Put file first (absolute path), drop duplicates, keep kMaxRecent.
    static void addRecentFile(const QString& file);
    static void clearRecentFiles();

    static QString controllerAddress();
    static void setControllerAddress(const QString& address);

    /// Where each test's HDF5 record goes ("" = not recorded); default: the application's
    /// data folder + "/runs".
    static QString recordDirectory();
    static void setRecordDirectory(const QString& dir);

    static QString language();
    static void setLanguage(const QString& code);

    /// The settings of the last confirmed run of configuration `name` (PreflightChecks).
    static QVariantMap lastRun(const QString& name);
    static void setLastRun(const QString& name, const QVariantMap& settings);

    static QByteArray windowGeometry();
    static QByteArray windowState();
    static void saveWindow(const QByteArray& geometry, const QByteArray& state);
};

} // namespace hsmu::gui
