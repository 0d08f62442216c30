#pragma once
// ReidentifyDialog: the replay window's "Re-identify..." choices: the method (UKF or
// Nelder-Mead, the recorded one first) and optionally an override JSON file, as
// `hsmu replay --identify --method M --config FILE` (docs/cli.md). It only asks; the window runs
// the identification. Thread rules: GUI thread only.

#include <QDialog>

class QComboBox;
class QLineEdit;

namespace hsmu::gui {

class ReidentifyDialog : public QDialog {
    Q_OBJECT
public:
    /// recordedMethod: "UKF" / "Nelder-Mead" (preselected), or "" when the record has none.
    explicit ReidentifyDialog(const QString& recordedMethod, QWidget* parent = nullptr);

    /// "ukf" or "nelderMead".
    QString method() const;
    /// The override file, "" for none.
    QString overridePath() const;

private:
    QComboBox* m_method = nullptr;
    QLineEdit* m_override = nullptr;
};

} // namespace hsmu::gui
