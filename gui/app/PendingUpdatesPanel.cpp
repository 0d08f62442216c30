#include "gui/app/PendingUpdatesPanel.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace hsmu::gui {

namespace {
enum Column { Parameter, Current, Proposed, Change, ColumnCount };
}

QString PendingUpdatesPanel::describe(ReporterPolicy policy) {
    switch (policy) {
    case ReporterPolicy::EveryStep:
        return tr("every step");
    case ReporterPolicy::ZeroCrossing:
        return tr("at zero-force crossings of the target");
    case ReporterPolicy::EveryNSteps:
        return tr("every N steps");
    case ReporterPolicy::OnApproval:
        return tr("on the operator's approval");
    }
    return {};
}

PendingUpdatesPanel::PendingUpdatesPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("pendingUpdatesPanel"));
    m_policy = new QComboBox(this);
    m_policy->setObjectName(QStringLiteral("approvalPolicy"));
    for (ReporterPolicy p : {ReporterPolicy::EveryStep, ReporterPolicy::ZeroCrossing,
                             ReporterPolicy::EveryNSteps, ReporterPolicy::OnApproval})
        m_policy->addItem(describe(p), int(p));
    m_everyN = new QSpinBox(this);
    m_everyN->setRange(1, 100000);
    m_everyN->setPrefix(tr("N = "));
    connect(m_policy, &QComboBox::activated, this, [this] { emitPolicy(); });
    connect(m_everyN, &QSpinBox::editingFinished, this, [this] { emitPolicy(); });

    m_summary = new QLabel(this);
    m_summary->setWordWrap(true);
    m_tree = new QTreeWidget(this);
    m_tree->setColumnCount(ColumnCount);
    m_tree->setHeaderLabels({tr("Parameter"), tr("Current"), tr("Proposed"), tr("Change [%]")});
    m_tree->header()->setSectionResizeMode(QHeaderView::Stretch);
    m_tree->setToolTip(tr("Current and proposed values in the law's normalized units"));
    m_tree->setAlternatingRowColors(true);

    auto* policyRow = new QHBoxLayout;
    policyRow->addWidget(new QLabel(tr("Apply updates:"), this));
    policyRow->addWidget(m_policy, 1);
    policyRow->addWidget(m_everyN);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(policyRow);
    layout->addWidget(m_summary);
    layout->addWidget(m_tree, 1);
    setSnapshot({});
    setEditable(false); // nothing to decide before a test is loaded
}

void PendingUpdatesPanel::emitPolicy() {
    const auto p = ReporterPolicy(m_policy->currentData().toInt());
    m_everyN->setEnabled(m_editable && p == ReporterPolicy::EveryNSteps);
    emit policyChosen(p, m_everyN->value());
}

void PendingUpdatesPanel::setEditable(bool editable) {
    m_editable = editable;
    m_policy->setEnabled(editable);
    m_everyN->setEnabled(editable && ReporterPolicy(m_policy->currentData().toInt()) ==
                                         ReporterPolicy::EveryNSteps);
    m_tree->setEnabled(editable || m_tree->topLevelItemCount() == 0);
}

QList<int> PendingUpdatesPanel::shownProposals() const {
    return QList<int>(m_shown.begin(), m_shown.end());
}

void PendingUpdatesPanel::fillProposal(QTreeWidgetItem* top, const UpdateProposal& p) {
    const int coalesced = m_coalesced.count(p.element) ? m_coalesced.at(p.element) : 1;
    QString title = tr("#%1 %2 at t = %3 s (step %4)")
                        .arg(p.id)
                        .arg(QString::fromStdString(p.element))
                        .arg(QString::number(p.time, 'f', 2))
                        .arg(p.step);
    if (coalesced > 1)
        title += tr(" - latest of %n proposal(s) since the last decision", nullptr, coalesced);
    top->setText(Parameter, title);
    top->setToolTip(Parameter, title);
    top->setData(Parameter, Qt::UserRole, p.id);
    top->setData(Parameter, Qt::UserRole + 1, QString::fromStdString(p.element));
    int k = 0;
    for (const auto& [name, proposed] : p.proposed) {
        QTreeWidgetItem* row = top->child(k++);
        const auto it = p.current.find(name);
        const double current = it == p.current.end() ? std::nan("") : it->second;
        row->setText(Parameter, QString::fromStdString(name));
        row->setText(Current, QString::number(current, 'g', 5));
        row->setText(Proposed, QString::number(proposed, 'g', 5));
        row->setText(Change, current != 0.0 && std::isfinite(current)
                                 ? QString::number(
                                       100.0 * (proposed - current) / std::abs(current), 'f', 1)
                                 : QString());
    }
    if (QTreeWidgetItem* decision = top->child(k))
        if (QWidget* buttons = m_tree->itemWidget(decision, Parameter)) {
            const QList<QPushButton*> b = buttons->findChildren<QPushButton*>();
            if (b.size() == 2) {
                b[0]->setObjectName(QStringLiteral("approve%1").arg(p.id));
                b[1]->setObjectName(QStringLiteral("reject%1").arg(p.id));
            }
        }
}

int PendingUpdatesPanel::coalescedCount(const QString& element) const {
    const auto it = m_coalesced.find(element.toStdString());
    return it == m_coalesced.end() ? 0 : it->second;
}

void PendingUpdatesPanel::setSnapshot(const UpdatingSnapshot& s) {
    {
        const QSignalBlocker b1(m_policy), b2(m_everyN);
        m_policy->setCurrentIndex(m_policy->findData(int(s.policy)));
        if (!m_everyN->hasFocus())
            m_everyN->setValue(s.everyN);
    }
    if (!s.enabled)
        m_summary->setText(tr("No online model updating in this test."));
    else if (s.policy != ReporterPolicy::OnApproval)
        m_summary->setText(tr("Updates are applied %1; choose \"on the operator's approval\" "
                              "to decide each one.")
                               .arg(describe(s.policy)));
    else
        m_summary->setText(
            tr("%n update(s) waiting for a decision.", nullptr, int(s.pending.size())));

    std::vector<int> ids;
    std::vector<std::string> elements;
    for (const UpdateProposal& p : s.pending) {
        ids.push_back(p.id);
        elements.push_back(p.element);
        // A newer proposal replaces the older one for the same element (the reporter keeps
        // the latest): count them, so the operator sees how many were coalesced.
        if (std::find(m_shown.begin(), m_shown.end(), p.id) == m_shown.end())
            ++m_coalesced[p.element];
    }
    for (auto it = m_coalesced.begin(); it != m_coalesced.end();)
        it = std::find(elements.begin(), elements.end(), it->first) == elements.end()
                 ? m_coalesced.erase(it) : std::next(it);
    if (ids == m_shown)
        return; // unchanged: keep the operator's selection and scroll position
    m_shown = ids;
    if (elements == m_shownElements) {
        // Same elements, newer proposals: update in place, the buttons stay where they are.
        for (int i = 0; i < m_tree->topLevelItemCount(); ++i)
            fillProposal(m_tree->topLevelItem(i), s.pending[std::size_t(i)]);
        setEditable(m_editable);
        return;
    }
    m_shownElements = elements;
    m_tree->clear();
    for (const UpdateProposal& p : s.pending) {
        // The proposal's title and its decision buttons span the row; its parameters below.
        auto* top = new QTreeWidgetItem(m_tree);
        top->setFirstColumnSpanned(true);
        for (std::size_t k = 0; k < p.proposed.size(); ++k)
            new QTreeWidgetItem(top);
        auto* buttons = new QWidget(m_tree);
        auto* h = new QHBoxLayout(buttons);
        h->setContentsMargins(0, 0, 0, 0);
        auto* approve = new QPushButton(tr("Approve"), buttons);
        auto* reject = new QPushButton(tr("Reject"), buttons);
        h->addWidget(approve);
        h->addWidget(reject);
        // The decision is for the proposal shown when the button is pressed.
        connect(approve, &QPushButton::clicked, this, [this, top] {
            const int id = top->data(Parameter, Qt::UserRole).toInt();
            m_coalesced.erase(top->data(Parameter, Qt::UserRole + 1).toString().toStdString());
            emit approveRequested(id);
        });
        connect(reject, &QPushButton::clicked, this, [this, top] {
            const int id = top->data(Parameter, Qt::UserRole).toInt();
            m_coalesced.erase(top->data(Parameter, Qt::UserRole + 1).toString().toStdString());
            emit rejectRequested(id);
        });
        h->addStretch(1);
        auto* decision = new QTreeWidgetItem(top);
        decision->setFirstColumnSpanned(true);
        m_tree->setItemWidget(decision, Parameter, buttons);
        top->setExpanded(true);
        fillProposal(top, p);
    }
    setEditable(m_editable);
}

} // namespace hsmu::gui
