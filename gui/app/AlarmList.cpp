#include "gui/app/AlarmList.h"

#include "gui/app/AlarmText.h"
#include "gui/app/LiveText.h"
#include "gui/app/OperatorEvent.h"

#include <QAction>
#include <QClipboard>
#include <QDateTime>
#include <QFile>
#include <QFileDialog>
#include <QGuiApplication>
#include <QHeaderView>
#include <QMenu>
#include <QMessageBox>

namespace hsmu::gui {

namespace {
constexpr int kSeverityRole = Qt::UserRole;
constexpr int kAckRole = Qt::UserRole + 1;
constexpr int kKindRole = Qt::UserRole + 2;
constexpr int kAckTimeRole = Qt::UserRole + 3;
constexpr int kCodeRole = Qt::UserRole + 4;
constexpr int kArgsRole = Qt::UserRole + 5;
constexpr int kEnglishRole = Qt::UserRole + 6;
constexpr int kEventRole = Qt::UserRole + 7; // an operator event's record text
const QColor kCritical(198, 40, 40);
const QColor kCriticalBackground(255, 205, 210);
const QColor kWarning(200, 120, 0);
} // namespace

AlarmList::AlarmList(QWidget* parent) : QTreeWidget(parent) {
    setObjectName(QStringLiteral("alarmList"));
    setAlternatingRowColors(true);
    setRootIsDecorated(false);
    setSelectionMode(QAbstractItemView::ExtendedSelection);
    setColumnCount(ColumnCount);
    header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    header()->setSectionResizeMode(Message, QHeaderView::Stretch);
    header()->setStretchLastSection(false);
    connect(this, &QTreeWidget::itemDoubleClicked, this, [this](QTreeWidgetItem* item) {
        acknowledge(item);
        notify();
    });
    auto* copy = new QAction(this);
    copy->setObjectName(QStringLiteral("copyAlarms"));
    copy->setShortcut(QKeySequence::Copy);
    copy->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    connect(copy, &QAction::triggered, this, &AlarmList::copyRows);
    addAction(copy);
    setContextMenuPolicy(Qt::CustomContextMenu);
    connect(this, &QWidget::customContextMenuRequested, this, &AlarmList::showMenu);
    // Headers, severities, kinds, acknowledgements and every message again in the new
    // language (an alarm from its code or English text, a console message from its data).
    LiveText::bind(this, [this] {
        setHeaderLabels({tr("Time [s]"), tr("Step"), tr("Severity"), tr("Kind"), tr("Message"),
                         tr("Acknowledged")});
        for (int i = 0; i < topLevelItemCount(); ++i)
            retranslate(topLevelItem(i));
        if (m_unacknowledged > 0)
            notify(); // the banner's latest message, retranslated
    });
}

QString AlarmList::rowsText(QChar separator, bool selectedOnly) const {
    const auto field = [separator](QString text) {
        text.replace(QLatin1Char('\n'), QLatin1Char(' '));
        if (separator == QLatin1Char(',') &&
            (text.contains(QLatin1Char(',')) || text.contains(QLatin1Char('"'))))
            text = QLatin1Char('"') + text.replace(QLatin1String("\""), QLatin1String("\"\"")) +
                   QLatin1Char('"');
        return text;
    };
    QStringList lines, cells;
    for (int c = 0; c < ColumnCount; ++c)
        cells << field(headerItem()->text(c));
    lines << cells.join(separator);
    const bool some = selectedOnly && !selectedItems().isEmpty();
    for (int i = 0; i < topLevelItemCount(); ++i) {
        const QTreeWidgetItem* item = topLevelItem(i);
        if (some && !item->isSelected())
            continue;
        cells.clear();
        for (int c = 0; c < ColumnCount; ++c)
            cells << field(item->text(c));
        lines << cells.join(separator);
    }
    return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

void AlarmList::copyRows() {
    QGuiApplication::clipboard()->setText(rowsText());
}

bool AlarmList::exportCsv(const QString& path, QString* error) const {
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text) ||
        file.write(rowsText(QLatin1Char(','), false).toUtf8()) < 0) {
        if (error)
            *error = tr("%1: cannot be written (%2)").arg(path, file.errorString());
        return false;
    }
    return true;
}

void AlarmList::showMenu(const QPoint& at) {
    auto* menu = new QMenu(this);
    menu->setAttribute(Qt::WA_DeleteOnClose);
    menu->addAction(selectedItems().isEmpty() ? tr("Copy the list") : tr("Copy selected rows"),
                    this, &AlarmList::copyRows);
    menu->addAction(tr("Export the list as CSV..."), this, &AlarmList::exportWithDialog);
    menu->popup(viewport()->mapToGlobal(at));
}

void AlarmList::exportWithDialog() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export alarms and events"),
                                                      QString(), tr("CSV files (*.csv)"));
    if (path.isEmpty())
        return;
    QString error;
    if (!exportCsv(path, &error))
        QMessageBox::warning(this, tr("Export alarms and events"), error);
}

void AlarmList::retranslate(QTreeWidgetItem* item) {
    item->setText(Severity, describe(AlarmSeverity(item->data(Severity, kSeverityRole).toInt())));
    const QVariant kind = item->data(Kind, kKindRole);
    item->setText(Kind, kind.isValid() ? describe(AlarmKind(kind.toInt())) : tr("console"));
    const QVariant ackAt = item->data(Acknowledged, kAckTimeRole);
    if (ackAt.isValid())
        item->setText(Acknowledged, tr("yes, %1").arg(ackAt.toString()));
    else if (!item->data(Acknowledged, kAckRole).toBool())
        item->setText(Acknowledged, tr("no"));
    const QVariant event = item->data(Message, kEventRole);
    if (event.isValid()) {
        if (const auto e = OperatorEvent::fromRecordText(event.toString().toStdString())) {
            const QString text = e->describe();
            item->setText(Message, text);
            item->setToolTip(Message, text);
        }
    }
    if (const auto render = m_renders.find(item); render != m_renders.end()) {
        const QString text = render->second();
        item->setText(Message, text);
        item->setToolTip(Message, text);
    }
    const QVariant english = item->data(Message, kEnglishRole);
    if (english.isValid()) {
        const std::string code = item->data(Message, kCodeRole).toString().toStdString();
        const QString text = AlarmText::describe(
            code, item->data(Message, kArgsRole).toStringList(), english.toString());
        item->setText(Message, text);
        item->setToolTip(Message, text);
    }
}

QString AlarmList::describe(AlarmKind kind) {
    switch (kind) {
    case AlarmKind::LimitExceeded:
        return tr("limit exceeded");
    case AlarmKind::ControlFault:
        return tr("control fault");
    case AlarmKind::ElementFault:
        return tr("element fault");
    case AlarmKind::IntegratorFault:
        return tr("integrator fault");
    case AlarmKind::OperatorHold:
        return tr("operator");
    case AlarmKind::Stability:
        return tr("stability");
    case AlarmKind::FitError:
        return tr("model fit error");
    case AlarmKind::Fracture:
        return tr("fracture");
    case AlarmKind::EstimatorRejected:
        return tr("estimator rejected");
    case AlarmKind::ParameterPinned:
        return tr("parameter at a bound");
    case AlarmKind::TrackingError:
        return tr("actuator tracking");
    case AlarmKind::ModelUpdate:
        return tr("model update");
    }
    return QString::fromLatin1(alarmKindName(kind));
}

QString AlarmList::describe(AlarmSeverity severity) {
    switch (severity) {
    case AlarmSeverity::Info:
        return tr("info");
    case AlarmSeverity::Warning:
        return tr("warning");
    case AlarmSeverity::Critical:
        return tr("critical");
    }
    return {};
}

void AlarmList::addAlarm(const Alarm& alarm, bool acknowledged) {
    QStringList args;
    for (const std::string& a : alarm.args)
        args << QString::fromStdString(a);
    const QString english = QString::fromStdString(alarm.message);
    QTreeWidgetItem* item =
        add(QString::number(alarm.time, 'f', 2), QString::number(alarm.step), alarm.severity,
            describe(alarm.kind), AlarmText::describe(alarm.code, args, english), acknowledged);
    item->setData(Kind, kKindRole, int(alarm.kind));
    item->setData(Message, kCodeRole, QString::fromStdString(alarm.code));
    item->setData(Message, kArgsRole, args);
    item->setData(Message, kEnglishRole, english); // retranslated from it (AlarmText)
}

void AlarmList::addMessage(const QString& text, AlarmSeverity severity) {
    add(QString(), QString(), severity, tr("console"), text);
}

void AlarmList::addMessage(std::function<QString()> render, AlarmSeverity severity) {
    QTreeWidgetItem* item = add(QString(), QString(), severity, tr("console"), render());
    m_renders[item] = std::move(render);
}

void AlarmList::addMessage(double time, int step, std::function<QString()> render,
                           AlarmSeverity severity) {
    QTreeWidgetItem* item = add(QString::number(time, 'f', 2), QString::number(step), severity,
                                tr("console"), render());
    m_renders[item] = std::move(render);
}

void AlarmList::addEvent(double time, int step, const QString& text) {
    add(QString::number(time, 'f', 2), QString::number(step), AlarmSeverity::Info,
        describe(AlarmKind::OperatorHold), text)
        ->setData(Kind, kKindRole, int(AlarmKind::OperatorHold));
}

void AlarmList::addEvent(const OperatorEvent& event) {
    addEvent(event.time, event.step, event.describe());
    topLevelItem(topLevelItemCount() - 1)
        ->setData(Message, kEventRole, QString::fromStdString(event.recordText()));
}

QTreeWidgetItem* AlarmList::add(const QString& time, const QString& step,
                                AlarmSeverity severity, const QString& kind,
                                const QString& text, bool acknowledged) {
    auto* item = new QTreeWidgetItem(this);
    item->setText(Time, time);
    item->setText(Step, step);
    item->setText(Severity, describe(severity));
    item->setText(Kind, kind);
    item->setText(Message, text);
    item->setToolTip(Message, text);
    item->setData(Severity, kSeverityRole, int(severity));
    const bool critical = severity == AlarmSeverity::Critical;
    item->setData(Acknowledged, kAckRole, !critical);
    item->setText(Acknowledged, critical ? tr("no") : QString());
    for (int c = 0; c < ColumnCount; ++c) {
        if (critical) {
            item->setForeground(c, kCritical);
            item->setBackground(c, kCriticalBackground);
        } else if (severity == AlarmSeverity::Warning) {
            item->setForeground(c, kWarning);
        }
    }
    scrollToItem(item);
    if (critical) {
        ++m_unacknowledged;
        if (acknowledged)
            acknowledge(item); // the operator's own doing: no banner
        else
            notify();
    }
    return item;
}

void AlarmList::acknowledge(QTreeWidgetItem* item) {
    if (!item || item->data(Acknowledged, kAckRole).toBool())
        return;
    item->setData(Acknowledged, kAckRole, true);
    const QString at = QDateTime::currentDateTime().toString(QStringLiteral("HH:mm:ss"));
    item->setData(Acknowledged, kAckTimeRole, at);
    item->setText(Acknowledged, tr("yes, %1").arg(at));
    for (int c = 0; c < ColumnCount; ++c)
        item->setBackground(c, QBrush());
    --m_unacknowledged;
}

void AlarmList::acknowledgeSelected() {
    for (QTreeWidgetItem* item : selectedItems())
        acknowledge(item);
    notify();
}

void AlarmList::acknowledgeAll() {
    for (int i = 0; i < topLevelItemCount(); ++i)
        acknowledge(topLevelItem(i));
    notify();
}

void AlarmList::clearAlarms() {
    m_renders.clear();
    clear();
    m_unacknowledged = 0;
    notify();
}

void AlarmList::notify() {
    QString latest;
    for (int i = topLevelItemCount() - 1; i >= 0 && m_unacknowledged > 0; --i) {
        const QTreeWidgetItem* item = topLevelItem(i);
        if (!item->data(Acknowledged, kAckRole).toBool()) {
            latest = item->text(Message);
            break;
        }
    }
    emit attentionChanged(m_unacknowledged, latest);
}

} // namespace hsmu::gui
