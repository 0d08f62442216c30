#include "gui/app/PreflightDialog.h"

#include "gui/app/AlarmText.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QScreen>
#include <QScrollArea>
#include <QGuiApplication>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace hsmu::gui {

namespace {
// The integrator's configuration name in the operator's words.
QString integratorText(const std::string& name) {
    if (name == "explicitNewmark")
        return PreflightDialog::tr("explicit Newmark");
    if (name == "alphaOS")
        return PreflightDialog::tr("alpha-OS");
    return QString::fromStdString(name);
}
} // namespace

namespace {
QString num(double v) {
    if (!std::isfinite(v) || v <= 0.0)
        return QCoreApplication::translate("PreflightDialog", "none");
    return QString::number(v, 'g', 4);
}
} // namespace

PreflightDialog::PreflightDialog(const PreflightReport& report, const QStringList& warnings,
                                 QWidget* parent)
    : QDialog(parent), m_report(report) {
    setObjectName(QStringLiteral("preflightDialog"));
    setWindowTitle(tr("Pre-flight check"));
    // The checks scroll when the screen is small (1280x720 with the amber box): every line
    // keeps the height its words need; the confirmation and the buttons stay in view.
    auto* outer = new QVBoxLayout(this);
    auto* scroll = new QScrollArea(this);
    scroll->setObjectName(QStringLiteral("preflightScroll"));
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    auto* body = new QWidget(scroll);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(0, 0, 0, 0);
    scroll->setWidget(body);
    outer->addWidget(scroll, 1);

    auto* analysis = new QGroupBox(tr("Integration and stability"), this);
    auto* form = new QFormLayout(analysis);
    form->addRow(tr("Integrator:"), new QLabel(integratorText(report.integrator), this));
    form->addRow(tr("Time step dt [s]:"), new QLabel(QString::number(report.dt, 'g', 6), this));
    form->addRow(tr("Steps:"), new QLabel(QString::number(report.totalSteps), this));
    form->addRow(tr("Ground motion:"),
                 new QLabel(tr("%1, PGA %2 m/s²")
                                .arg(AlarmText::reason(QString::fromStdString(report.groundMotion)))
                                .arg(QString::number(report.pga, 'f', 3)),
                            this));
    const StabilityReport& st = report.stability;
    form->addRow(tr("omega_max [rad/s]:"), new QLabel(QString::number(st.omegaMax, 'g', 5), this));
    form->addRow(
        tr("omega_max dt [-] / limit:"),
        new QLabel(tr("%1 / %2").arg(QString::number(st.omegaDt, 'g', 4),
                                     std::isfinite(st.limit) ? QString::number(st.limit, 'g', 4)
                                                             : tr("unconditionally stable")),
                   this));
    // From the report's numbers, in the operator's language (core's message is English).
    const QString stabilityText = AlarmText::stability(
        st, integratorText(report.integrator), report.dt);
    auto* verdict = new QLabel(this);
    verdict->setObjectName(QStringLiteral("stabilityVerdict"));
    verdict->setWordWrap(true);
    if (st.stable)
        verdict->setText(tr("Stable: %1").arg(stabilityText));
    else
        verdict->setText(
            tr("UNSTABLE: %1%2")
                .arg(stabilityText,
                     report.allowUnstable ? tr(" (forced by the configuration)") : QString()));
    verdict->setStyleSheet(st.stable ? QStringLiteral("color: #2e7d32;")
                                     : QStringLiteral("color: #c62828; font-weight: bold;"));
    form->addRow(tr("Check:"), verdict);
    layout->addWidget(analysis);

    auto* specimens = new QGroupBox(tr("Specimens: limits and initial measured values"), this);
    auto* sv = new QVBoxLayout(specimens);
    for (const SpecimenPreflight& s : report.specimens) {
        auto* control = new QLabel(
            tr("%1: %2").arg(QString::fromStdString(s.element),
                             AlarmText::reason(QString::fromStdString(s.control))),
            specimens);
        control->setObjectName(QStringLiteral("preflightControl"));
        control->setWordWrap(true);
        sv->addWidget(control);
    }
    auto* table = new QTableWidget(int(report.specimens.size()), 6, specimens);
    table->setObjectName(QStringLiteral("preflightSpecimens"));
    table->setHorizontalHeaderLabels({tr("Element"), tr("Max |d|"), tr("Max |F|"),
                                      tr("Max |Δd| per step"), tr("Measured d"), tr("Measured F")});
    table->verticalHeader()->hide();
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    for (int i = 0; i < int(report.specimens.size()); ++i) {
        const SpecimenPreflight& s = report.specimens[std::size_t(i)];
        const QString d = QString::fromStdString(s.deformationUnit);
        const QString f = QString::fromStdString(s.forceUnit);
        auto withUnit = [](const QString& value, const QString& unit) {
            return unit.isEmpty() ? value : QStringLiteral("%1 %2").arg(value, unit);
        };
        auto limit = [&withUnit](double v, const QString& unit) {
            return std::isfinite(v) && v > 0.0 ? withUnit(num(v), unit) : num(v); // "none"
        };
        const QStringList cells{QString::fromStdString(s.element),
                                limit(s.limits.maxDeformation, d),
                                limit(s.limits.maxForce, f),
                                limit(s.limits.maxIncrement, d),
                                withUnit(QString::number(s.measuredDeformation, 'g', 4), d),
                                withUnit(QString::number(s.measuredForce, 'g', 4), f)};
        for (int c = 0; c < cells.size(); ++c)
            table->setItem(i, c, new QTableWidgetItem(cells[c]));
    }
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    sv->addWidget(table);
    auto* note = new QLabel(tr("Measured d and F: what the specimen reported after the link "
                               "was prepared, before any target was sent."),
                            specimens);
    note->setWordWrap(true);
    sv->addWidget(note);
    layout->addWidget(specimens, 1);

    if (!warnings.isEmpty()) {
        auto* flagged = new QLabel(tr("Please check:") + QStringLiteral("\n• ") +
                                       warnings.join(QStringLiteral("\n• ")),
                                   this);
        flagged->setObjectName(QStringLiteral("preflightWarnings"));
        flagged->setWordWrap(true);
        flagged->setStyleSheet(QStringLiteral("color: #8a4b00; background: #fff3cd; padding: 4px;"));
        layout->addWidget(flagged);
    }
    m_zero = new QCheckBox(tr("I confirm the zero offsets: with the specimen unloaded the "
                              "actuator displacement and the load cell read zero."),
                           this);
    m_zero->setObjectName(QStringLiteral("zeroOffsetsConfirmed"));
    outer->addWidget(m_zero);

    auto* buttons = new QDialogButtonBox(this);
    m_start = buttons->addButton(tr("Start test"), QDialogButtonBox::AcceptRole);
    // Our own words (Qt's standard buttons are not translated without Qt's catalogues).
    buttons->addButton(tr("Cancel"), QDialogButtonBox::RejectRole);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    outer->addWidget(buttons);
    connect(m_zero, &QCheckBox::toggled, this, &PreflightDialog::updateStart);
    updateStart();
    // Every text wraps to the dialog's width (a long ground-motion path, a controller's
    // description in Spanish) instead of widening it past the screen.
    for (QLabel* l : body->findChildren<QLabel*>())
        l->setWordWrap(true);
    // 760 px wide, as tall as the checks need, within the screen's available height.
    const int width = 760;
    const int contents = body->heightForWidth(width - 2 * outer->contentsMargins().left());
    QSize size(width, std::max(480, contents + m_zero->sizeHint().height() +
                                        buttons->sizeHint().height() + 4 * outer->spacing() +
                                        outer->contentsMargins().top() +
                                        outer->contentsMargins().bottom()));
    if (const QScreen* screen = parent ? parent->screen() : QGuiApplication::primaryScreen())
        size = size.boundedTo(screen->availableGeometry().size() - QSize(16, 48));
    resize(size);
}

void PreflightDialog::updateStart() {
    m_start->setEnabled(m_zero->isChecked() && m_report.startable());
}

} // namespace hsmu::gui
