#include "gui/app/TestStatusBar.h"

#include "gui/app/SiteHealthLabel.h"
#include "gui/app/LiveText.h"

#include <QDir>
#include <QFileInfo>
#include <QLabel>

namespace hsmu::gui {

TestStatusBar::TestStatusBar(QWidget* parent) : QStatusBar(parent) {
    auto label = [this](int minWidth) {
        auto* l = new QLabel(this);
        l->setMinimumWidth(minWidth);
        l->setFrameShape(QFrame::StyledPanel);
        addPermanentWidget(l);
        return l;
    };
    m_time = label(130);
    m_step = label(150);
    m_rate = label(120);
    m_state = label(120);
    m_link = new SiteHealthLabel(this);
    addPermanentWidget(m_link);
    m_recording = label(120);
    m_time->setObjectName(QStringLiteral("statusTime"));
    m_step->setObjectName(QStringLiteral("statusStep"));
    m_rate->setObjectName(QStringLiteral("statusRate"));
    m_state->setObjectName(QStringLiteral("statusState"));
    m_recording->setObjectName(QStringLiteral("statusRecording"));
    m_recording->setMaximumWidth(280); // long paths: cut, in full in the tool tip
    // Every text again in the new language (the link's text comes from its owner).
    LiveText::bind(this, [this] {
        setProgress(m_progress.step, m_progress.total, m_progress.time, m_progress.rate);
        setRunState(m_runState);
        setRecordingFile(m_recordingFile);
    });
}

void TestStatusBar::setProgress(int step, int totalSteps, double testTime, double stepsPerSecond) {
    m_progress = {step, totalSteps, testTime, stepsPerSecond};
    m_time->setText(tr("t = %1 s").arg(QString::number(testTime, 'f', 2)));
    m_step->setText(tr("step %1 / %2").arg(step).arg(totalSteps));
    const QString rate = tr("%1 steps/s").arg(QString::number(stepsPerSecond, 'f', 0));
    // The time left at the present rate (while it runs).
    if (stepsPerSecond >= 0.5 && totalSteps > step) {
        const qint64 left = qRound64((totalSteps - step) / stepsPerSecond);
        const QString eta = left >= 3600 ? QStringLiteral("%1:%2:%3")
                                               .arg(left / 3600)
                                               .arg(left / 60 % 60, 2, 10, QLatin1Char('0'))
                                               .arg(left % 60, 2, 10, QLatin1Char('0'))
                                         : QStringLiteral("%1:%2")
                                               .arg(left / 60)
                                               .arg(left % 60, 2, 10, QLatin1Char('0'));
        m_rate->setText(tr("%1, %2 left").arg(rate, eta));
    } else {
        m_rate->setText(rate);
    }
}

void TestStatusBar::setRunState(RunState state) {
    m_runState = state;
    m_state->setText(describe(state));
    const bool alarm = state == RunState::Holding || state == RunState::Failed;
    m_state->setStyleSheet(alarm ? QStringLiteral("color: white; background: #c62828;")
                                 : QString());
}

void TestStatusBar::setLink(const QList<SiteHealthLabel::Site>& sites,
                            std::shared_ptr<const SiteMonitor> monitor) {
    m_link->setSites(sites);
    m_link->setMonitor(std::move(monitor));
}

void TestStatusBar::setRecordingFile(const QString& file) {
    // The run folder names the record; the full path is in the tool tip.
    m_recordingFile = file;
    const QFileInfo info(file);
    m_recording->setText(file.isEmpty()
                             ? tr("not recording")
                             : tr("recording: %1/%2").arg(info.dir().dirName(), info.fileName()));
    m_recording->setToolTip(file);
}

} // namespace hsmu::gui
