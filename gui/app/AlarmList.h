#pragma once
// AlarmList: the alarms and operator events of the current test, newest last: test time [s],
// step, severity, a translated kind and the message, and whether the operator acknowledged it.
// Every message follows a language change: an alarm is shown from its code or its English
// (language-neutral) text, a console message from the data it was made of.
// A critical alarm stays highlighted (red) until acknowledged; attentionChanged() reports how
// many critical alarms are unacknowledged so the window can demand attention.
// The list can be copied (Ctrl+C: the selected rows, or all, as tab-separated text with the
// header) and exported as CSV (its context menu), as shown, in the current language.
// Thread rules: GUI thread only.

#include "core/util/Alarm.h"

#include <QTreeWidget>

#include <functional>
#include <unordered_map>

namespace hsmu::gui {

struct OperatorEvent;

class AlarmList : public QTreeWidget {
    Q_OBJECT
public:
    enum Column { Time, Step, Severity, Kind, Message, Acknowledged, ColumnCount };

    explicit AlarmList(QWidget* parent = nullptr);

    /// acknowledged: the operator caused it (a Stop's hold): listed as acknowledged at once,
    /// no attention demanded.
    void addAlarm(const Alarm& alarm, bool acknowledged = false);
    /// A console message that is not a test alarm (e.g. a configuration error), fixed text.
    void addMessage(const QString& text, AlarmSeverity severity);
    /// A console message made by render() now and again at each language change (render
    /// keeps the language-neutral data and calls tr() / AlarmText each time).
    void addMessage(std::function<QString()> render, AlarmSeverity severity);
    /// The same at test time `time` [s] and step `step` (e.g. "test finished").
    void addMessage(double time, int step, std::function<QString()> render,
                    AlarmSeverity severity);
    /// An operator action at test time `time` [s] and step `step` (kind "operator").
    void addEvent(double time, int step, const QString& text);
    /// An operator event, shown with its time and step and retranslated at each language
    /// change (from its language-neutral record text).
    void addEvent(const OperatorEvent& event);
    /// Remove every entry (a new test).
    void clearAlarms();

    void acknowledgeSelected();
    void acknowledgeAll();
    int unacknowledgedCritical() const { return m_unacknowledged; }

    static QString describe(AlarmKind kind);
    static QString describe(AlarmSeverity severity);

    /// The rows (the selected ones, or every one if none is selected) with the header line,
    /// columns separated by `separator`; a CSV field is quoted when it must be.
    QString rowsText(QChar separator = QLatin1Char('\t'), bool selectedOnly = true) const;
    /// Copy rowsText() to the clipboard.
    void copyRows();
    /// Write every row as CSV (UTF-8) to path; false and *error naming the file on failure.
    bool exportCsv(const QString& path, QString* error = nullptr) const;

signals:
    /// count: unacknowledged critical alarms; latest: the newest one's text (empty if none).
    void attentionChanged(int count, const QString& latest);

private:
    QTreeWidgetItem* add(const QString& time, const QString& step, AlarmSeverity severity,
                         const QString& kind, const QString& text, bool acknowledged = false);
    void retranslate(QTreeWidgetItem* item);
    void acknowledge(QTreeWidgetItem* item);
    void notify();
    void showMenu(const QPoint& at);
    void exportWithDialog();

    int m_unacknowledged = 0;
    std::unordered_map<const QTreeWidgetItem*, std::function<QString()>> m_renders;
};

} // namespace hsmu::gui
