#pragma once
// ParametersPanel: the identified parameters (ParameterTableModel: value, sigma, bounds,
// lock; bounds and locks editable while a test is loaded, effective on the next step), the
// inspector's fit error e [-] and its threshold (editable, effective on the next step).
// It only emits the operator's edits; MainWindow wires them to the TestController.
// Thread rules: GUI thread only.

#include "gui/app/UpdatingSnapshot.h"

#include <QWidget>

class QDoubleSpinBox;
class QLabel;
class QTableView;

namespace hsmu::gui {

class ParameterTableModel;

class ParametersPanel : public QWidget {
    Q_OBJECT
public:
    explicit ParametersPanel(QWidget* parent = nullptr);

    void setSnapshot(const UpdatingSnapshot& snapshot);
    void setEditable(bool editable);
    ParameterTableModel* model() const { return m_model; }
    QTableView* table() const { return m_table; }

signals:
    void boundsEdited(const QString& name, double lower, double upper);
    void lockEdited(const QString& name, bool locked);
    void thresholdEdited(double threshold);
    void editRefused(const QString& reason);

private:
    void showSummary();
    /// The threshold field only while the test updates its model.
    void showThreshold();
    UpdatingSnapshot m_snapshot; ///< the last one shown
    ParameterTableModel* m_model = nullptr;
    QTableView* m_table = nullptr;
    QLabel* m_summary = nullptr;
    QDoubleSpinBox* m_threshold = nullptr;
    QLabel* m_thresholdLabel = nullptr;
};

} // namespace hsmu::gui
