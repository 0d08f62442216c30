#include "gui/app/SettingsDialog.h"

#include "gui/app/ConsoleSettings.h"
#include "gui/app/Translations.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace hsmu::gui {

SettingsDialog::SettingsDialog(QWidget* parent) : QDialog(parent) {
    setObjectName(QStringLiteral("settingsDialog"));
    setWindowTitle(tr("Settings"));
    m_language = new QComboBox(this);
    m_language->setObjectName(QStringLiteral("languageBox"));
    m_language->addItem(tr("System default"), QString());
    QStringList codes = Translations::available();
    if (!codes.contains(QStringLiteral("en")))
        codes.prepend(QStringLiteral("en")); // the source language needs no catalogue
    for (const QString& code : codes)
        m_language->addItem(Translations::displayName(code), code);
    const int current = m_language->findData(ConsoleSettings::language());
    m_language->setCurrentIndex(current >= 0 ? current : 0);

    auto* clearRecent = new QPushButton(tr("Clear recent files"), this);
    connect(clearRecent, &QPushButton::clicked, this, [clearRecent] {
        ConsoleSettings::clearRecentFiles();
        clearRecent->setEnabled(false);
    });

    m_recordDir = new QLineEdit(ConsoleSettings::recordDirectory(), this);
    m_recordDir->setObjectName(QStringLiteral("recordDirectory"));
    m_recordDir->setPlaceholderText(tr("empty: tests are not recorded"));
    auto* browse = new QPushButton(tr("Browse..."), this);
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString dir =
            QFileDialog::getExistingDirectory(this, tr("Record folder"), m_recordDir->text());
        if (!dir.isEmpty())
            m_recordDir->setText(dir);
    });
    auto* recordRow = new QHBoxLayout;
    recordRow->addWidget(m_recordDir, 1);
    recordRow->addWidget(browse);

    auto* form = new QFormLayout;
    form->addRow(tr("Record folder (HDF5):"), recordRow);
    form->addRow(tr("Language:"), m_language);
    auto* note = new QLabel(tr("A new language applies at once, to every window."), this);
    note->setWordWrap(true);
    form->addRow(QString(), note);
    form->addRow(tr("Recent files:"), clearRecent);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("OK"));
    buttons->button(QDialogButtonBox::Cancel)->setText(tr("Cancel"));
    connect(buttons, &QDialogButtonBox::accepted, this, [this] {
        store();
        accept();
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons);
}

void SettingsDialog::store() {
    const QString language = m_language->currentData().toString();
    if (language != ConsoleSettings::language())
        Translations::install(*QCoreApplication::instance(), language); // live: LanguageChange
    ConsoleSettings::setLanguage(language);
    ConsoleSettings::setRecordDirectory(m_recordDir->text().trimmed());
}

} // namespace hsmu::gui
