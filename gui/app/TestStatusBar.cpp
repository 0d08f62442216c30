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
    m_link = label(160);
    m_sites = new SiteHealthLabel(this);
    addPermanentWidget(m_sites);
    m_recording = label(120);
    m_time->setObjectName(QStringLiteral("statusTime"));
    m_step->setObjectName(QStringLiteral("statusStep"));
    m_rate->setObjectName(QStringLiteral("statusRate"));
    m_state->setObjectName(QStringLiteral("statusState"));
    m_link->setObjectName(QStringLiteral("statusLink"));
    m_recording->setObjectName(QStringLiteral("statusRecording"));
    for (QLabel* l : {m_link, m_recording})
        l->setMaximumWidth(280); // long addresses and paths: cut, in full in the tool tip
    setLink(tr("no link"), true);
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
    m_rate->setText(tr("%1 steps/s").arg(QString::number(stepsPerSecond, 'f', 0)));
}

void TestStatusBar::setRunState(RunState state) {
    m_runState = state;
    m_state->setText(describe(state));
    const bool alarm = state == RunState::Holding || state == RunState::Failed;
    m_state->setStyleSheet(alarm ? QStringLiteral("color: white; background: #c62828;")
                                 : QString());
}

void TestStatusBar::setLink(const QString& text, bool ok) {
    m_link->setText(tr("link: %1").arg(text));
    m_link->setToolTip(m_link->text());
    m_link->setStyleSheet(ok ? QString() : QStringLiteral("color: white; background: #c62828;"));
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

void TestStatusBar::setSites(std::shared_ptr<const SiteMonitor> monitor) {
    m_sites->setMonitor(std::move(monitor));
}

} // namespace hsmu::gui
