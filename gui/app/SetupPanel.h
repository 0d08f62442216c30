#pragma once
// SetupPanel: the test's setup as the operator may change it before a start: ground motion
// file, the record's own sample step [s] (0 = from the file; a one-column file needs it) and
// scale [-], integration step dt [s], duration [s] (0 = the whole record), the
// controller (built-in virtual lab or hsmu-controller at tcp://host:port), each specimen's
// safety limits (0 = no limit; the specimen's units), the integrator (explicit Newmark or
// alpha-OS with its alpha) and the updating settings (on/off, inspector threshold; when
// updates are applied is the Pending updates panel's one control). Editable while no test
// runs, read-only while one does. Apply (or Start with unapplied edits) rebuilds the test from edited(); the loaded configuration is the base.
// Thread rules: GUI thread only.

#include "comms/LinkAddress.h"
#include "core/config/TestConfig.h"

#include <QStringList>
#include <QWidget>

#include <memory>
#include <optional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace hsmu {
class SiteMonitor;
}

namespace hsmu::gui {

class SiteHealthView;

class SetupPanel : public QWidget {
    Q_OBJECT
public:
    explicit SetupPanel(QWidget* parent = nullptr);

    /// Show cfg (the configuration as loaded, with the command-line overrides applied).
    void setConfig(const TestConfig& cfg);
    /// Per-site health of the loaded test in the "Sites" box (SiteHealthView).
    void setSiteMonitor(std::shared_ptr<const SiteMonitor> monitor);
    bool hasConfig() const { return m_loaded; }
    /// The loaded configuration with the panel's edits; nullopt and *error if one is invalid.
    std::optional<TestConfig> edited(QString* error = nullptr) const;
    /// The controller chosen; nullopt and *error if the address is invalid.
    std::optional<comms::LinkAddress> controller(QString* error = nullptr) const;
    void setControllerAddress(const QString& address);
    QString controllerText() const;
    /// The controller's token (session only: never written to the settings).
    QString token() const;
    void setEditable(bool editable);
    /// Edits not yet applied to the loaded test.
    bool isDirty() const { return m_dirty; }
    void markApplied();

    /// Show why the chosen ground motion cannot be used (empty: hide).
    void setGroundMotionStatus(const QString& error);
    QString groundMotionStatus() const;

signals:
    void applyRequested();
    /// A ground-motion file was chosen or typed (the window checks and plots it at once).
    void groundMotionChosen();
    /// "Test link": connect to the controller now.
    void testLinkRequested();
    void dirtyChanged(bool dirty);

private:
    /// The loaded configuration's name and ground-motion placeholder (or "no configuration").
    void showName();
    static void setLabel(QFormLayout* form, QWidget* field, const QString& text);
    void enableLinkFields();
    void showLinkNote();
    QWidget* buildRunGroup();
    QWidget* buildControllerGroup();
    QWidget* buildUpdatingGroup();
    void markDirty();
    void browseGroundMotion();
    /// The safety-limit headers broken into lines that fit their columns.
    void fitLimitHeaders();

    TestConfig m_base;
    bool m_loaded = false;
    bool m_dirty = false;
    bool m_editable = true;
    QLabel* m_name = nullptr;
    SiteHealthView* m_sites = nullptr;
    QLabel* m_linkNote = nullptr;
    QWidget* m_body = nullptr;
    QLabel* m_groundMotionStatus = nullptr;
    QLineEdit* m_groundMotion = nullptr;
    QDoubleSpinBox* m_recordDt = nullptr; ///< the record's sample step [s]; 0 = the file's
    QDoubleSpinBox* m_scale = nullptr;
    QDoubleSpinBox* m_dt = nullptr;
    QDoubleSpinBox* m_duration = nullptr;
    QComboBox* m_integrator = nullptr;
    QDoubleSpinBox* m_alpha = nullptr;
    QComboBox* m_controllerKind = nullptr;
    QLineEdit* m_host = nullptr;
    QSpinBox* m_port = nullptr;
    QLineEdit* m_token = nullptr;
    QTableWidget* m_limits = nullptr;
    QCheckBox* m_updating = nullptr;
    QDoubleSpinBox* m_threshold = nullptr;
    QPushButton* m_apply = nullptr;
    QList<QWidget*> m_inputs;
    QStringList m_limitHeaders; ///< the whole header texts (current language)
};

} // namespace hsmu::gui
