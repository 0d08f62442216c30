#pragma once
// The replay window's side panels and exports:
//   ReplayEventList  every alarm and operator note of the record (time [s], step, kind,
//                    text), oldest first; activating a row (double-click, Enter) asks to jump
//                    to that step (jumpTo(rows shown))
//   ReplayReadout    the numeric values of one row: time [s], step, ground acceleration
//                    [m/s^2], each DOF's u [m], each element's deformation and force (its
//                    units) and each identified parameter
//   ReplayExport     a time window of the record as CSV (one row per step, the read-out's
//                    columns) and the plots as PNG, SVG or PDF
// Thread rules: GUI thread only.

#include <QCoreApplication>
#include <QStringList>
#include <QTableWidget>
#include <QTreeWidget>

class QCustomPlot;

namespace hsmu {
struct RecordData;
}

namespace hsmu::gui {

class ReplayEventList : public QTreeWidget {
    Q_OBJECT
public:
    enum Column { Time, Step, Kind, Text, ColumnCount };
    explicit ReplayEventList(const RecordData& data, QWidget* parent = nullptr);
    /// The number of rows to show to reach `step` (row index of step + 1).
    static int rowsThrough(const RecordData& data, int step);

signals:
    void jumpTo(int rowsShown);

private:
    /// Kind and text of an entry in the current language.
    void retranslate(QTreeWidgetItem* item);
    const RecordData& m_data;
};

class ReplayReadout : public QTableWidget {
    Q_OBJECT
public:
    explicit ReplayReadout(const RecordData& data, QWidget* parent = nullptr);
    /// Show row `row` (0-based; out of range: empty values).
    void showRow(int row);
    /// The value cell of the quantity named `name` (e.g. "t [s]"), "" if absent.
    QString value(const QString& name) const;

private:
    const RecordData& m_data;
};

class ReplayExport {
    Q_DECLARE_TR_FUNCTIONS(ReplayExport)

public:
    /// The column names of exportWindowCsv() (and of the read-out), units included.
    static QStringList columns(const RecordData& data);
    /// One row of values in columns() order.
    static std::vector<double> values(const RecordData& data, int row);
    /// Rows with t0 <= time <= t1 [s] as CSV at path; false and *error naming the file.
    static bool exportWindowCsv(const RecordData& data, double t0, double t1, const QString& path,
                                QString* error = nullptr, int* rows = nullptr);
    /// Every plot into dir as <objectName>.<format> (png, svg or pdf); the files written, the
    /// failures in *errors.
    static QStringList exportPlots(const QList<QCustomPlot*>& plots, const QString& dir,
                                   const QString& format, QStringList* errors = nullptr);
};

} // namespace hsmu::gui
