#pragma once
// PendingUpdatesPanel: the reporter's approval policy (every step, zero crossing, every N
// steps, on approval; effective on the next step) and, under "on approval", each pending
// proposal: target element, test time [s] and step, and per parameter the target's current
// value, the proposed one and the change [%], with Approve and Reject buttons. The reporter
// keeps the latest proposal per element; the panel updates it in place (the buttons stay put)
// and shows how many proposals were coalesced since the last decision. It only emits
// the operator's decisions; MainWindow wires them to the TestController.
// Thread rules: GUI thread only.

#include "gui/app/UpdatingSnapshot.h"

#include <QWidget>

#include <map>
#include <string>
#include <vector>

class QComboBox;
class QLabel;
class QSpinBox;
class QTreeWidget;
class QTreeWidgetItem;

namespace hsmu::gui {

class PendingUpdatesPanel : public QWidget {
    Q_OBJECT
public:
    explicit PendingUpdatesPanel(QWidget* parent = nullptr);

    void setSnapshot(const UpdatingSnapshot& snapshot);
    void setEditable(bool editable);
    QTreeWidget* tree() const { return m_tree; }
    /// Ids of the proposals shown, oldest first.
    QList<int> shownProposals() const;
    /// Proposals for `element` seen since the last decision on it (the reporter keeps only
    /// the latest; the panel shows it with this count).
    int coalescedCount(const QString& element) const;

    static QString describe(ReporterPolicy policy);

signals:
    void approveRequested(int proposalId);
    void rejectRequested(int proposalId);
    void policyChosen(hsmu::ReporterPolicy policy, int everyN);

private:
    void emitPolicy();
    void fillProposal(QTreeWidgetItem* top, const UpdateProposal& p);

    QComboBox* m_policy = nullptr;
    QSpinBox* m_everyN = nullptr;
    QLabel* m_summary = nullptr;
    QTreeWidget* m_tree = nullptr;
    std::vector<int> m_shown;
    std::vector<std::string> m_shownElements;
    std::map<std::string, int> m_coalesced; ///< element -> proposals since the last decision
    bool m_editable = false;
};

} // namespace hsmu::gui
