#include "gui/app/RthsTwinPanel.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>
#include <limits>

namespace hsmu::gui {

namespace {

QString number(double v)
{
    return QString::number(v, 'g', 6);
}

QString unitText(rths::TwinParameterUnit u)
{
    switch (u) {
    case rths::TwinParameterUnit::NewtonSecondPerMetre: return QStringLiteral("N s/m");
    case rths::TwinParameterUnit::NewtonPerMetre: return QStringLiteral("N/m");
    case rths::TwinParameterUnit::Newton: return QStringLiteral("N");
    case rths::TwinParameterUnit::Metre: return QStringLiteral("m");
    case rths::TwinParameterUnit::Dimensionless: break;
    }
    return QStringLiteral("-");
}

QTableWidgetItem* readOnly(const QString& text)
{
    auto* item = new QTableWidgetItem(text);
    item->setFlags(item->flags() & ~Qt::ItemIsEditable);
    return item;
}

} // namespace

RthsTwinPanel::RthsTwinPanel(QWidget* parent) : QWidget(parent)
{
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    m_title = new QLabel(this);
    m_title->setWordWrap(true);
    m_table = new QTableWidget(0, ColumnCount, this);
    m_table->setObjectName(QStringLiteral("rthsTwinTable"));
    m_table->verticalHeader()->setVisible(false);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setMinimumHeight(120);
    m_send = new QPushButton(this);
    m_send->setObjectName(QStringLiteral("rthsTwinSend"));
    m_decision = new QLabel(this);
    m_decision->setObjectName(QStringLiteral("rthsTwinDecision"));
    m_decision->setWordWrap(true);
    m_decision->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* row = new QHBoxLayout;
    row->addWidget(m_title, 1);
    row->addWidget(m_send);
    v->addLayout(row);
    v->addWidget(m_table, 1);
    v->addWidget(m_decision);
    m_pendingTitle = new QLabel(this);
    m_pendingTitle->setWordWrap(true); // long in some languages: never widens the dock
    m_pending = new QTableWidget(0, 4, this);
    m_pending->setObjectName(QStringLiteral("rthsTwinProposals"));
    m_pending->verticalHeader()->setVisible(false);
    m_pending->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_pending->setSelectionMode(QAbstractItemView::SingleSelection);
    m_pending->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_pending->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_pending->horizontalHeader()->setStretchLastSection(true);
    m_pending->setMaximumHeight(90);
    m_approve = new QPushButton(this);
    m_approve->setObjectName(QStringLiteral("rthsTwinApprove"));
    m_reject = new QPushButton(this);
    m_reject->setObjectName(QStringLiteral("rthsTwinReject"));
    auto* decide = new QHBoxLayout;
    decide->addWidget(m_pendingTitle, 1);
    decide->addWidget(m_approve);
    decide->addWidget(m_reject);
    v->addLayout(decide);
    v->addWidget(m_pending);
    connect(m_send, &QPushButton::clicked, this, &RthsTwinPanel::send);
    connect(m_approve, &QPushButton::clicked, this, [this] { decideSelected(true); });
    connect(m_reject, &QPushButton::clicked, this, [this] { decideSelected(false); });
    connect(m_pending, &QTableWidget::itemSelectionChanged, this, &RthsTwinPanel::updateButtons);
    retranslateUi();
    updateButtons();
}

void RthsTwinPanel::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void RthsTwinPanel::retranslateUi()
{
    m_table->setHorizontalHeaderLabels({tr("Parameter"), tr("Value"), tr("Physical value"), tr("Bounds"),
                                        tr("New value")});
    m_send->setText(tr("Send update"));
    m_pending->setHorizontalHeaderLabels({tr("Proposal"), tr("Tick (time)"), tr("Fit error"), tr("Proposed values")});
    m_pendingTitle->setText(tr("Proposals waiting for approval (the controller's identification)"));
    m_approve->setText(tr("Approve"));
    m_approve->setToolTip(tr("Apply the selected proposal before the loop's next tick (refused if outside the bounds)"));
    m_reject->setText(tr("Reject"));
    m_send->setToolTip(tr("Apply the new values to the twin before the loop's next tick (checked against the bounds first)"));
    m_title->setText(m_damper.enabled
                         ? tr("Damper twin (storey of DOF %1), values in its scales uRef, fRef").arg(m_damper.twinDof + 1)
                         : tr("Damper twin: none in this run"));
    refreshValues();
}

void RthsTwinPanel::setTwin(const rths::DamperSettings& damper, double rate)
{
    m_damper = damper;
    m_rate = rate > 0.0 ? rate : 1.0;
    m_names.clear();
    m_values.clear();
    if (damper.enabled) {
        const MrDamper law(damper.twin);
        m_names = law.parameterNames();
        for (std::size_t i = 0; i < m_names.size(); ++i)
            m_values.push_back(law.parameterValue(int(i)));
    }
    m_table->setRowCount(int(m_names.size()));
    m_pending->setRowCount(0);
    for (int r = 0; r < int(m_names.size()); ++r) {
        const std::string& n = m_names[std::size_t(r)];
        m_table->setItem(r, Name, readOnly(QString::fromStdString(n)));
        const auto b = damper.box.find(n);
        m_table->setItem(r, Bounds, readOnly(b == damper.box.end()
                                                 ? QStringLiteral("-")
                                                 : QStringLiteral("[%1, %2]").arg(number(b->second.lower), number(b->second.upper))));
        m_table->setItem(r, NewValue, new QTableWidgetItem(QString()));
    }
    setDecision(QString(), false);
    retranslateUi();
    updateButtons();
}

void RthsTwinPanel::refreshValues()
{
    const double uRef = value("uRef"), fRef = value("fRef");
    for (int r = 0; r < m_table->rowCount() && r < int(m_values.size()); ++r) {
        const std::string& n = m_names[std::size_t(r)];
        const double x = m_values[std::size_t(r)];
        m_table->setItem(r, Value, readOnly(number(x)));
        m_table->setItem(r, Physical, readOnly(QStringLiteral("%1 %2").arg(number(x * rths::twinParameterFactor(n, uRef, fRef)),
                                                                      unitText(rths::twinParameterUnit(n)))));
    }
}

void RthsTwinPanel::setRunning(bool going)
{
    m_running = going;
    updateButtons();
}

void RthsTwinPanel::updateButtons()
{
    m_send->setEnabled(m_running && m_damper.enabled);
    const bool chosen = m_running && !m_pending->selectedItems().isEmpty();
    m_approve->setEnabled(chosen);
    m_reject->setEnabled(chosen);
}

std::vector<int> RthsTwinPanel::pendingIds() const
{
    std::vector<int> ids;
    for (int r = 0; r < m_pending->rowCount(); ++r)
        ids.push_back(m_pending->item(r, 0)->data(Qt::UserRole).toInt());
    return ids;
}

void RthsTwinPanel::decide(int id, bool approve)
{
    emit decisionRequested(id, approve);
}

void RthsTwinPanel::decideSelected(bool approve)
{
    const QList<QTableWidgetItem*> chosen = m_pending->selectedItems();
    if (!chosen.isEmpty())
        decide(m_pending->item(chosen.front()->row(), 0)->data(Qt::UserRole).toInt(), approve);
}

void RthsTwinPanel::showProposal(const UpdateEvent& e)
{
    const int id = e.proposal;
    for (int r = m_pending->rowCount() - 1; r >= 0; --r)
        if (m_pending->item(r, 0)->data(Qt::UserRole).toInt() == id)
            m_pending->removeRow(r);
    const QString tick = QStringLiteral("%1 (%2 s)").arg(e.step).arg(e.step / m_rate, 0, 'f', 3);
    switch (e.decision) {
    case UpdateDecision::Proposed: {
        QStringList values;
        for (std::size_t i = 0; i < e.parameters.size() && i < e.applied.size(); ++i)
            values << QStringLiteral("%1 = %2").arg(QString::fromStdString(e.parameters.name(i)), number(e.applied[i]));
        const int r = m_pending->rowCount();
        m_pending->insertRow(r);
        auto* first = new QTableWidgetItem(QStringLiteral("#%1").arg(id));
        first->setData(Qt::UserRole, id);
        m_pending->setItem(r, 0, first);
        m_pending->setItem(r, 1, new QTableWidgetItem(tick));
        m_pending->setItem(r, 2, new QTableWidgetItem(QStringLiteral("--"))); // the controller's UKF sends none
        m_pending->setItem(r, 3, new QTableWidgetItem(values.join(QStringLiteral(", "))));
        m_pending->selectRow(r);
        setDecision(tr("Proposal #%1 before tick %2: waiting for your approval").arg(id).arg(tick), false);
        break;
    }
    case UpdateDecision::Superseded:
        setDecision(tr("Proposal #%1 %2").arg(id).arg(QString::fromStdString(e.message)), false);
        break;
    case UpdateDecision::Rejected:
        setDecision(tr("Proposal #%1 rejected before tick %2: nothing applied").arg(id).arg(tick), false);
        break;
    case UpdateDecision::Applied:
        setDecision(tr("Proposal #%1 applied before tick %2").arg(id).arg(tick), false);
        break;
    default:
        setDecision(tr("Proposal #%1 refused: %2").arg(id).arg(QString::fromStdString(e.message)), true);
        break;
    }
    updateButtons();
}

double RthsTwinPanel::value(const std::string& name) const
{
    for (std::size_t i = 0; i < m_names.size(); ++i)
        if (m_names[i] == name)
            return m_values[i];
    return std::numeric_limits<double>::quiet_NaN();
}

void RthsTwinPanel::setNewValue(const QString& name, const QString& text)
{
    for (int r = 0; r < m_table->rowCount(); ++r)
        if (m_table->item(r, Name)->text() == name)
            m_table->item(r, NewValue)->setText(text);
}

QString RthsTwinPanel::collect(rths::TwinUpdate& out) const
{
    out = rths::TwinUpdate{{}, {}, "operator", 0};
    for (int r = 0; r < m_table->rowCount(); ++r) {
        const QString text = m_table->item(r, NewValue)->text().trimmed();
        if (text.isEmpty())
            continue;
        bool ok = false;
        const double x = QLocale().toDouble(text, &ok);
        const double y = ok ? x : text.toDouble(&ok); // the C locale's too (1.5 where 1,5 is the local way)
        if (!ok)
            return tr("%1: '%2' is not a number").arg(m_table->item(r, Name)->text(), text);
        out.names.push_back(m_names[std::size_t(r)]);
        out.values.push_back(y);
    }
    if (out.names.empty())
        return tr("type at least one new value");
    return QString::fromStdString(rths::checkTwinUpdate(m_damper, out));
}

void RthsTwinPanel::send()
{
    rths::TwinUpdate u;
    if (const QString why = collect(u); !why.isEmpty()) {
        setDecision(tr("Not sent: %1").arg(why), true);
        return;
    }
    setDecision(tr("Sent: applied before the loop's next tick, or refused with the reason"), false);
    emit updateRequested(u);
}

void RthsTwinPanel::showNotSent(const QString& why)
{
    setDecision(tr("Not sent: %1").arg(why), true);
}

void RthsTwinPanel::showDecisions(const std::vector<UpdateEvent>& events)
{
    for (const UpdateEvent& e : events) {
        if (e.proposal != 0 && e.decision != UpdateDecision::Applied) {
            showProposal(e);
            continue;
        }
        if (!e.ok) {
            setDecision(e.step > 0 ? tr("Refused before tick %1: %2").arg(e.step).arg(QString::fromStdString(e.message))
                                   : tr("Refused: %1").arg(QString::fromStdString(e.message)),
                        true);
            continue;
        }
        QStringList values;
        for (std::size_t i = 0; i < e.parameters.size() && i < e.applied.size(); ++i) {
            const std::string& n = e.parameters.name(i);
            for (std::size_t k = 0; k < m_names.size(); ++k)
                if (m_names[k] == n)
                    m_values[k] = e.applied[i];
            values << QStringLiteral("%1 = %2").arg(QString::fromStdString(n), number(e.applied[i]));
        }
        if (e.proposal != 0)
            showProposal(e);
        else
            setDecision(tr("Applied before tick %1 (t = %2 s; %3): %4")
                            .arg(e.step).arg(e.step / m_rate, 0, 'f', 3)
                            .arg(QString::fromStdString(e.message), values.join(QStringLiteral(", "))),
                        false);
    }
    refreshValues();
}

QString RthsTwinPanel::decisionText() const
{
    return m_decision->text();
}

void RthsTwinPanel::setDecision(const QString& text, bool bad)
{
    m_decision->setText(text);
    m_decision->setStyleSheet(bad ? QStringLiteral("color: #b00000; font-weight: bold;") : QString());
}

} // namespace hsmu::gui
