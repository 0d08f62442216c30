#include "gui/app/ControlBar.h"

#include "gui/PresetLibrary.h"
#include "gui/app/LiveText.h"

#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QSignalBlocker>

#include <cmath>

namespace hsmu::gui {

ControlBar::ControlBar(QWidget* parent) : QToolBar(parent) {
    setObjectName(QStringLiteral("controlBar"));
    setMovable(false);
    setToolButtonStyle(Qt::ToolButtonTextOnly);

    auto* presetLabel = new QLabel(this);
    addWidget(presetLabel);
    m_presets = new QComboBox(this);
    m_presets->addItem(QString(), QString());
    for (const PresetLibrary::Preset& p : PresetLibrary::presets()) {
        m_presets->addItem(p.id, p.id);
        m_presets->setItemData(m_presets->count() - 1, p.title, Qt::ToolTipRole);
    }
    connect(m_presets, &QComboBox::activated, this, [this](int index) {
        const QString id = m_presets->itemData(index).toString();
        if (!id.isEmpty())
            emit presetChosen(id);
    });
    // Narrow enough for 1280 px in every language; the list opens as wide as it needs.
    m_presets->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_presets->setMinimumContentsLength(12);
    addWidget(m_presets);

    m_open = addAction(QString(), this, &ControlBar::openRequested);
    m_open->setShortcut(QKeySequence::Open);
    addSeparator();
    m_start = addAction(QString(), this, &ControlBar::startRequested);
    m_pause = addAction(QString(), this, &ControlBar::pauseRequested);
    m_step = addAction(QString(), this, &ControlBar::singleStepRequested);
    m_resume = addAction(QString(), this, &ControlBar::resumeRequested);
    addSeparator(); // Stop ends the test: apart from Resume (and it asks first)
    m_stop = addAction(QString(), this, &ControlBar::stopRequested);
    m_stop->setObjectName(QStringLiteral("stopTest"));
    // Keys for the run (docs/console.md, "Keyboard shortcuts"): the same requests as the
    // buttons, so Start still shows the pre-flight check and Stop still asks.
    m_start->setObjectName(QStringLiteral("startTest"));
    m_pause->setObjectName(QStringLiteral("pauseTest"));
    m_step->setObjectName(QStringLiteral("singleStep"));
    m_resume->setObjectName(QStringLiteral("resumeTest"));
    m_start->setShortcut(QKeySequence(Qt::Key_F5));
    m_pause->setShortcut(QKeySequence(Qt::Key_F6));
    m_resume->setShortcut(QKeySequence(Qt::Key_F7));
    m_step->setShortcut(QKeySequence(Qt::Key_F10));
    m_stop->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F5));
    addSeparator();
    const QKeySequence holdKey = emergencyHoldShortcut();
    m_hold = addAction(QString(), this, &ControlBar::emergencyHoldRequested);
    m_hold->setObjectName(QStringLiteral("emergencyHold"));
    m_hold->setShortcut(holdKey);
    m_hold->setShortcutContext(Qt::ApplicationShortcut);
    if (QWidget* button = widgetForAction(m_hold))
        button->setStyleSheet(QStringLiteral("QToolButton { color: white; background: #c62828;"
                                             " font-weight: bold; padding: 3px 6px; }"));
    addSeparator();

    auto* speedLabel = new QLabel(this);
    m_speedLabelAction = addWidget(speedLabel);
    m_speed = new QComboBox(this);
    // Pseudo-dynamic tests run at 1/10 to 1/100 of real time, or at a fixed wall time per step.
    for (double f : {0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 0.0, kWallPerStep})
        m_speed->addItem(QString(), f);
    m_speed->setCurrentIndex(m_speed->findData(1.0));
    m_wallPerStep = new QDoubleSpinBox(this);
    m_wallPerStep->setObjectName(QStringLiteral("wallTimePerStep"));
    m_wallPerStep->setRange(0.001, 600.0);
    m_wallPerStep->setDecimals(3);
    m_wallPerStep->setValue(1.0);
    connect(m_speed, &QComboBox::currentIndexChanged, this, [this] { emitPace(); });
    connect(m_wallPerStep, &QDoubleSpinBox::valueChanged, this, [this] { emitPace(); });
    m_speed->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_speed->setMinimumContentsLength(10); // the list opens as wide as it needs
    addWidget(m_speed);
    m_wallPerStepAction = addWidget(m_wallPerStep);
    m_wallPerStepAction->setVisible(false);
    LiveText::bind(this, [this, presetLabel, speedLabel, holdKey] {
        setWindowTitle(tr("Test control"));
        presetLabel->setText(tr("Preset: "));
        m_presets->setToolTip(tr("Test configurations shipped with the console"));
        m_presets->setItemText(0, tr("(choose a preset)"));
        m_open->setText(tr("Open configuration..."));
        const auto keyOf = [](const QAction* a) {
            return a->shortcut().toString(QKeySequence::NativeText);
        };
        m_start->setText(tr("Start"));
        m_start->setToolTip(tr("Start the test after the pre-flight check (%1)").arg(keyOf(m_start)));
        m_pause->setText(tr("Pause"));
        m_pause->setToolTip(tr("Pause between two steps (%1)").arg(keyOf(m_pause)));
        m_step->setText(tr("Single step"));
        m_step->setToolTip(
            tr("Run exactly one integration step, then stay paused (%1)").arg(keyOf(m_step)));
        m_resume->setText(tr("Resume"));
        m_resume->setToolTip(tr("Continue the test (%1)").arg(keyOf(m_resume)));
        m_stop->setText(tr("Stop..."));
        m_stop->setToolTip(
            tr("End the test, keeping the data (asks for confirmation; %1)").arg(keyOf(m_stop)));
        const QString key = holdKey.toString(QKeySequence::NativeText);
        m_hold->setText(tr("Emergency hold (%1)").arg(key));
        m_hold->setToolTip(tr("Hold the test at once, between two steps (%1)").arg(key));
        speedLabel->setText(tr(" Speed: "));
        m_speed->setToolTip(tr("Test time per wall-clock time"));
        for (int i = 0; i < m_speed->count(); ++i)
            m_speed->setItemText(i, speedText(m_speed->itemData(i).toDouble()));
        m_wallPerStep->setSuffix(tr(" s/step")); // short: the bar fits 1280 px with it
        m_wallPerStep->setToolTip(
            tr("Each step takes this long in wall time (pseudo-dynamic pace)"));
    });
    setRunState(RunState::Idle);
}

QString ControlBar::speedText(double factor) {
    if (factor == kWallPerStep)
        return tr("fixed wall time per step");
    if (factor == 0.0)
        return tr("as fast as possible");
    if (factor < 0.5)
        return tr("1/%1 x real time").arg(qRound(1.0 / factor));
    if (factor == 0.5)
        return tr("0.5 x real time");
    if (factor == 1.0)
        return tr("real time");
    if (factor == 2.0)
        return tr("2 x real time");
    return tr("5 x real time");
}

void ControlBar::setRunState(RunState state) {
    const bool active =
        state == RunState::Running || state == RunState::Paused || state == RunState::Holding;
    m_start->setEnabled(state == RunState::Ready || state == RunState::Finished ||
                        state == RunState::Stopped || state == RunState::Failed);
    m_pause->setEnabled(state == RunState::Running);
    m_step->setEnabled(state == RunState::Ready || state == RunState::Paused);
    m_resume->setEnabled(state == RunState::Paused || state == RunState::Holding);
    m_stop->setEnabled(active);
    m_presets->setEnabled(!active);
    m_open->setEnabled(!active);
    m_hold->setEnabled(true); // always: the operator's last resort
}

QKeySequence ControlBar::emergencyHoldShortcut() {
    return QKeySequence(Qt::CTRL | Qt::Key_H);
}

void ControlBar::selectPreset(const QString& id) {
    const QSignalBlocker block(m_presets);
    const int index = m_presets->findData(id);
    m_presets->setCurrentIndex(index >= 0 ? index : 0);
}

double ControlBar::speed() const {
    const double f = m_speed->currentData().toDouble();
    return f == kWallPerStep ? 0.0 : f;
}

double ControlBar::wallTimePerStep() const {
    return m_speed->currentData().toDouble() == kWallPerStep ? m_wallPerStep->value() : 0.0;
}

void ControlBar::setWallTimePerStep(double seconds) {
    if (seconds > 0.0) {
        m_wallPerStep->setValue(seconds);
        m_speed->setCurrentIndex(m_speed->findData(kWallPerStep));
    }
}

void ControlBar::emitPace() {
    // The field for the wall time per step takes the label's place (the bar fits 1280 px in
    // every language; the combo still says "fixed wall time per step").
    m_wallPerStepAction->setVisible(wallTimePerStep() > 0.0);
    m_speedLabelAction->setVisible(wallTimePerStep() <= 0.0);
    emit paceChanged(speed(), wallTimePerStep());
    emit speedChanged(speed());
}

void ControlBar::setSpeed(double factor) {
    int best = 0;
    for (int i = 0; i < m_speed->count(); ++i)
        if (m_speed->itemData(i).toDouble() != kWallPerStep &&
            std::abs(m_speed->itemData(i).toDouble() - factor) <
            std::abs(m_speed->itemData(best).toDouble() - factor))
            best = i;
    m_speed->setCurrentIndex(best);
}

} // namespace hsmu::gui
