#include "gui/replay/ReplayWindow.h"

#include "core/record/RecordReader.h"
#include "gui/plots/LivePlotsPanel.h"
#include "gui/replay/RecordPlayback.h"

#include <QAction>
#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QSlider>
#include <QTimer>
#include <QToolBar>

#include <exception>

namespace hsmu::gui {

ReplayWindow* ReplayWindow::open(const QString& path, QWidget* parent, QString* error) {
    std::shared_ptr<const RecordData> data;
    try {
        const RecordReader reader(path.toStdString());
        if (reader.rows() == 0)
            throw std::runtime_error(path.toStdString() + ": the record holds no step");
        data = std::make_shared<const RecordData>(reader.data());
    } catch (const std::exception& e) {
        if (error)
            *error = QString::fromStdString(e.what());
        return nullptr;
    }
    return new ReplayWindow(std::move(data), path, parent);
}

ReplayWindow* ReplayWindow::openWithDialog(QWidget* parent) {
    const QString path = QFileDialog::getOpenFileName(
        parent, tr("Open record"), QString(), tr("HSMU records (*.h5 *.hdf5);;All files (*)"));
    if (path.isEmpty())
        return nullptr;
    QString error;
    ReplayWindow* window = open(path, parent, &error);
    if (!window) {
        QMessageBox::critical(parent, tr("Cannot open the record"), error);
        return nullptr;
    }
    window->setAttribute(Qt::WA_DeleteOnClose);
    window->setWindowFlag(Qt::Window);
    window->QMainWindow::show();
    return window;
}

ReplayWindow::ReplayWindow(std::shared_ptr<const RecordData> data, const QString& path,
                           QWidget* parent)
    : QMainWindow(parent), m_playback(std::make_unique<RecordPlayback>(std::move(data))) {
    setWindowFlag(Qt::Window);
    const RecordData& d = m_playback->data();
    setWindowTitle(tr("HSMU Replay - %1 (%2)")
                       .arg(QString::fromStdString(d.meta.configName), QFileInfo(path).fileName()));

    m_panel = new LivePlotsPanel(this);
    m_panel->configure(d.layout, PlotReferences::ofConfigurationJson(d.meta.configuration));
    m_panel->setGroundMotion(
        QVector<double>(d.time.data(), d.time.data() + d.time.size()),
        QVector<double>(d.groundAcceleration.data(),
                        d.groundAcceleration.data() + d.groundAcceleration.size()));
    setCentralWidget(m_panel);

    auto* bar = addToolBar(tr("Replay"));
    bar->setObjectName(QStringLiteral("replayToolBar"));
    m_playAction = bar->addAction(tr("Play"));
    m_playAction->setShortcut(Qt::Key_Space);
    connect(m_playAction, &QAction::triggered, this, [this] { isPlaying() ? pause() : play(); });
    bar->addWidget(new QLabel(tr(" Speed "), bar));
    m_speed = new QComboBox(bar);
    for (const double s : {0.25, 0.5, 1.0, 2.0, 5.0, 10.0, 50.0})
        m_speed->addItem(tr("%1 x").arg(s), s);
    m_speed->setCurrentIndex(2);
    m_speed->setToolTip(tr("Test seconds per wall second"));
    connect(m_speed, &QComboBox::currentIndexChanged, this,
            [this](int i) { setSpeed(m_speed->itemData(i).toDouble()); });
    bar->addWidget(m_speed);
    m_slider = new QSlider(Qt::Horizontal, bar);
    m_slider->setRange(0, m_playback->rows());
    m_slider->setMinimumWidth(300);
    m_slider->setToolTip(tr("Scrub through the record"));
    connect(m_slider, &QSlider::sliderMoved, this, &ReplayWindow::seek);
    connect(m_slider, &QSlider::actionTriggered, this, [this](int action) {
        if (action != QAbstractSlider::SliderMove) // page / step clicks and keys
            QTimer::singleShot(0, this, [this] { seek(m_slider->value()); });
    });
    bar->addWidget(m_slider);
    m_position = new QLabel(bar);
    m_position->setMinimumWidth(260);
    bar->addWidget(m_position);

    m_timer = new QTimer(this);
    m_timer->setInterval(kTickMs);
    connect(m_timer, &QTimer::timeout, this, &ReplayWindow::tick);
    resize(1280, 800);
    seek(1); // the initial state
}

ReplayWindow::~ReplayWindow() = default;

int ReplayWindow::rowsShown() const {
    return m_playback->shown();
}

int ReplayWindow::rowCount() const {
    return m_playback->rows();
}

bool ReplayWindow::isPlaying() const {
    return m_timer->isActive();
}

void ReplayWindow::play() {
    if (m_playback->atEnd())
        seek(1); // play again from the start
    m_wall.start();
    m_timer->start();
    updateControls();
}

void ReplayWindow::pause() {
    m_timer->stop();
    updateControls();
}

void ReplayWindow::seek(int n) {
    bool restart = false;
    const std::vector<StepRecord> rows = m_playback->seek(n, &restart);
    showRows(rows, restart);
}

void ReplayWindow::setSpeed(double factor) {
    m_playback->setSpeed(factor);
    const int i = m_speed->findData(m_playback->speed());
    if (i >= 0 && i != m_speed->currentIndex())
        m_speed->setCurrentIndex(i);
}

void ReplayWindow::tick() {
    const double wall = double(m_wall.nsecsElapsed()) * 1e-9;
    m_wall.restart();
    showRows(m_playback->advance(wall), false);
    if (m_playback->atEnd()) {
        pause();
        emit finished();
    }
}

void ReplayWindow::showRows(const std::vector<StepRecord>& rows, bool restart) {
    if (restart)
        m_panel->clearData();
    m_panel->appendRecords(rows);
    if (restart || !rows.empty())
        m_panel->refresh();
    updateControls();
    emit positionChanged(m_playback->shown());
}

void ReplayWindow::updateControls() {
    m_playAction->setText(isPlaying() ? tr("Pause") : tr("Play"));
    if (!m_slider->isSliderDown())
        m_slider->setValue(m_playback->shown());
    m_position->setText(tr(" t = %1 s   step %2 of %3 ")
                            .arg(m_playback->time(), 0, 'f', 3)
                            .arg(m_playback->step())
                            .arg(m_playback->data().steps.back()));
}

} // namespace hsmu::gui
