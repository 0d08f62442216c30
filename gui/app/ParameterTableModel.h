#pragma once
// ParameterTableModel: the identified parameters of a test as a table: name, value, sigma
// (1 standard deviation), lower and upper bound, locked. Bounds and the lock are editable;
// an edit is not written into the model but emitted (boundsEdited / lockEdited) for the
// TestController, and shows once the worker's next UpdatingSnapshot confirms it, so the table
// always shows what the updater really uses. Values in the law's own units (normalized by
// uRef / fRef for Bouc-Wen, docs/method.md, Normalized units).
// Thread rules: GUI thread only.

#include "gui/app/UpdatingSnapshot.h"

#include <QAbstractTableModel>

namespace hsmu::gui {

class ParameterTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Name, Value, Sigma, Lower, Upper, Locked, ColumnCount };

    explicit ParameterTableModel(QObject* parent = nullptr);

    void setSnapshot(const UpdatingSnapshot& snapshot);
    /// While read-only (no running test) nothing is editable.
    void setEditable(bool editable);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation o, int role) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role) override;

signals:
    void boundsEdited(const QString& name, double lower, double upper);
    void lockEdited(const QString& name, bool locked);
    /// An edit that is not a number, and why.
    void editRefused(const QString& reason);

private:
    std::vector<ParameterState> m_rows;
    bool m_canLock = false;
    bool m_editable = true;
};

} // namespace hsmu::gui
