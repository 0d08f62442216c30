#include "gui/replay/ReplayWindow.h"

#include "core/record/RecordReader.h"
#include "gui/app/AlarmText.h"
#include "gui/app/LiveText.h"
#include "gui/plots/LivePlotsPanel.h"
#include "gui/replay/RecordPlayback.h"
#include "gui/replay/Reidentification.h"
#include "gui/replay/ReidentifyDialog.h"
#include "gui/replay/ReplayPanels.h"
#include "gui/plots/HistoryPlot.h"

#include <QAction>
#include <QComboBox>
#include <QDockWidget>
#include <QMenu>
#include <QMenuBar>
#include <QEventLoop>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QProgressDialog>
#include <QSlider>
#include <QThread>
#include <QTimer>
#include <QToolBar>

#include <exception>
#include <optional>

namespace hsmu::gui {

struct ReplayWindow::Outcome {
    std::optional<Reidentification> value;
    QString error;
};

namespace {

/// The record's data, or nullptr with the reader's message in error. Any thread.
std::shared_ptr<const RecordData> loadRecord(const QString& path, QString& error) {
    try {
        const RecordReader reader(path.toStdString());
        if (reader.rows() == 0)
            throw std::runtime_error(path.toStdString() + ": the record holds no step");
        return std::make_shared<const RecordData>(reader.data());
    } catch (const std::exception& e) {
        error = QString::fromStdString(e.what());
        return nullptr;
    }
}

} // namespace

ReplayWindow* ReplayWindow::open(const QString& path, QWidget* parent, QString* error) {
    QString why;
    auto data = loadRecord(path, why);
    if (!data) {
        if (error)
            *error = why;
        return nullptr;
    }
    return new ReplayWindow(std::move(data), path, parent);
}

ReplayWindow* ReplayWindow::openInBackground(const QString& path, QWidget* parent,
                                             QString* error) {
    struct Loaded {
        std::shared_ptr<const RecordData> data;
        QString error;
    };
    auto loaded = std::make_shared<Loaded>(); // shared: a cancelled worker may outlive us
    QThread* worker = QThread::create([loaded, path] {
        loaded->data = loadRecord(path, loaded->error);
    });
    QProgressDialog busy(parent); // Qt's own (translated) Cancel button
    busy.setWindowTitle(tr("Open record"));
    busy.setLabelText(QFileInfo(path).fileName());
    busy.setRange(0, 0); // a busy indicator
    busy.setMinimumDuration(0);
    busy.setWindowModality(Qt::WindowModal);
    QEventLoop loop;
    QObject::connect(worker, &QThread::finished, &loop, &QEventLoop::quit);
    QObject::connect(worker, &QThread::finished, worker, &QObject::deleteLater);
    QObject::connect(&busy, &QProgressDialog::canceled, &loop, &QEventLoop::quit);
    worker->start();
    busy.show();
    loop.exec();
    if (error)
        error->clear();
    if (!worker->isFinished() && busy.wasCanceled())
        return nullptr; // the worker ends within the reader's deadline and deletes itself
    busy.close();
    if (!loaded->data) {
        if (error)
            *error = loaded->error;
        return nullptr;
    }
    return new ReplayWindow(loaded->data, path, parent);
}

ReplayWindow* ReplayWindow::openWithDialog(QWidget* parent) {
    const QString path = QFileDialog::getOpenFileName(
        parent, tr("Open record"), QString(), tr("HSMU records (*.h5 *.hdf5);;All files (*)"));
    if (path.isEmpty())
        return nullptr;
    QString error;
    ReplayWindow* window = openInBackground(path, parent, &error);
    if (!window) {
        if (!error.isEmpty())
            QMessageBox::critical(parent, tr("Cannot open the record"),
                                  AlarmText::reason(error)); // the reader's text, translated
        return nullptr;
    }
    window->setAttribute(Qt::WA_DeleteOnClose);
    window->setWindowFlag(Qt::Window);
    window->QMainWindow::show();
    return window;
}

ReplayWindow::ReplayWindow(std::shared_ptr<const RecordData> data, const QString& path,
                           QWidget* parent)
    : QMainWindow(parent), m_playback(std::make_unique<RecordPlayback>(std::move(data))),
      m_path(path) {
    setWindowFlag(Qt::Window);
    const RecordData& d = m_playback->data();
    live([this, name = QString::fromStdString(d.meta.configName), file = QFileInfo(path).fileName()] {
        setWindowTitle(tr("HSMU Replay - %1 (%2)").arg(name, file));
    });

    m_panel = new LivePlotsPanel(this);
    m_panel->configure(d.layout, PlotReferences::ofConfigurationJson(d.meta.configuration));
    m_panel->setGroundMotion(
        QVector<double>(d.time.data(), d.time.data() + d.time.size()),
        QVector<double>(d.groundAcceleration.data(),
                        d.groundAcceleration.data() + d.groundAcceleration.size()));
    setCentralWidget(m_panel);

    auto* bar = addToolBar(QString());
    bar->setObjectName(QStringLiteral("replayToolBar"));
    live([bar] { bar->setWindowTitle(tr("Replay")); });
    m_playAction = bar->addAction(QString());
    m_playAction->setShortcut(Qt::Key_Space);
    connect(m_playAction, &QAction::triggered, this, [this] { isPlaying() ? pause() : play(); });
    auto* speedLabel = new QLabel(bar);
    bar->addWidget(speedLabel);
    m_speed = new QComboBox(bar);
    for (const double s : {0.25, 0.5, 1.0, 2.0, 5.0, 10.0, 50.0})
        m_speed->addItem(QString(), s);
    m_speed->setCurrentIndex(2);
    live([this, speedLabel] {
        speedLabel->setText(tr(" Speed "));
        for (int i = 0; i < m_speed->count(); ++i)
            m_speed->setItemText(i, tr("%1 x").arg(m_speed->itemData(i).toDouble()));
        m_speed->setToolTip(tr("Test seconds per wall second"));
    });
    connect(m_speed, &QComboBox::currentIndexChanged, this,
            [this](int i) { setSpeed(m_speed->itemData(i).toDouble()); });
    bar->addWidget(m_speed);
    m_slider = new QSlider(Qt::Horizontal, bar);
    m_slider->setRange(0, m_playback->rows());
    m_slider->setMinimumWidth(300);
    live([this] { m_slider->setToolTip(tr("Scrub through the record")); });
    connect(m_slider, &QSlider::sliderMoved, this, &ReplayWindow::seek);
    connect(m_slider, &QSlider::actionTriggered, this, [this](int action) {
        if (action != QAbstractSlider::SliderMove) // page / step clicks and keys
            QTimer::singleShot(0, this, [this] { seek(m_slider->value()); });
    });
    bar->addWidget(m_slider);
    m_position = new QLabel(bar);
    m_position->setMinimumWidth(260);
    bar->addWidget(m_position);
    bar->addSeparator();
    m_reidentifyAction = bar->addAction(QString());
    live([this] {
        m_reidentifyAction->setText(tr("Re-identify..."));
        m_reidentifyAction->setToolTip(tr(
            "Identify the specimen again with other settings and overlay the parameter history"));
    });
    m_reidentifyAction->setEnabled(d.layout.updating.has_value()); // else no parameter plot
    connect(m_reidentifyAction, &QAction::triggered, this, &ReplayWindow::reidentifyWithDialog);
    m_busy = new QProgressBar(bar);
    m_busy->setRange(0, 0); // busy indicator
    m_busy->setMaximumWidth(120);
    live([this] {
        m_busy->setFormat(tr("identifying"));
        m_busy->setToolTip(tr("Re-identifying the specimen"));
    });
    m_busyAction = bar->addWidget(m_busy);
    m_busyAction->setVisible(false);

    m_timer = new QTimer(this);
    m_timer->setInterval(kTickMs);
    connect(m_timer, &QTimer::timeout, this, &ReplayWindow::tick);
    buildPanelsAndMenus();
    LiveText::bind(this, [this] {
        for (const auto& texts : m_texts)
            texts();
        updateControls();
    });
    resize(1280, 720);
    seek(1); // the initial state
}

ReplayWindow::~ReplayWindow() {
    if (m_reidentifier) { // identifyOffline cannot be interrupted: let it end
        m_reidentifier->disconnect(this);
        m_reidentifier->wait();
        delete m_reidentifier;
    }
}

QString ReplayWindow::reidentifiedCurveName(const QString& method) {
    return tr("re-identified (%1)").arg(method);
}

void ReplayWindow::reidentifyWithDialog() {
    const auto& updating = m_playback->data().layout.updating;
    ReidentifyDialog dialog(updating ? QString::fromStdString(updating->method) : QString(), this);
    if (dialog.exec() == QDialog::Accepted)
        reidentify(dialog.method(), dialog.overridePath());
}

void ReplayWindow::reidentify(const QString& method, const QString& overridePath) {
    if (m_reidentifier)
        return;
    m_outcome = std::make_shared<Outcome>();
    m_reidentifier = QThread::create(
        [outcome = m_outcome, data = &m_playback->data(), source = m_path, method, overridePath] {
            try {
                outcome->value = reidentifyRecord(*data, source, method, overridePath);
            } catch (const std::exception& e) {
                outcome->error = QString::fromStdString(e.what());
            }
        });
    m_reidentifier->setObjectName(QStringLiteral("hsmu re-identification"));
    connect(m_reidentifier, &QThread::finished, this, &ReplayWindow::showReidentification);
    m_reidentifyAction->setEnabled(false);
    m_busyAction->setVisible(true);
    m_reidentifier->start();
}

void ReplayWindow::showReidentification() {
    m_reidentifier->wait();
    delete m_reidentifier;
    m_reidentifier = nullptr;
    const std::shared_ptr<Outcome> outcome = std::move(m_outcome);
    m_reidentifyAction->setEnabled(true);
    m_busyAction->setVisible(false);
    if (!outcome->value) {
        auto* box = new QMessageBox(QMessageBox::Critical, tr("Re-identification failed"),
                                    AlarmText::reason(outcome->error), QMessageBox::Ok, this);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open(); // not exec(): the window stays live
        emit reidentificationFailed(outcome->error);
        return;
    }
    const OfflineIdentificationResult& r = outcome->value->result;
    const QString curve = reidentifiedCurveName(QString::fromStdString(r.method));
    const std::vector<double>& t = outcome->value->time;
    const QVector<double> time(t.begin(), t.end());
    for (std::size_t j = 0; j < r.parameterNames.size(); ++j) {
        QVector<double> values(r.parameters.rows());
        for (Eigen::Index k = 0; k < r.parameters.rows(); ++k)
            values[k] = r.parameters(k, Eigen::Index(j));
        m_panel->overlayParameterHistory(curve, QString::fromStdString(r.parameterNames[j]), time,
                                         values);
    }
    emit reidentified(curve);
}

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

void ReplayWindow::buildPanelsAndMenus() {
    const RecordData& d = m_playback->data();
    m_events = new ReplayEventList(d, this);
    connect(m_events, &ReplayEventList::jumpTo, this, [this](int rows) {
        pause();
        seek(rows);
    });
    auto* events = new QDockWidget(this);
    live([events] { events->setWindowTitle(tr("Events, alarms and notes")); });
    events->setObjectName(QStringLiteral("replayEventsDock"));
    events->setWidget(m_events);
    addDockWidget(Qt::BottomDockWidgetArea, events);
    m_readout = new ReplayReadout(d, this);
    auto* readout = new QDockWidget(this);
    live([readout] { readout->setWindowTitle(tr("Values at the cursor")); });
    readout->setObjectName(QStringLiteral("replayReadoutDock"));
    readout->setWidget(m_readout);
    addDockWidget(Qt::RightDockWidgetArea, readout);
    connect(this, &ReplayWindow::positionChanged, m_readout,
            [this](int shown) { m_readout->showRow(shown - 1); });

    QMenu* file = menuBar()->addMenu(QString());
    QAction* csv = file->addAction(QString(), this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export time window"),
                                                          QString(), tr("CSV files (*.csv)"));
        QString error;
        if (!path.isEmpty() && !exportWindowCsv(path, &error))
            QMessageBox::warning(this, tr("Export time window"), error);
    });
    QAction* plots = file->addAction(QString(), this, [this] {
        QString filter;
        const QString base = QFileDialog::getSaveFileName(
            this, tr("Export plots"), QString(),
            tr("PNG images (*.png);;SVG drawings (*.svg);;PDF documents (*.pdf)"), &filter);
        if (base.isEmpty())
            return;
        const QFileInfo info(base);
        const QString format = info.suffix().isEmpty()
                                   ? filter.section(QStringLiteral("*."), 1).left(3)
                                   : info.suffix();
        QStringList errors;
        ReplayExport::exportPlots(m_panel->findChildren<QCustomPlot*>(), info.absolutePath(),
                                  format, &errors);
        if (!errors.isEmpty())
            QMessageBox::warning(this, tr("Export plots"), errors.join(QLatin1Char('\n')));
    });
    file->addSeparator();
    QAction* close = file->addAction(QString(), this, &QWidget::close);
    close->setObjectName(QStringLiteral("closeReplay"));
    close->setShortcuts({QKeySequence::Close, QKeySequence(Qt::CTRL | Qt::Key_W)});
    QMenu* playback = menuBar()->addMenu(QString());
    playback->addAction(m_playAction);
    QAction* back = playback->addAction(QString(), this, [this] {
        pause();
        seek(m_playback->shown() - 1);
    });
    back->setShortcut(Qt::Key_Left);
    QAction* forward = playback->addAction(QString(), this, [this] {
        pause();
        seek(m_playback->shown() + 1);
    });
    forward->setShortcut(Qt::Key_Right);
    QAction* start = playback->addAction(QString(), this, [this] { seek(1); });
    start->setShortcut(Qt::Key_Home);
    QAction* end = playback->addAction(QString(), this, [this] { seek(m_playback->rows()); });
    end->setShortcut(Qt::Key_End);
    QMenu* view = menuBar()->addMenu(QString());
    view->addAction(events->toggleViewAction());
    view->addAction(readout->toggleViewAction());
    live([=] {
        file->setTitle(tr("&File"));
        csv->setText(tr("Export time window as &CSV..."));
        plots->setText(tr("Export &plots (PNG, SVG or PDF)..."));
        close->setText(tr("&Close"));
        playback->setTitle(tr("&Playback"));
        back->setText(tr("Step &back"));
        forward->setText(tr("Step &forward"));
        start->setText(tr("To the &start"));
        end->setText(tr("To the &end"));
        view->setTitle(tr("&View"));
    });
}

void ReplayWindow::live(std::function<void()> texts) {
    texts();
    m_texts.push_back(std::move(texts));
}

bool ReplayWindow::exportWindowCsv(const QString& path, QString* error, int* rows) const {
    // The time window shown by the displacement plot (zoom it to pin a window).
    const auto* plot = m_panel->findChild<HistoryPlot*>(QStringLiteral("displacementPlot"));
    const QCPRange r = plot ? plot->xAxis->range() : QCPRange(-1e300, 1e300);
    return ReplayExport::exportWindowCsv(m_playback->data(), r.lower, r.upper, path, error, rows);
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
