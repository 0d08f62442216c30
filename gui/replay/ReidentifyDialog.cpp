#include "gui/replay/ReidentifyDialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPushButton>

namespace hsmu::gui {

ReidentifyDialog::ReidentifyDialog(const QString& recordedMethod, QWidget* parent)
    : QDialog(parent) {
    setWindowTitle(tr("Re-identify"));
    m_method = new QComboBox(this);
    m_method->addItem(tr("UKF"), QStringLiteral("ukf"));
    m_method->addItem(tr("Nelder-Mead"), QStringLiteral("nelderMead"));
    if (recordedMethod == QStringLiteral("Nelder-Mead"))
        m_method->setCurrentIndex(1);

    m_override = new QLineEdit(this);
    m_override->setPlaceholderText(tr("none: the recorded settings"));
    auto* browse = new QPushButton(tr("Browse..."), this);
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Override settings"), QString(), tr("JSON (*.json);;All files (*)"));
        if (!path.isEmpty())
            m_override->setText(path);
    });
    auto* row = new QHBoxLayout;
    row->addWidget(m_override, 1);
    row->addWidget(browse);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("OK"));
    buttons->button(QDialogButtonBox::Cancel)->setText(tr("Cancel"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* form = new QFormLayout(this);
    form->addRow(tr("Method"), m_method);
    form->addRow(tr("Override (JSON)"), row);
    form->addRow(buttons);
    m_override->setToolTip(tr("{\"model\": ..., \"updating\": ...} merged into the recorded "
                              "settings, as hsmu replay --config"));
}

QString ReidentifyDialog::method() const {
    return m_method->currentData().toString();
}

QString ReidentifyDialog::overridePath() const {
    return m_override->text().trimmed();
}

} // namespace hsmu::gui
