#include "gui/app/ParametersPanel.h"

#include "gui/app/LiveText.h"
#include "gui/app/ParameterTableModel.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QSignalBlocker>
#include <QTableView>
#include <QVBoxLayout>

namespace hsmu::gui {

ParametersPanel::ParametersPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("parametersPanel"));
    m_summary = new QLabel(this);
    m_summary->setWordWrap(true);
    m_threshold = new QDoubleSpinBox(this);
    m_threshold->setObjectName(QStringLiteral("fitThreshold"));
    m_threshold->setRange(0.001, 10.0);
    m_threshold->setDecimals(3);
    m_threshold->setSingleStep(0.01);
    // Only a changed value is an edit (leaving the field is not: no "0.1 -> 0.1" event).
    connect(m_threshold, &QDoubleSpinBox::editingFinished, this, [this] {
        if (m_snapshot.enabled && m_threshold->value() != m_threshold->valueFromText(
                                      m_threshold->textFromValue(m_snapshot.fitThreshold)))
            emit thresholdEdited(m_threshold->value());
    });

    m_model = new ParameterTableModel(this);
    connect(m_model, &ParameterTableModel::boundsEdited, this, &ParametersPanel::boundsEdited);
    connect(m_model, &ParameterTableModel::lockEdited, this, &ParametersPanel::lockEdited);
    connect(m_model, &ParameterTableModel::editRefused, this, &ParametersPanel::editRefused);
    m_table = new QTableView(this);
    m_table->setModel(m_model);
    m_table->verticalHeader()->hide();
    // Names and the lock box take what they need, the numbers share the rest; a number is
    // never broken over two lines ("0." / "0078312").
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_table->horizontalHeader()->setSectionResizeMode(ParameterTableModel::Name,
                                                      QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(ParameterTableModel::Locked,
                                                      QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setMinimumSectionSize(24);
    m_table->setWordWrap(false);
    m_table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                             QAbstractItemView::AnyKeyPressed);
    m_table->setAlternatingRowColors(true);

    auto* thresholdRow = new QHBoxLayout;
    auto* thresholdLabel = new QLabel(this);
    m_thresholdLabel = thresholdLabel;
    thresholdRow->addWidget(thresholdLabel);
    thresholdRow->addWidget(m_threshold);
    thresholdRow->addStretch(1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_summary);
    layout->addLayout(thresholdRow);
    layout->addWidget(m_table, 1);
    auto* note = new QLabel(this);
    note->setWordWrap(true);
    note->setStyleSheet(QStringLiteral("color: palette(mid);"));
    layout->addWidget(note);
    setEditable(false);
    showThreshold();
    LiveText::bind(this, [this, thresholdLabel, note] {
        m_threshold->setToolTip(tr("Normalized RMS fit error above which the inspector "
                                   "requests an update; effective on the next step"));
        thresholdLabel->setText(tr("Fit-error threshold [-]:"));
        note->setText(tr("Value, sigma (1 standard deviation) and bounds in the law's "
                         "normalized units (u / u_ref, F / F_ref). Double-click a bound to "
                         "edit it; bound and lock edits take effect on the next step."));
        showSummary();
        emit m_model->headerDataChanged(Qt::Horizontal, 0, m_model->columnCount() - 1);
    });
}

void ParametersPanel::setSnapshot(const UpdatingSnapshot& s) {
    m_model->setSnapshot(s);
    m_snapshot = s;
    showSummary();
    if (s.enabled && !m_threshold->hasFocus()) {
        const QSignalBlocker block(m_threshold);
        m_threshold->setValue(s.fitThreshold);
    }
    showThreshold();
}

void ParametersPanel::showThreshold() {
    // Without updating there is no threshold: no field showing its minimum (0.001) as one.
    m_threshold->setVisible(m_snapshot.enabled);
    m_thresholdLabel->setVisible(m_snapshot.enabled);
}

void ParametersPanel::showSummary() {
    const UpdatingSnapshot& s = m_snapshot;
    if (!s.enabled) {
        m_summary->setText(tr("No online model updating in this test."));
        return;
    }
    m_summary->setText(
        tr("%1 on %2 at step %3: fit error e = %4 (threshold %5), %6 updates "
           "applied")
            .arg(QString::fromStdString(s.method), QString::fromStdString(s.specimen))
            .arg(s.step)
            .arg(QString::number(s.fitError, 'f', 3))
            .arg(QString::number(s.fitThreshold, 'f', 3))
            .arg(s.appliedUpdates));
}

void ParametersPanel::setEditable(bool editable) {
    m_model->setEditable(editable);
    m_threshold->setEnabled(editable);
}

} // namespace hsmu::gui
