#pragma once
// PreflightDialog: the confirmation before a test starts (as OpenFresco's GenericTCP control
// asks): the integrator, dt [s], the stability check (omega_max [rad/s], omega_max dt against
// the scheme's limit), the ground motion and its PGA [m/s^2], and per specimen its control, its
// safety limits and the values measured after the link was prepared. Start is enabled only
// once the operator ticked (values flagged by PreflightChecks are listed in amber) "zero offsets confirmed" and the stability check allows the run.
// A specimen loaded by an earlier test (its committed steps and last deformation, amber box
// "loadedSpecimen"; docs/console.md) needs an explicit choice first: continue on it (then Start
// as usual), or a fresh specimen (the button then reads "Reset the specimen": accepted with
// specimenChoice() Fresh, nothing starts; the console asks the controller and shows the check
// again). A controller that refused a fresh specimen before leaves only Continue.
// Thread rules: GUI thread only.

#include "gui/app/PreflightReport.h"

#include <QDialog>

class QCheckBox;
class QPushButton;
class QRadioButton;

namespace hsmu::gui {

class PreflightDialog : public QDialog {
    Q_OBJECT
public:
    /// warnings: PreflightChecks::warnings(), shown in amber above the confirmation.
    explicit PreflightDialog(const PreflightReport& report, const QStringList& warnings = {},
                             QWidget* parent = nullptr);

    enum class SpecimenChoice { None, Continue, Fresh };

    QCheckBox* zeroConfirmation() const { return m_zero; }
    /// The operator's choice for specimens loaded by an earlier test (None without any).
    SpecimenChoice specimenChoice() const;
    /// The two choices (nullptr when no specimen was loaded by an earlier test).
    QRadioButton* continueChoice() const { return m_continue; }
    QRadioButton* freshChoice() const { return m_fresh; }
    QPushButton* startButton() const { return m_start; }

private:
    void updateStart();
    QWidget* loadedSpecimenBox(const PreflightReport& report);

    PreflightReport m_report;
    QCheckBox* m_zero = nullptr;
    QPushButton* m_start = nullptr;
    QRadioButton* m_continue = nullptr;
    QRadioButton* m_fresh = nullptr;
};

} // namespace hsmu::gui
