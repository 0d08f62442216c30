#include "gui/app/PreflightDialog.h"

#include "gui/app/ActuatorLimitText.h"
#include "gui/app/AlarmText.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
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
                                std::isfinite(s.measuredForce)
                                    ? withUnit(QString::number(s.measuredForce, 'g', 4), f)
                                    : tr("not measured")};
        for (int c = 0; c < cells.size(); ++c)
            table->setItem(i, c, new QTableWidgetItem(cells[c]));
    }
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    sv->addWidget(table);
    auto* note = new QLabel(
        report.hasLoadedSpecimen()
            ? tr("Measured d and F: what the specimen reported after the link was prepared, "
                 "before any target was sent; for a specimen loaded by an earlier test, d is "
                 "its last committed deformation and F is measured at the first step.")
            : tr("Measured d and F: what the specimen reported after the link was prepared, "
                 "before any target was sent."),
        specimens);
    note->setWordWrap(true);
    sv->addWidget(note);
    for (const SpecimenPreflight& s : report.specimens)
        for (const ActuatorLimitLine& l : s.actuatorLimits) {
            auto* line = new QLabel(ActuatorLimitText::line(s.element, l), specimens);
            line->setObjectName(QStringLiteral("actuatorLimitLine"));
            line->setWordWrap(true);
            if (l.verdict == LimitVerdict::Pass)
                line->setStyleSheet(QStringLiteral("color: #2e7d32;"));
            else if (l.verdict == LimitVerdict::Exceeded)
                line->setStyleSheet(QStringLiteral("color: #c62828; font-weight: bold;"));
            sv->addWidget(line);
        }
    layout->addWidget(specimens, 1);

    if (report.hasLoadedSpecimen())
        layout->addWidget(loadedSpecimenBox(report));
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

QWidget* PreflightDialog::loadedSpecimenBox(const PreflightReport& report) {
    auto* box = new QGroupBox(tr("Specimen loaded by an earlier test"), this);
    box->setObjectName(QStringLiteral("loadedSpecimen"));
    box->setStyleSheet(QStringLiteral("QGroupBox { color: #8a4b00; background: #fff3cd; }"));
    auto* v = new QVBoxLayout(box);
    bool freshPossible = true;
    bool continuePossible = true;
    for (const SpecimenPreflight& s : report.specimens) {
        if (!s.loaded())
            continue;
        const QString unit = QString::fromStdString(s.deformationUnit);
        auto* line = new QLabel(
            tr("%1 has %L2 committed steps from an earlier test; its last committed "
               "deformation is %3 %4. This test starts from rest: its first target moves the "
               "specimen from there.")
                .arg(QString::fromStdString(s.element))
                .arg(qulonglong(s.committedSteps))
                .arg(QString::number(s.lastDeformation, 'g', 4), unit),
            box);
        line->setObjectName(QStringLiteral("loadedSpecimenLine"));
        v->addWidget(line);
        if (s.continueExceedsIncrement()) {
            continuePossible = false;
            auto* jump = new QLabel(
                tr("Continuing would move it by about %1 %2 at the first step, more than the "
                   "increment limit %3 %2: the controller would hold the test. Choose a fresh "
                   "specimen, or bring the specimen back to rest at the controller.")
                    .arg(QString::number(std::abs(s.lastDeformation), 'g', 4), unit,
                         QString::number(s.limits.maxIncrement, 'g', 4)),
                box);
            jump->setObjectName(QStringLiteral("continueExceedsIncrement"));
            v->addWidget(jump);
        }
        if (!s.freshRefused.empty()) {
            freshPossible = false;
            auto* refused = new QLabel(
                tr("Its controller refused a fresh specimen (%1): replace the specimen at the "
                   "controller and restart the controller without its state file, or continue "
                   "on the loaded specimen.")
                    .arg(AlarmText::reason(QString::fromStdString(s.freshRefused))),
                box);
            refused->setObjectName(QStringLiteral("freshRefused"));
            v->addWidget(refused);
        }
    }
    auto* explain = new QLabel(tr("Choose: continue on the loaded specimen (its damage is part "
                                  "of this test), or a fresh specimen (its controller resets "
                                  "it to step 0, then this check is shown again)."),
                               box);
    v->addWidget(explain);
    m_continue = new QRadioButton(tr("Continue on the loaded specimen"), box);
    m_continue->setObjectName(QStringLiteral("continueLoadedSpecimen"));
    m_fresh = new QRadioButton(tr("Fresh specimen"), box);
    m_fresh->setObjectName(QStringLiteral("freshSpecimen"));
    m_fresh->setEnabled(freshPossible);
    m_continue->setEnabled(continuePossible);
    v->addWidget(m_continue);
    v->addWidget(m_fresh);
    connect(m_continue, &QRadioButton::toggled, this, &PreflightDialog::updateStart);
    connect(m_fresh, &QRadioButton::toggled, this, &PreflightDialog::updateStart);
    return box;
}

PreflightDialog::SpecimenChoice PreflightDialog::specimenChoice() const {
    if (m_fresh && m_fresh->isChecked())
        return SpecimenChoice::Fresh;
    if (m_continue && m_continue->isChecked())
        return SpecimenChoice::Continue;
    return SpecimenChoice::None;
}

void PreflightDialog::updateStart() {
    const SpecimenChoice choice = specimenChoice();
    if (choice == SpecimenChoice::Fresh) { // nothing starts: reset, then this check again
        m_start->setText(tr("Reset the specimen"));
        m_start->setEnabled(true);
        return;
    }
    m_start->setText(tr("Start test"));
    const bool chosen = !m_report.hasLoadedSpecimen() || choice == SpecimenChoice::Continue;
    m_start->setEnabled(m_zero->isChecked() && m_report.startable() && chosen);
}

} // namespace hsmu::gui
