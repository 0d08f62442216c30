#pragma once
// RthsTwinPanel: the damper twin in the console's RTHS view (docs/rths.md, "The console's RTHS
// view"; "A damper and its twin"). For a run whose configuration has a "damper", it shows the
// twin's parameters as the loop has them now: each in the twin's scales (uRef [m], fRef [N]:
// MrDamper.h) and as a physical value with its unit (rths::twinParameterFactor, e.g. c0 in
// N s/m), and the parameter box (`bounds`). It starts from the configuration's twin law and
// follows every update the loop applies (the operator's, or the online identification's on a
// controller), as the session reports them with their tick.
// The operator types new values in the "New value" column and presses Send update: the values
// are checked here first with the loop's own check (rths::checkTwinUpdate: a name the law does
// not have, a value that is not a number or not finite, outside the box, or refused by the law:
// shown in red with the reason, nothing sent); a valid set is handed on (updateRequested) to be
// applied before the loop's next tick (locally, or over the link as rths-update, the message of
// `hsmu rths --controller --update`). The loop or the controller decides; its decision, applied
// before tick K or refused with the reason, is shown below the table.
// Proposals (docs/rths.md, "Proposals approved by the console"): a controller whose
// identification waits for approval sends each estimate as a proposal; the pending ones are
// listed (id, tick and time, fit figure when known, values) and the operator approves or rejects
// the selected one (decisionRequested); a proposal leaves the list when it is approved and
// applied, rejected, superseded by a newer one, or refused (outside the box: never applied).
// Thread rules: GUI thread only.

#include "core/rths/DamperTwin.h"

#include <QWidget>

#include <string>
#include <vector>

class QLabel;
class QPushButton;
class QTableWidget;

namespace hsmu::gui {

class RthsTwinPanel : public QWidget {
    Q_OBJECT
public:
    enum Column { Name, Value, Physical, Bounds, NewValue, ColumnCount };

    explicit RthsTwinPanel(QWidget* parent = nullptr);

    /// The run's twin: its initial law and box (damper.enabled false: "no twin", the table
    /// empty); rate [Hz] gives the time of a decision's tick.
    void setTwin(const rths::DamperSettings& damper, double rate);
    /// A run is going: updates may be sent.
    void setRunning(bool going);
    /// Decisions on updates (RthsSession::twinUpdates): applied values become the current ones.
    void showDecisions(const std::vector<UpdateEvent>& events);

    /// The twin's current value of `name` in its scales (NaN when it has none).
    double value(const std::string& name) const;
    /// Type `text` in the New value cell of parameter `name` (tests, scripts).
    void setNewValue(const QString& name, const QString& text);
    /// The update the New value cells ask for; "" when it may be sent, else why not.
    QString collect(rths::TwinUpdate& out) const;
    /// Collect, then hand the update on (updateRequested) or show why not.
    void send();
    /// Show that the update was not sent (the session's reason).
    void showNotSent(const QString& why);
    /// The decision line under the table.
    QString decisionText() const;
    QTableWidget* table() const { return m_table; }
    /// The pending proposals' ids, in the list's order.
    std::vector<int> pendingIds() const;
    /// Approve (true) or reject proposal `id`: what the buttons do with the selected row.
    void decide(int id, bool approve);

signals:
    void updateRequested(const hsmu::rths::TwinUpdate& update);
    void decisionRequested(int id, bool approve);

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
    void refreshValues();
    void setDecision(const QString& text, bool bad);
    void updateButtons();
    /// A proposal's event: listed (Proposed) or taken off the list, the decision line says so.
    void showProposal(const UpdateEvent& e);
    void decideSelected(bool approve);

    rths::DamperSettings m_damper;
    double m_rate = 1.0;
    bool m_running = false;
    std::vector<std::string> m_names;
    std::vector<double> m_values; // current, in m_names order
    QLabel* m_title = nullptr;
    QTableWidget* m_table = nullptr;
    QPushButton* m_send = nullptr;
    QLabel* m_decision = nullptr;
    QLabel* m_pendingTitle = nullptr;
    QTableWidget* m_pending = nullptr;
    QPushButton* m_approve = nullptr;
    QPushButton* m_reject = nullptr;
};

} // namespace hsmu::gui
