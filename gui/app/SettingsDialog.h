#pragma once
// SettingsDialog: the console's preferences: the record folder (empty: no record; applies
// to the next test loaded), the language (the system's or one with an
// embedded catalogue; applied at the next start) and clearing the recent files. Stores into
// ConsoleSettings on OK.
// Thread rules: GUI thread only.

#include <QDialog>

class QComboBox;
class QLineEdit;

namespace hsmu::gui {

class SettingsDialog : public QDialog {
    Q_OBJECT
public:
    explicit SettingsDialog(QWidget* parent = nullptr);

    QComboBox* languageBox() const { return m_language; }
    /// Store the choices (also what OK does).
    void store();

private:
    QComboBox* m_language = nullptr;
    QLineEdit* m_recordDir = nullptr;
};

} // namespace hsmu::gui
