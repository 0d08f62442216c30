#include "gui/app/PendingUpdatesPanel.h"

#include <QBrush>
#include <QColor>
#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <cmath>

namespace hsmu::gui {

namespace {
enum Column { Parameter, Current, Proposed, Latest, Change, ColumnCount };
constexpr int kIdRole = Qt::UserRole;
constexpr ReporterPolicy kPolicies[] = {ReporterPolicy::EveryStep, ReporterPolicy::ZeroCrossing,
                                        ReporterPolicy::EveryNSteps, ReporterPolicy::OnApproval};
} // namespace

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
    for (ReporterPolicy p : kPolicies)
        m_policy->addItem(describe(p), int(p));
    // The long policies must not widen the dock at 1280x720: the box shows what fits, the
    // list the whole texts, the tool tip the chosen one.
    m_policy->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_policy->setMinimumContentsLength(14);
    connect(m_policy, &QComboBox::currentIndexChanged, this,
            [this] { m_policy->setToolTip(m_policy->currentText()); });
    m_everyN = new QSpinBox(this);
    m_everyN->setRange(1, 100000);
    connect(m_policy, &QComboBox::activated, this, [this] { emitPolicy(); });
    connect(m_everyN, &QSpinBox::editingFinished, this, [this] { emitPolicy(); });

    m_summary = new QLabel(this);
    m_summary->setObjectName(QStringLiteral("pendingSummary"));
    m_summary->setWordWrap(true);
    m_tree = new QTreeWidget(this);
    m_tree->setColumnCount(ColumnCount);
    m_tree->header()->setSectionResizeMode(QHeaderView::Stretch);
    // Five columns share the dock's width: a long header is cut ("..."), the numbers fit,
    // and no horizontal scroll bar takes a row of the short list.
    m_tree->header()->setMinimumSectionSize(40);
    m_tree->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_tree->setAlternatingRowColors(true);
    // Room for the header, the oldest proposal's title, its decision buttons and a parameter:
    // the dock cannot be squeezed below that (it was ~60 px at 1280x720, buttons hidden).
    const int row = fontMetrics().height() + 4;
    m_tree->setMinimumHeight(2 * m_tree->frameWidth() + m_tree->header()->sizeHint().height() +
                             2 * row + QPushButton(QStringLiteral("Approve")).sizeHint().height());

    // The offsets: their own item under the proposals, never decided by the policy.
    m_offsetsBox = new QWidget(this);
    m_offsetsBox->setObjectName(QStringLiteral("pendingOffsets"));
    m_offsetsText = new QLabel(m_offsetsBox);
    m_offsetsText->setWordWrap(true);
    m_offsetsText->setTextFormat(Qt::PlainText);
    m_approveOffsets = new QPushButton(m_offsetsBox);
    m_approveOffsets->setObjectName(QStringLiteral("approveOffsets"));
    m_rejectOffsets = new QPushButton(m_offsetsBox);
    m_rejectOffsets->setObjectName(QStringLiteral("rejectOffsets"));
    // The decision is for the offsets shown when the button was pressed.
    for (QPushButton* b : {m_approveOffsets, m_rejectOffsets}) {
        connect(b, &QPushButton::pressed, b,
                [this, b] { b->setProperty("pressedId", m_offsetsBox->property("offsetsId")); });
        connect(b, &QPushButton::clicked, this, [this, b] {
            const QVariant pressed = b->property("pressedId");
            const int id = (pressed.isValid() ? pressed : m_offsetsBox->property("offsetsId")).toInt();
            b->setProperty("pressedId", QVariant());
            if (b == m_approveOffsets)
                emit approveOffsetsRequested(id);
            else
                emit rejectOffsetsRequested(id);
        });
    }
    auto* offsetButtons = new QHBoxLayout;
    offsetButtons->addWidget(m_approveOffsets);
    offsetButtons->addWidget(m_rejectOffsets);
    offsetButtons->addStretch(1);
    auto* offsetLayout = new QVBoxLayout(m_offsetsBox);
    offsetLayout->setContentsMargins(0, 0, 0, 0);
    offsetLayout->addWidget(m_offsetsText);
    offsetLayout->addLayout(offsetButtons);

    // The label above its choice: the row fits the dock at 1280x720 in every language.
    auto* policyRow = new QHBoxLayout;
    m_policyLabel = new QLabel(this);
    m_policyLabel->setWordWrap(true);
    policyRow->addWidget(m_policy, 1);
    policyRow->addWidget(m_everyN);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_policyLabel);
    layout->addLayout(policyRow);
    layout->addWidget(m_summary);
    layout->addWidget(m_tree, 1);
    layout->addWidget(m_offsetsBox);
    retranslateUi();
    setSnapshot({});
    setEditable(false); // nothing to decide before a test is loaded
}

void PendingUpdatesPanel::retranslateUi() {
    for (int i = 0; i < m_policy->count(); ++i) {
        const QString text = describe(ReporterPolicy(m_policy->itemData(i).toInt()));
        m_policy->setItemText(i, text);
        m_policy->setItemData(i, text, Qt::ToolTipRole);
    }
    m_policy->setToolTip(m_policy->currentText());
    m_everyN->setPrefix(tr("N = "));
    m_policyLabel->setText(tr("Apply updates:"));
    m_tree->setHeaderLabels(
        {tr("Parameter"), tr("Current"), tr("Proposed"), tr("Estimate now"), tr("Change [%]")});
    m_tree->setToolTip(tr("The target's current value, the proposed one, the estimator's "
                          "value now and the change the proposal makes, in the law's "
                          "normalized units"));
    m_approveOffsets->setText(tr("Approve offsets"));
    m_rejectOffsets->setText(tr("Reject offsets"));
    showSummary();
    showOffsets();
    for (const UpdateProposal& p : m_snapshot.pending)
        if (const auto it = m_items.find(p.element); it != m_items.end())
            fillProposal(it->second, p);
}

QString PendingUpdatesPanel::describeOffsets(const OffsetProposal& p,
                                             const QString& deformationUnit,
                                             const QString& forceUnit) {
    // value +- the 95 % half-width (1.96 sd), or "(on its bound)" when it has no interval.
    const auto value = [](double v, double sd, const QString& unit) {
        const QString u = unit.isEmpty() ? QString() : QLatin1Char(' ') + unit;
        if (!std::isfinite(sd))
            return tr("%1%2 (on its bound, no interval)").arg(QString::number(v, 'g', 4), u);
        return tr("%1 +- %2%3 (95 %)")
            .arg(QString::number(v, 'g', 4), QString::number(1.96 * sd, 'g', 2), u);
    };
    return tr("Offsets #%1 for the twins: u0 = %2, F0 = %3")
        .arg(p.id)
        .arg(value(p.deformationOffset, p.deformationSd, deformationUnit),
             value(p.forceOffset, p.forceSd, forceUnit));
}

QString PendingUpdatesPanel::offsetsDetail(const OffsetProposal& p) {
    return tr("Found at t = %1 s (step %2) on %3 samples; the specimen's NRMSE %4 without them, "
              "%5 with them. They reach the twins (F = F_law(u - u0) + F0) only if you approve "
              "them, whatever the policy.")
        .arg(QString::number(p.time, 'f', 2))
        .arg(p.step)
        .arg(qulonglong(p.samples))
        .arg(QString::number(p.nrmseWithout, 'g', 3), QString::number(p.nrmseWith, 'g', 3));
}

void PendingUpdatesPanel::showOffsets() {
    const auto& p = m_snapshot.offsets;
    m_offsetsBox->setVisible(p.has_value());
    m_offsetsBox->setProperty("offsetsId", p ? p->id : 0);
    m_offsetsText->setText(p ? describeOffsets(*p, QString::fromStdString(m_snapshot.deformationUnit),
                                               QString::fromStdString(m_snapshot.forceUnit))
                             : QString());
    const QString detail = p ? offsetsDetail(*p) : QString();
    for (QWidget* w : {static_cast<QWidget*>(m_offsetsText), static_cast<QWidget*>(m_approveOffsets)})
        w->setToolTip(detail);
}

void PendingUpdatesPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void PendingUpdatesPanel::emitPolicy() {
    const auto p = ReporterPolicy(m_policy->currentData().toInt());
    if (!m_editable && m_nextRunPolicy) { // no test to tell: the panel shows the choice itself
        m_snapshot.policy = p;
        m_snapshot.everyN = m_everyN->value();
        showSummary();
    }
    setEditable(m_editable);
    emit policyChosen(p, m_everyN->value());
}

void PendingUpdatesPanel::setEditable(bool editable) {
    m_editable = editable;
    const bool policy = editable || (m_nextRunPolicy && m_snapshot.enabled);
    m_policy->setEnabled(policy);
    m_everyN->setEnabled(policy && ReporterPolicy(m_policy->currentData().toInt()) ==
                                       ReporterPolicy::EveryNSteps);
    m_tree->setEnabled(editable || m_tree->topLevelItemCount() == 0);
    m_approveOffsets->setEnabled(editable);
    m_rejectOffsets->setEnabled(editable);
}

void PendingUpdatesPanel::setNextRunPolicyEditable(bool editable) {
    m_nextRunPolicy = editable;
    setEditable(m_editable);
}

QList<int> PendingUpdatesPanel::shownProposals() const {
    QList<int> ids;
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i)
        ids.push_back(m_tree->topLevelItem(i)->data(Parameter, kIdRole).toInt());
    return ids;
}

void PendingUpdatesPanel::showSummary() {
    const UpdatingSnapshot& s = m_snapshot;
    QString text;
    if (!s.enabled)
        text = tr("No online model updating in this test.");
    else if (s.policy != ReporterPolicy::OnApproval)
        text = tr("Updates are applied %1; choose \"on the operator's approval\" to decide each "
                  "one.")
                   .arg(describe(s.policy));
    else
        text = tr("%n update(s) waiting for a decision.", nullptr, int(s.pending.size())) +
               QLatin1Char(' ') +
               tr("One proposal per target, renewed every %1 s of test time with the "
                  "estimator's latest values (it replaces the one shown); Approve applies the "
                  "values shown while they are current.")
                   .arg(QString::number(s.proposalInterval, 'g', 3));
    if (s.enabled && s.notQueued > 0)
        text += QLatin1Char(' ') +
                tr("%n newer proposal(s) were not queued (the queue holds %1); each is in the "
                   "record.",
                   nullptr, s.notQueued)
                    .arg(s.maxPending);
    m_summary->setText(text);
}

void PendingUpdatesPanel::fillProposal(QTreeWidgetItem* top, const UpdateProposal& p) {
    const bool stale = m_snapshot.stale(p);
    QString title = tr("#%1 %2 at t = %3 s (step %4)")
                        .arg(p.id)
                        .arg(QString::fromStdString(p.element))
                        .arg(QString::number(p.time, 'f', 2))
                        .arg(p.step);
    if (std::isfinite(p.fitError))
        title += tr(", fit error %1").arg(QString::number(p.fitError, 'g', 3));
    if (stale)
        title += tr(": stale (older than %1 s), wait for the next proposal")
                     .arg(QString::number(m_snapshot.proposalInterval, 'g', 3));
    top->setData(Parameter, kIdRole, p.id);
    top->setText(Parameter, title);
    top->setToolTip(Parameter, title);
    top->setForeground(Parameter, stale ? QBrush(QColor(0x8a, 0x4b, 0x00)) : QBrush());
    if (QTreeWidgetItem* decision = top->child(0))
        if (QWidget* buttons = m_tree->itemWidget(decision, Parameter))
            for (QPushButton* b : buttons->findChildren<QPushButton*>()) {
                const bool approve = b->property("approve").toBool();
                b->setObjectName(QStringLiteral("%1%2")
                                     .arg(approve ? QStringLiteral("approve")
                                                  : QStringLiteral("reject"))
                                     .arg(p.id));
                b->setText(approve ? tr("Approve") : tr("Reject"));
                if (approve)
                    b->setEnabled(!stale);
            }
    const auto latest = m_snapshot.latest.find(p.element);
    int k = 1; // the decision row first, right under the title; the parameters below it
    for (std::size_t j = 0; j < p.proposed.size(); ++j) {
        QTreeWidgetItem* row = top->child(k++);
        if (!row)
            row = new QTreeWidgetItem(top);
        const double proposed = p.proposed[j];
        const double current = j < p.current.size() ? p.current[j] : std::nan("");
        const double now = latest != m_snapshot.latest.end() && j < latest->second.size()
                               ? latest->second[j]
                               : std::nan("");
        row->setText(Parameter, QString::fromStdString(p.parameters.name(j)));
        row->setText(Current, QString::number(current, 'g', 5));
        row->setText(Proposed, QString::number(proposed, 'g', 5));
        row->setText(Latest, std::isfinite(now) ? QString::number(now, 'g', 5) : QString());
        row->setText(Change, current != 0.0 && std::isfinite(current)
                                 ? QString::number(
                                       100.0 * (proposed - current) / std::abs(current), 'f', 1)
                                 : QString());
    }
    while (top->childCount() > k)
        delete top->takeChild(k);
}

QTreeWidgetItem* PendingUpdatesPanel::addProposal(const UpdateProposal& p) {
    // The proposal's title and, right under it, its decision buttons span the row; its
    // parameters below (at 1280x720 the oldest proposal's buttons show without scrolling).
    auto* top = new QTreeWidgetItem(m_tree);
    top->setFirstColumnSpanned(true);
    auto* decision = new QTreeWidgetItem(top);
    decision->setFirstColumnSpanned(true);
    auto* buttons = new QWidget(m_tree);
    auto* h = new QHBoxLayout(buttons);
    h->setContentsMargins(0, 0, 0, 0);
    auto* approve = new QPushButton(buttons);
    auto* reject = new QPushButton(buttons);
    approve->setProperty("approve", true);
    h->addWidget(approve);
    h->addWidget(reject);
    h->addStretch(1);
    // The decision is for the proposal shown when the button was pressed: one renewed under
    // the mouse before the release is not the one the operator read (the worker then
    // refuses the older one as superseded).
    for (QPushButton* b : {approve, reject}) {
        connect(b, &QPushButton::pressed, b,
                [b, top] { b->setProperty("pressedId", top->data(Parameter, kIdRole)); });
        connect(b, &QPushButton::clicked, this, [this, b, top, isApprove = b == approve] {
            const QVariant pressed = b->property("pressedId");
            const int id = pressed.isValid() ? pressed.toInt() : top->data(Parameter, kIdRole).toInt();
            b->setProperty("pressedId", QVariant());
            if (isApprove)
                emit approveRequested(id);
            else
                emit rejectRequested(id);
        });
    }
    m_tree->setItemWidget(decision, Parameter, buttons);
    top->setExpanded(true);
    fillProposal(top, p);
    return top;
}

void PendingUpdatesPanel::setSnapshot(const UpdatingSnapshot& s) {
    {
        const QSignalBlocker b1(m_policy), b2(m_everyN);
        m_policy->setCurrentIndex(m_policy->findData(int(s.policy)));
        if (!m_everyN->hasFocus())
            m_everyN->setValue(s.everyN);
    }
    m_snapshot = s;
    showSummary();
    showOffsets();
    // One row per target: a newer proposal for a target takes its row in place (the buttons
    // stay under the mouse); decided targets leave, new ones are appended below.
    std::map<std::string, const UpdateProposal*> pending;
    for (const UpdateProposal& p : s.pending)
        pending[p.element] = &p;
    for (auto it = m_items.begin(); it != m_items.end();) {
        if (pending.count(it->first)) {
            ++it;
            continue;
        }
        // The buttons sit on a child row: the view does not release them with the parent.
        if (QTreeWidgetItem* decision = it->second->child(0))
            m_tree->removeItemWidget(decision, Parameter);
        delete it->second;
        it = m_items.erase(it);
    }
    for (const UpdateProposal& p : s.pending) {
        if (const auto it = m_items.find(p.element); it != m_items.end())
            fillProposal(it->second, p);
        else
            m_items[p.element] = addProposal(p);
    }
    setEditable(m_editable);
}

} // namespace hsmu::gui
