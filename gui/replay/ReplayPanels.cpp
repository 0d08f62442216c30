#include "gui/replay/ReplayPanels.h"

#include "core/record/RecordData.h"
#include "gui/app/AlarmList.h"
#include "gui/app/AlarmText.h"
#include "gui/app/LiveText.h"
#include "gui/app/OperatorEvent.h"
#include "gui/plots/PlotExporter.h"

#include <QDir>
#include <QFile>
#include <QHeaderView>
#include <QTextStream>
#include <cmath>

#include <qcustomplot.h>

#include <algorithm>

namespace hsmu::gui {

namespace {
QString csvField(QString s) {
    if (s.contains(QLatin1Char(',')) || s.contains(QLatin1Char('"')))
        s = QLatin1Char('"') + s.replace(QLatin1String("\""), QLatin1String("\"\"")) +
            QLatin1Char('"');
    return s;
}
QString q(const std::string& s) {
    return QString::fromStdString(s);
}
} // namespace

ReplayEventList::ReplayEventList(const RecordData& data, QWidget* parent)
    : QTreeWidget(parent), m_data(data) {
    setObjectName(QStringLiteral("replayEvents"));
    setRootIsDecorated(false);
    setAlternatingRowColors(true);
    setColumnCount(ColumnCount);
    header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    header()->setSectionResizeMode(Text, QHeaderView::Stretch);
    header()->setStretchLastSection(false);
    // Entries by step: alarms (index >= 0 into data.alarms) and notes (index < 0: ~note).
    std::vector<std::pair<int, int>> entries; // (step, index)
    for (std::size_t i = 0; i < data.alarms.size(); ++i)
        entries.emplace_back(data.alarms[i].step, int(i));
    for (std::size_t i = 0; i < data.notes.size(); ++i)
        entries.emplace_back(data.notes[i].step, ~int(i));
    std::stable_sort(entries.begin(), entries.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [step, index] : entries) {
        auto* item = new QTreeWidgetItem(this);
        const double time = index >= 0 ? data.alarms[std::size_t(index)].time
                                       : data.notes[std::size_t(~index)].time;
        item->setText(Time, QString::number(time, 'f', 3));
        item->setText(Step, QString::number(step));
        item->setData(Step, Qt::UserRole, step);
        item->setData(Text, Qt::UserRole, index);
    }
    // The record is language-neutral: every text is made in the current language, again at
    // each language change (core's texts from their codes, operator events from their keys).
    LiveText::bind(this, [this] {
        setHeaderLabels({tr("Time [s]"), tr("Step"), tr("Kind"), tr("Event, alarm or note")});
        setToolTip(tr("Double-click (or Enter) to jump to the step"));
        for (int i = 0; i < topLevelItemCount(); ++i)
            retranslate(topLevelItem(i));
    });
    connect(this, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* item) {
        emit jumpTo(rowsThrough(m_data, item->data(Step, Qt::UserRole).toInt()));
    });
}

void ReplayEventList::retranslate(QTreeWidgetItem* item) {
    const int index = item->data(Text, Qt::UserRole).toInt();
    QString kind, text;
    if (index >= 0) {
        const Alarm& a = m_data.alarms[std::size_t(index)];
        kind = tr("%1, %2").arg(AlarmList::describe(a.severity), AlarmList::describe(a.kind));
        text = AlarmText::describe(a.code, {}, q(a.message));
    } else {
        const RecordNote& n = m_data.notes[std::size_t(~index)];
        const auto event = OperatorEvent::fromRecordText(n.text);
        kind = event ? tr("operator") : tr("note");
        text = event ? event->describe() : q(n.text);
    }
    item->setText(Kind, kind);
    item->setText(Text, text);
    item->setToolTip(Text, text);
}

int ReplayEventList::rowsThrough(const RecordData& data, int step) {
    const auto it = std::upper_bound(data.steps.begin(), data.steps.end(), step);
    return std::max(1, int(it - data.steps.begin()));
}

QStringList ReplayExport::columns(const RecordData& d) {
    QStringList c{QStringLiteral("step"), QStringLiteral("t [s]"), QStringLiteral("ag [m/s^2]")};
    for (Eigen::Index j = 0; j < d.u.cols(); ++j) // the DOFs recorded
        c << QStringLiteral("u %1 [m]").arg(q(d.layout.dofNames[std::size_t(d.dofIndex(int(j)))]));
    for (const ElementInfo& e : d.layout.elements) {
        c << QStringLiteral("d %1 [%2]").arg(q(e.name), q(e.units.deformation));
        c << QStringLiteral("F %1 [%2]").arg(q(e.name), q(e.units.force));
    }
    if (d.layout.updating)
        for (const std::string& p : d.layout.updating->parameters)
            c << QStringLiteral("%1 [-]").arg(q(p));
    return c;
}

std::vector<double> ReplayExport::values(const RecordData& d, int row) {
    std::vector<double> v;
    if (row < 0 || row >= d.rows())
        return v;
    v.push_back(d.steps[std::size_t(row)]);
    v.push_back(d.time(row));
    v.push_back(d.groundAcceleration(row));
    const int k = d.dofRowOf(row); // -1: a step whose DOFs were decimated away
    for (Eigen::Index j = 0; j < d.u.cols(); ++j)
        v.push_back(k >= 0 ? d.u(k, j) : std::nan(""));
    for (Eigen::Index j = 0; j < d.deformation.cols(); ++j) {
        v.push_back(d.deformation(row, j));
        v.push_back(d.force(row, j));
    }
    if (d.layout.updating)
        for (Eigen::Index j = 0; j < d.parameters.cols(); ++j)
            v.push_back(d.parameters(row, j));
    return v;
}

bool ReplayExport::exportWindowCsv(const RecordData& d, double t0, double t1, const QString& path,
                                   QString* error, int* rows) {
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text)) {
        if (error)
            *error = tr("%1: cannot be written (%2)").arg(path, file.errorString());
        return false;
    }
    QTextStream out(&file);
    QStringList header;
    for (const QString& c : columns(d))
        header << csvField(c);
    out << header.join(QLatin1Char(',')) << '\n';
    int n = 0;
    for (int r = 0; r < d.rows(); ++r) {
        if (d.time(r) < t0 - 1e-12 || d.time(r) > t1 + 1e-12)
            continue;
        QStringList cells;
        for (double v : values(d, r))
            cells << QString::number(v, 'g', 17);
        out << cells.join(QLatin1Char(',')) << '\n';
        ++n;
    }
    out.flush();
    if (file.error() != QFileDevice::NoError) {
        if (error)
            *error = tr("%1: cannot be written (%2)").arg(path, file.errorString());
        return false;
    }
    if (rows)
        *rows = n;
    return true;
}

QStringList ReplayExport::exportPlots(const QList<QCustomPlot*>& plots, const QString& dir,
                                      const QString& format, QStringList* errors) {
    QStringList written;
    int i = 0;
    for (QCustomPlot* p : plots) {
        const QString name = p->objectName().isEmpty() ? QStringLiteral("plot%1").arg(i)
                                                        : PlotExporter::fileSafe(p->objectName());
        ++i;
        const QString path = QDir(dir).filePath(name + QLatin1Char('.') + format.toLower());
        QString why;
        if (PlotExporter::saveAs(*p, path, PlotExporter::kWidth, PlotExporter::kHeight, &why))
            written << path;
        else if (errors)
            *errors << tr("%1: %2").arg(path, why);
    }
    return written;
}

ReplayReadout::ReplayReadout(const RecordData& data, QWidget* parent)
    : QTableWidget(parent), m_data(data) {
    setObjectName(QStringLiteral("replayReadout"));
    const QStringList names = ReplayExport::columns(data);
    setColumnCount(2);
    setRowCount(int(names.size()));
    verticalHeader()->hide();
    horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    for (int i = 0; i < names.size(); ++i) {
        auto* name = new QTableWidgetItem(names[i]);
        name->setData(Qt::UserRole, names[i]); // the CSV column's (language-neutral) name
        setItem(i, 0, name);
        setItem(i, 1, new QTableWidgetItem);
    }
    LiveText::bind(this, [this] {
        setHorizontalHeaderLabels({tr("Quantity"), tr("Value at the cursor")});
        // The first three columns have words; the rest are symbols with names and units.
        const QString shown[] = {tr("step"), tr("t [s]"), tr("ag [m/s²]")};
        for (int i = 0; i < 3 && i < rowCount(); ++i) {
            item(i, 0)->setText(shown[i]);
            item(i, 0)->setToolTip(item(i, 0)->data(Qt::UserRole).toString());
        }
    });
}

void ReplayReadout::showRow(int row) {
    const std::vector<double> v = ReplayExport::values(m_data, row);
    for (int i = 0; i < rowCount(); ++i)
        item(i, 1)->setText(std::size_t(i) < v.size() ? QString::number(v[std::size_t(i)], 'g', 6)
                                                        : QString());
}

QString ReplayReadout::value(const QString& name) const {
    for (int i = 0; i < rowCount(); ++i)
        if (item(i, 0)->data(Qt::UserRole).toString() == name)
            return item(i, 1)->text();
    return {};
}

} // namespace hsmu::gui
