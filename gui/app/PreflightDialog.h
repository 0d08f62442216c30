#pragma once
// PreflightDialog: the confirmation before a test starts (as OpenFresco's GenericTCP control
// asks): the integrator, dt [s], the stability check (omega_max [rad/s], omega_max dt against
// the scheme's limit), the ground motion and its PGA [m/s^2], and per specimen its control, its
// safety limits and the values measured after the link was prepared. Start is enabled only
// once the operator ticked (values flagged by PreflightChecks are listed in amber) "zero offsets confirmed" and the stability check allows the run.
// Thread rules: GUI thread only.

#include "gui/app/PreflightReport.h"

#include <QDialog>

class QCheckBox;
class QPushButton;

namespace hsmu::gui {

class PreflightDialog : public QDialog {
    Q_OBJECT
public:
    /// warnings: PreflightChecks::warnings(), shown in amber above the confirmation.
    explicit PreflightDialog(const PreflightReport& report, const QStringList& warnings = {},
                             QWidget* parent = nullptr);

    QCheckBox* zeroConfirmation() const { return m_zero; }
    QPushButton* startButton() const { return m_start; }

private:
    void updateStart();

    PreflightReport m_report;
    QCheckBox* m_zero = nullptr;
    QPushButton* m_start = nullptr;
};

} // namespace hsmu::gui
