#include "gui/app/ParameterTableModel.h"

#include <QBrush>
#include <QColor>

#include <cmath>

namespace hsmu::gui {

namespace {
QString number(double v, int digits = 5) {
    if (std::isinf(v))
        return v > 0 ? QStringLiteral("+inf") : QStringLiteral("-inf");
    return QString::number(v, 'g', digits);
}
} // namespace

ParameterTableModel::ParameterTableModel(QObject* parent) : QAbstractTableModel(parent) {}

void ParameterTableModel::setSnapshot(const UpdatingSnapshot& snapshot) {
    const bool sameRows = snapshot.parameters.size() == m_rows.size() &&
                          std::equal(m_rows.begin(), m_rows.end(), snapshot.parameters.begin(),
                                     [](const ParameterState& a, const ParameterState& b) {
                                         return a.name == b.name;
                                     });
    m_canLock = snapshot.canLock;
    if (!sameRows) {
        beginResetModel();
        m_rows = snapshot.parameters;
        endResetModel();
        return;
    }
    m_rows = snapshot.parameters;
    if (!m_rows.empty())
        emit dataChanged(index(0, Value), index(int(m_rows.size()) - 1, Locked));
}

void ParameterTableModel::setEditable(bool editable) {
    m_editable = editable;
    if (!m_rows.empty())
        emit dataChanged(index(0, Lower), index(int(m_rows.size()) - 1, Locked));
}

int ParameterTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_rows.size());
}

int ParameterTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant ParameterTableModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= int(m_rows.size()))
        return {};
    const ParameterState& p = m_rows[std::size_t(index.row())];
    if (role == Qt::DisplayRole || role == Qt::EditRole) {
        switch (index.column()) {
        case Name:
            return QString::fromStdString(p.name);
        case Value:
            return role == Qt::EditRole ? QVariant(p.value) : QVariant(number(p.value));
        case Sigma: // an uncertainty: three significant digits are all it has
            return number(p.sigma, 3);
        case Lower:
            return role == Qt::EditRole ? QVariant(p.bounds.lower)
                                        : QVariant(number(p.bounds.lower));
        case Upper:
            return role == Qt::EditRole ? QVariant(p.bounds.upper)
                                        : QVariant(number(p.bounds.upper));
        default:
            return {};
        }
    }
    if (role == Qt::CheckStateRole && index.column() == Locked)
        return p.locked ? Qt::Checked : Qt::Unchecked;
    if (role == Qt::TextAlignmentRole && index.column() != Name)
        return int(Qt::AlignRight | Qt::AlignVCenter);
    if (role == Qt::BackgroundRole && index.column() == Value) {
        const double width = p.bounds.upper - p.bounds.lower;
        const bool atBound =
            std::isfinite(width) && width > 0.0 &&
            (p.value - p.bounds.lower < 1e-3 * width || p.bounds.upper - p.value < 1e-3 * width);
        if (atBound)
            return QBrush(QColor(255, 236, 179)); // amber: pinned at a bound
    }
    if (role == Qt::ToolTipRole && (index.column() == Lower || index.column() == Upper))
        return tr("Double-click to edit; effective on the next step");
    return {};
}

QVariant ParameterTableModel::headerData(int section, Qt::Orientation o, int role) const {
    if (o != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, o, role);
    switch (section) {
    case Name:
        return tr("Parameter");
    case Value:
        return tr("Value");
    case Sigma:
        return tr("Sigma");
    case Lower:
        return tr("Lower");
    case Upper:
        return tr("Upper");
    case Locked:
        return tr("Lock");
    default:
        return {};
    }
}

Qt::ItemFlags ParameterTableModel::flags(const QModelIndex& index) const {
    Qt::ItemFlags f = QAbstractTableModel::flags(index);
    if (!m_editable)
        return f;
    if (index.column() == Lower || index.column() == Upper)
        f |= Qt::ItemIsEditable;
    if (index.column() == Locked && m_canLock)
        f |= Qt::ItemIsUserCheckable;
    return f;
}

bool ParameterTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!index.isValid() || index.row() >= int(m_rows.size()) || !m_editable)
        return false;
    const ParameterState& p = m_rows[std::size_t(index.row())];
    const QString name = QString::fromStdString(p.name);
    if (index.column() == Locked && role == Qt::CheckStateRole) {
        emit lockEdited(name, value.toInt() == Qt::Checked);
        return true;
    }
    if ((index.column() != Lower && index.column() != Upper) || role != Qt::EditRole)
        return false;
    bool ok = false;
    const double v = value.toDouble(&ok);
    if (!ok || !std::isfinite(v)) {
        emit editRefused(tr("%1: '%2' is not a number").arg(name, value.toString()));
        return false;
    }
    const double lower = index.column() == Lower ? v : p.bounds.lower;
    const double upper = index.column() == Upper ? v : p.bounds.upper;
    emit boundsEdited(name, lower, upper);
    return true; // shown once the worker's snapshot confirms it
}

} // namespace hsmu::gui
