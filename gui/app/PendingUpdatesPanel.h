#pragma once
// PendingUpdatesPanel: the reporter's approval policy (every step, zero crossing, every N
// steps, on approval; effective on the next step) and, under "on approval", the pending
// proposals: one per target (Reporter: renewed every proposal interval with the estimator's
// latest values, each supersedes the one before), each with its target element, test time
// [s], step and the fit error when it was made, and per parameter the target's current value,
// the proposed one, the estimator's value now and the change [%] the proposal makes, with its
// own Approve and Reject buttons. A renewed proposal takes its target's row in place (the rows
// never move, the buttons stay under the mouse); a button decides the proposal shown when it
// was pressed. A stale proposal (older than one interval: no offer renewed it) is marked and
// its Approve disabled. Offers not queued (Reporter::maxPending()) are counted in the summary
// and each is in the record (/updating/events, decision "notQueued"). It only emits the
// operator's decisions; MainWindow wires them to the TestController. Retranslates itself on a
// language change.
// Offsets (docs/console.md, "Offsets for the twins"): the offsets the updating's check found
// (ModelUpdater::pendingOffsets) are a separate item below the proposals, with their values,
// units and 95 % intervals and their own Approve / Reject buttons: whatever the policy, they
// reach the twins only through that Approve.
// Thread rules: GUI thread only.

#include "gui/app/UpdatingSnapshot.h"

#include <QWidget>

#include <map>
#include <string>
#include <vector>

class QComboBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QTreeWidget;
class QTreeWidgetItem;

namespace hsmu::gui {

class PendingUpdatesPanel : public QWidget {
    Q_OBJECT
public:
    explicit PendingUpdatesPanel(QWidget* parent = nullptr);

    void setSnapshot(const UpdatingSnapshot& snapshot);
    /// true while a test is loaded or runs: decisions and the policy go to the test at once.
    void setEditable(bool editable);
    /// true between runs (stopped, finished, failed; nothing armed): the policy box stays
    /// enabled (when the test has updating) and the choice is for the next run only; the
    /// panel shows it at once, the window applies it when the next Start reloads the test.
    void setNextRunPolicyEditable(bool editable);
    QTreeWidget* tree() const { return m_tree; }
    /// Ids of the proposals shown, oldest first (the reporter's queue order).
    QList<int> shownProposals() const;
    QLabel* summary() const { return m_summary; }
    /// The offsets item (hidden while no offsets are pending) and its text.
    QWidget* offsetsBox() const { return m_offsetsBox; }
    QLabel* offsetsText() const { return m_offsetsText; }
    /// The text of pending offsets p in the specimen's units (values, 95 % intervals).
    static QString describeOffsets(const OffsetProposal& p, const QString& deformationUnit,
                                   const QString& forceUnit);
    /// Where they were found, both fits' NRMSE and the rule (the item's tool tip).
    static QString offsetsDetail(const OffsetProposal& p);

    static QString describe(ReporterPolicy policy);

signals:
    void approveRequested(int proposalId);
    void rejectRequested(int proposalId);
    void approveOffsetsRequested(int id);
    void rejectOffsetsRequested(int id);
    void policyChosen(hsmu::ReporterPolicy policy, int everyN);

protected:
    void changeEvent(QEvent* event) override;

private:
    void emitPolicy();
    void retranslateUi();
    void showSummary();
    QTreeWidgetItem* addProposal(const UpdateProposal& p);
    void fillProposal(QTreeWidgetItem* top, const UpdateProposal& p);
    void showOffsets();

    QComboBox* m_policy = nullptr;
    QSpinBox* m_everyN = nullptr;
    QLabel* m_policyLabel = nullptr;
    QLabel* m_summary = nullptr;
    QTreeWidget* m_tree = nullptr;
    QWidget* m_offsetsBox = nullptr;
    QLabel* m_offsetsText = nullptr;
    QPushButton* m_approveOffsets = nullptr;
    QPushButton* m_rejectOffsets = nullptr;
    UpdatingSnapshot m_snapshot;                   ///< the last one shown
    std::map<std::string, QTreeWidgetItem*> m_items; ///< target element -> its top-level row
    bool m_editable = false;
    bool m_nextRunPolicy = false; ///< between runs: the policy is chosen for the next run
};

} // namespace hsmu::gui
