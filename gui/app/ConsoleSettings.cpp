#include "gui/app/ConsoleSettings.h"

#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>

namespace hsmu::gui {

namespace {
const QString kRecent = QStringLiteral("recentFiles");
const QString kController = QStringLiteral("controllerAddress");
const QString kRecordDir = QStringLiteral("recordDirectory");
const QString kLanguage = QStringLiteral("language");
const QString kGeometry = QStringLiteral("window/geometry");
const QString kState = QStringLiteral("window/state");
} // namespace

QVariantMap ConsoleSettings::lastRun(const QString& name) {
    return QSettings().value(QStringLiteral("lastRun/") + name.toUtf8().toBase64()).toMap();
}

void ConsoleSettings::setLastRun(const QString& name, const QVariantMap& settings) {
    QSettings().setValue(QStringLiteral("lastRun/") + name.toUtf8().toBase64(), settings);
}

QStringList ConsoleSettings::recentFiles() {
    QStringList out;
    for (const QString& f : QSettings().value(kRecent).toStringList())
        if (QFileInfo::exists(f))
            out << f;
    return out;
}

void ConsoleSettings::addRecentFile(const QString& file) {
    const QString path = QFileInfo(file).absoluteFilePath();
    QStringList list = QSettings().value(kRecent).toStringList();
    list.removeAll(path);
    list.prepend(path);
    while (list.size() > kMaxRecent)
        list.removeLast();
    QSettings().setValue(kRecent, list);
}

void ConsoleSettings::clearRecentFiles() {
    QSettings().remove(kRecent);
}

QString ConsoleSettings::controllerAddress() {
    return QSettings().value(kController, QStringLiteral("builtin")).toString();
}

void ConsoleSettings::setControllerAddress(const QString& address) {
    QSettings().setValue(kController, address);
}

QString ConsoleSettings::recordDirectory() {
    const QString fallback =
        QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) +
        QStringLiteral("/runs");
    return QSettings().value(kRecordDir, fallback).toString();
}

void ConsoleSettings::setRecordDirectory(const QString& dir) {
    QSettings().setValue(kRecordDir, dir);
}

QString ConsoleSettings::language() {
    return QSettings().value(kLanguage).toString();
}

void ConsoleSettings::setLanguage(const QString& code) {
    QSettings().setValue(kLanguage, code);
}

QByteArray ConsoleSettings::windowGeometry() {
    return QSettings().value(kGeometry).toByteArray();
}

QByteArray ConsoleSettings::windowState() {
    return QSettings().value(kState).toByteArray();
}

void ConsoleSettings::saveWindow(const QByteArray& geometry, const QByteArray& state) {
    QSettings s;
    s.setValue(kGeometry, geometry);
    s.setValue(kState, state);
}

} // namespace hsmu::gui
