#include "gui/plots/LivePlotsPanel.h"

#include "core/config/TestFactory.h"
#include "gui/plots/ActuatorsPanel.h"
#include "gui/app/LiveText.h"
#include "gui/plots/HistoryPlot.h"
#include "gui/plots/HysteresisPlot.h"
#include "gui/plots/ParameterPlot.h"
#include "gui/plots/PlotElementPicker.h"
#include "gui/plots/PlotExporter.h"
#include "gui/plots/PlotStyle.h"
#include "gui/plots/PlotTools.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QSplitter>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <exception>

namespace hsmu::gui {

namespace {

constexpr int kParameterColumns = 4;
constexpr int kNoteRow = 99; // below every row of parameter plots
constexpr int kSmallPlotWidth = 160;  // [px] minimum, so the panel fits a 1280 x 800 window
constexpr int kSmallPlotHeight = 110; // [px]

int specimenOf(const RunLayout& layout) {
    // The identified specimen, as the hysteresis plot and the Parameters dock show it.
    for (std::size_t i = 0; i < layout.elements.size() && layout.updating; ++i)
        if (layout.elements[i].experimental && layout.elements[i].name == layout.updating->specimen)
            return int(i);
    for (std::size_t i = 0; i < layout.elements.size(); ++i)
        if (layout.elements[i].experimental)
            return int(i);
    return -1;
}

std::vector<int> specimensOf(const RunLayout& layout) {
    std::vector<int> out;
    for (std::size_t i = 0; i < layout.elements.size(); ++i)
        if (layout.elements[i].experimental)
            out.push_back(int(i));
    return out;
}

// A plot under its element picker (the header row, hidden with a single choice).
QWidget* underPicker(QWidget* parent, PlotElementPicker*& picker, QCustomPlot* plot,
                     const char* name) {
    auto* box = new QWidget(parent);
    auto* v = new QVBoxLayout(box);
    v->setContentsMargins(0, 0, 0, 0);
    v->setSpacing(0);
    picker = new PlotElementPicker(box);
    picker->setObjectName(QString::fromLatin1(name));
    plot->setParent(box);
    v->addWidget(picker);
    v->addWidget(plot, 1);
    return box;
}

// Only the rows' time and element samples (and the auxiliary force) are kept: a picked
// element's whole history can be drawn again without the DOF vectors.
StepRecord slim(const StepRecord& r) {
    StepRecord s;
    s.step = r.step;
    s.time = r.time;
    s.elements = r.elements;
    s.hasUpdating = r.hasUpdating;
    s.updating.auxiliaryForce = r.updating.auxiliaryForce;
    return s;
}

template <typename Plot> Plot* makePlot(QWidget* parent, const char* name) {
    auto* plot = new Plot(parent);
    plot->setObjectName(QString::fromLatin1(name));
    plot->setMinimumSize(kSmallPlotWidth, kSmallPlotHeight);
    return plot;
}

} // namespace

LivePlotsPanel::LivePlotsPanel(QWidget* parent) : QWidget(parent) {
    auto* vertical = new QSplitter(Qt::Vertical, this);
    auto* top = new QSplitter(Qt::Horizontal, vertical);
    m_hysteresis = makePlot<HysteresisPlot>(nullptr, "hysteresisPlot"); // into its box below
    QWidget* hysteresisBox =
        underPicker(top, m_hysteresisPicker, m_hysteresis, "hysteresisElement");
    auto* histories = new QWidget(top);
    auto* grid = new QGridLayout(histories);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->setSpacing(2);
    m_force = makePlot<HistoryPlot>(histories, "forcePlot");
    m_displacement = makePlot<HistoryPlot>(histories, "displacementPlot");
    m_ground = makePlot<HistoryPlot>(histories, "groundMotionPlot");
    m_tracking = makePlot<HistoryPlot>(histories, "trackingPlot");
    grid->addWidget(underPicker(histories, m_forcePicker, m_force, "forceElement"), 0, 0);
    grid->addWidget(m_displacement, 0, 1);
    grid->addWidget(m_ground, 1, 0);
    grid->addWidget(underPicker(histories, m_trackingPicker, m_tracking, "trackingElement"), 1,
                    1);
    grid->setColumnStretch(0, 1); // a picker above a plot never widens its column
    grid->setColumnStretch(1, 1);
    top->addWidget(hysteresisBox);
    top->addWidget(histories);
    top->setStretchFactor(0, 2);
    top->setStretchFactor(1, 3);
    top->setSizes({400, 600}); // proportions: the loop gets two fifths of the width

    m_parameterArea = new QWidget(vertical);
    m_parameterGrid = new QGridLayout(m_parameterArea);
    m_parameterGrid->setContentsMargins(0, 0, 0, 0);
    m_parameterGrid->setSpacing(2);
    m_fitError = makePlot<HistoryPlot>(m_parameterArea, "fitErrorPlot");
    m_parameterGrid->addWidget(m_fitError, 0, 0);
    m_overlayNote = new QLabel(m_parameterArea);
    m_overlayNote->setObjectName(QStringLiteral("overlayNote"));
    m_overlayNote->setWordWrap(true);
    m_overlayNote->hide();
    m_parameterGrid->addWidget(m_overlayNote, kNoteRow, 0, 1, kParameterColumns);
    LiveText::bind(m_overlayNote, [this] { showOverlayNote(); });
    m_fitError->yAxis->ticker()->setTickCount(3);
    m_actuators = new ActuatorsPanel(vertical);
    vertical->addWidget(top);
    vertical->addWidget(m_parameterArea);
    vertical->addWidget(m_actuators);
    vertical->setStretchFactor(0, 3);
    vertical->setStretchFactor(1, 2);
    vertical->setStretchFactor(2, 2);
    vertical->setSizes({600, 400, 400});

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(vertical);

    for (QCustomPlot* p : std::initializer_list<QCustomPlot*>{m_hysteresis, m_force, m_displacement,
                                                              m_ground, m_tracking, m_fitError,
                                                              &m_actuators->plot()})
        enableExportMenu(p);
    connect(m_hysteresisPicker, &PlotElementPicker::elementPicked, this,
            [this](int e) { showPicked(*m_hysteresis, [this, e] { showHysteresisOf(e); }); });
    connect(m_forcePicker, &PlotElementPicker::elementPicked, this,
            [this](int e) { showPicked(*m_force, [this, e] { showForceOf(e); }); });
    connect(m_trackingPicker, &PlotElementPicker::elementPicked, this,
            [this](int e) { showPicked(*m_tracking, [this, e] { showTrackingOf(e); }); });
    m_redrawTimer = new QTimer(this);
    m_redrawTimer->setSingleShot(true);
    connect(m_redrawTimer, &QTimer::timeout, this, &LivePlotsPanel::refreshNow);
    configure(RunLayout{});
}

void LivePlotsPanel::configure(const RunLayout& layout, const PlotReferences& references) {
    m_layout = layout;
    // Each per-element plot keeps the operator's pick while its element exists; by default
    // it shows the element the Parameters dock identifies.
    const std::vector<int> loops = HysteresisPlot::loopElements(layout);
    const int loopDefault = HysteresisPlot::defaultElement(layout);
    showHysteresisOf(m_hysteresisPicker->setChoices(layout, loops, loopDefault));
    showForceOf(m_forcePicker->setChoices(layout, loops, loopDefault));
    m_displacement->showDisplacements(layout);
    m_ground->showGroundAcceleration();
    m_fixedGroundMotion = false;
    const int specimen = m_trackingPicker->setChoices(layout, specimensOf(layout), specimenOf(layout));
    m_hasSpecimen = specimen >= 0;
    if (m_hasSpecimen)
        showTrackingOf(specimen);
    m_tracking->setVisible(m_hasSpecimen);
    m_hasUpdating = layout.updating.has_value();
    m_fitError->showFitError(m_hasUpdating ? references.fitThreshold : qQNaN());
    rebuildParameterPlots(layout, references);
    m_parameterArea->setVisible(m_hasUpdating);
    m_actuators->configure(layout, references);
    m_actuators->setVisible(m_actuators->hasChannels());
    clearData();
    // Another test: the last one's zoom and time span go (autoscale on, no time span known).
    for (QCustomPlot* p : allPlots()) {
        PlotStyle::setEmptyXRange(*p, qQNaN(), qQNaN());
        PlotTools::attach(*p)->setAutoscale(true);
    }
    refreshNow();
}

void LivePlotsPanel::showHysteresisOf(int element) {
    m_hysteresis->showElements(m_layout, HysteresisPlot::withTwins(m_layout, element));
    const bool identified = element >= 0 && m_layout.updating &&
                            m_layout.elements[std::size_t(element)].name == m_layout.updating->specimen;
    if (identified) // the auxiliary model describes the identified specimen only
        m_hysteresis->addAuxiliaryModel(m_layout);
    nameSubject(*m_hysteresis, *m_hysteresisPicker);
}

void LivePlotsPanel::showForceOf(int element) {
    m_force->showForces(m_layout, HysteresisPlot::withTwins(m_layout, element));
    nameSubject(*m_force, *m_forcePicker);
}

void LivePlotsPanel::showTrackingOf(int element) {
    if (element >= 0)
        m_tracking->showTracking(m_layout, element);
    nameSubject(*m_tracking, *m_trackingPicker);
}

void LivePlotsPanel::nameSubject(QCustomPlot& plot, const PlotElementPicker& picker) {
    // With a choice the read-out names the element shown (the title does too).
    PlotTools::attach(plot)->setSubject(picker.isVisibleTo(this) ? picker.elementName()
                                                                 : QString());
}

void LivePlotsPanel::showPicked(QCustomPlot& plot, const std::function<void()>& show) {
    PlotTools* tools = PlotTools::attach(plot);
    tools->hideReadout(); // it described the other element
    show();
    // The new element's whole history, from the rows kept so far.
    if (auto* h = qobject_cast<HysteresisPlot*>(&plot)) {
        h->clearData();
        h->appendRecords(m_history);
    } else if (auto* g = qobject_cast<HistoryPlot*>(&plot)) {
        g->clearData();
        g->appendRecords(m_history);
    }
    tools->setAutoscale(true); // another element: its own ranges
    PlotStyle::rescaleWithMargin(plot);
    plot.replot(QCustomPlot::rpRefreshHint);
}

std::vector<QCustomPlot*> LivePlotsPanel::allPlots() const {
    std::vector<QCustomPlot*> out{m_hysteresis, m_force,    m_displacement,       m_ground,
                                  m_tracking,   m_fitError, &m_actuators->plot()};
    out.insert(out.end(), m_parameters.begin(), m_parameters.end());
    return out;
}

void LivePlotsPanel::configure(const RunLayout& layout, const TestConfig& cfg) {
    configure(layout, PlotReferences::of(cfg));
    // On failure the test's own loader reports the problem; the rows carry the acceleration.
    showGroundMotionOf(cfg);
}

bool LivePlotsPanel::showGroundMotionOf(const TestConfig& cfg, QString* error) {
    try {
        const GroundMotion g = buildGroundMotion(cfg.groundMotion, cfg.sourcePath);
        QVector<double> t(qsizetype(g.acceleration.size())), a(t.size());
        for (qsizetype i = 0; i < t.size(); ++i) {
            t[i] = double(i) * g.dt;
            a[i] = g.acceleration[std::size_t(i)];
        }
        if (cfg.analysis.duration > 0.0) { // the test stops there: show what it applies
            qsizetype n = 0;
            while (n < t.size() && t[n] <= cfg.analysis.duration + 1e-9)
                ++n;
            t.resize(n);
            a.resize(n);
        }
        setGroundMotion(t, a);
        return true;
    } catch (const std::exception& e) {
        if (error)
            *error = QString::fromStdString(e.what());
        return false;
    }
}

void LivePlotsPanel::setGroundMotion(const QVector<double>& time,
                                     const QVector<double>& acceleration) {
    m_ground->showGroundMotion(time, acceleration);
    m_fixedGroundMotion = true;
    m_ground->refresh();
    // Before the first steps the time axes span the test: 0 to the record's (cut) end.
    std::vector<QCustomPlot*> timed{m_force, m_displacement, m_tracking, m_fitError,
                                    &m_actuators->plot()};
    timed.insert(timed.end(), m_parameters.begin(), m_parameters.end());
    for (QCustomPlot* p : timed)
        PlotStyle::setEmptyXRange(*p, 0.0, time.isEmpty() ? qQNaN() : time.back());
    if (m_rows <= 1)
        refreshNow();
}

bool LivePlotsPanel::overlayParameterHistory(const QString& curveName, const QString& parameter,
                                             const QVector<double>& time,
                                             const QVector<double>& values) {
    for (ParameterPlot* p : m_parameters)
        if (p->parameterName() == parameter) {
            p->setOverlay(curveName, time, values);
            p->refresh();
            if (!m_overlays.contains(curveName))
                m_overlays << curveName;
            showOverlayNote();
            return true;
        }
    return false;
}

void LivePlotsPanel::showOverlayNote() {
    QStringList parts;
    for (const QString& name : m_overlays) {
        const QCPGraph* g =
            m_parameters.empty() ? nullptr : m_parameters.front()->overlayGraph(name);
        const QString colour = g ? g->pen().color().name() : QStringLiteral("#000000");
        parts << QStringLiteral("<span style=\"color:%1\"><b>- - -</b></span> %2")
                     .arg(colour, name.toHtmlEscaped());
    }
    m_overlayNote->setText(parts.isEmpty() ? QString()
                                           : tr("Dashed: %1").arg(parts.join(QStringLiteral(", "))));
    m_overlayNote->setVisible(!parts.isEmpty());
}

bool LivePlotsPanel::setParameterBounds(const QString& parameter, double lower, double upper) {
    for (ParameterPlot* p : m_parameters)
        if (p->parameterName() == parameter) {
            if (p->setBounds(lower, upper))
                p->refresh();
            return true;
        }
    return false;
}

void LivePlotsPanel::rebuildParameterPlots(const RunLayout& layout,
                                           const PlotReferences& references) {
    for (ParameterPlot* p : m_parameters)
        delete p;
    m_parameters.clear();
    m_overlays.clear();
    showOverlayNote();
    if (!layout.updating)
        return;
    const auto& names = layout.updating->parameters;
    for (std::size_t i = 0; i < names.size(); ++i) {
        auto* plot = makePlot<ParameterPlot>(m_parameterArea, "parameterPlot");
        const QString name = QString::fromStdString(names[i]);
        plot->setObjectName(QStringLiteral("parameterPlot_%1").arg(name));
        plot->showParameter(name, int(i));
        const auto b = references.bounds.find(names[i]);
        if (b != references.bounds.end())
            plot->setBounds(b->second.lower, b->second.upper);
        plot->legend->setVisible(i == 0); // one legend explains the band for the row
        const int cell = int(i) + 1;      // cell 0: the fit error
        m_parameterGrid->addWidget(plot, cell / kParameterColumns, cell % kParameterColumns);
        enableExportMenu(plot);
        m_parameters.push_back(plot);
    }
}

void LivePlotsPanel::appendRecords(const std::vector<StepRecord>& rows) {
    if (rows.empty())
        return;
    m_hysteresis->appendRecords(rows);
    m_actuators->appendRecords(rows);
    m_force->appendRecords(rows);
    m_displacement->appendRecords(rows);
    if (!m_fixedGroundMotion)
        m_ground->appendRecords(rows);
    m_ground->setTimeCursor(rows.back().time);
    if (m_hasSpecimen)
        m_tracking->appendRecords(rows);
    if (m_hasUpdating) {
        m_fitError->appendRecords(rows);
        for (ParameterPlot* p : m_parameters)
            p->appendRecords(rows);
    }
    m_rows += qint64(rows.size());
    for (const StepRecord& r : rows)
        m_history.push_back(slim(r));
}

void LivePlotsPanel::clearData() {
    // A read-out describes the data shown: it goes with them (another test's elements).
    for (QCustomPlot* p : std::initializer_list<QCustomPlot*>{m_hysteresis, m_force, m_displacement,
                                                              m_ground, m_tracking, m_fitError,
                                                              &m_actuators->plot()})
        PlotTools::attach(*p)->hideReadout();
    for (ParameterPlot* p : m_parameters)
        PlotTools::attach(*p)->hideReadout();
    m_hysteresis->clearData();
    m_actuators->clearData();
    m_force->clearData();
    m_displacement->clearData();
    if (!m_fixedGroundMotion)
        m_ground->clearData();
    m_ground->setTimeCursor(qQNaN());
    m_tracking->clearData();
    m_fitError->clearData();
    for (ParameterPlot* p : m_parameters)
        p->clearData();
    m_rows = 0;
    m_history.clear();
}

std::vector<QCustomPlot*> LivePlotsPanel::visiblePlots() const {
    std::vector<QCustomPlot*> out;
    for (const NamedPlot& p : plots())
        out.push_back(p.plot);
    out.insert(out.end(), m_parameters.begin(), m_parameters.end());
    return out;
}

void LivePlotsPanel::refresh() {
    if (m_redrawTimer->isActive())
        return; // a redraw is already due: it will show these rows too
    const qint64 wait =
        m_sinceRedraw.isValid() ? m_intervalMs - m_sinceRedraw.elapsed() : qint64(0);
    if (wait > 0)
        m_redrawTimer->start(int(wait));
    else
        refreshNow();
}

void LivePlotsPanel::refreshNow() {
    m_redrawTimer->stop();
    QElapsedTimer cost;
    cost.start();
    for (QCustomPlot* p : visiblePlots()) {
        PlotStyle::rescaleWithMargin(*p);
        p->replot(QCustomPlot::rpRefreshHint); // draws into the plot's buffer now
    }
    const qint64 ms = cost.elapsed();
    m_intervalMs = int(std::clamp<qint64>(kBudgetFactor * ms, kMinIntervalMs, kMaxIntervalMs));
    m_sinceRedraw.start();
    ++m_redraws;
}

std::vector<LivePlotsPanel::NamedPlot> LivePlotsPanel::plots() const {
    std::vector<NamedPlot> out{{QStringLiteral("hysteresis"), m_hysteresis},
                               {QStringLiteral("force"), m_force},
                               {QStringLiteral("displacement"), m_displacement},
                               {QStringLiteral("ground_motion"), m_ground}};
    if (m_hasSpecimen)
        out.push_back({QStringLiteral("tracking"), m_tracking});
    if (m_hasUpdating)
        out.push_back({QStringLiteral("fit_error"), m_fitError});
    if (m_actuators->hasChannels())
        out.push_back({QStringLiteral("channels"), &m_actuators->plot()});
    return out;
}

QStringList LivePlotsPanel::exportAll(const QString& dir, const QString& suffix,
                                      QStringList* errors) {
    QStringList written;
    auto save = [&](QCustomPlot& plot, const QString& base) {
        const QString path = QDir(dir).filePath(base + QLatin1Char('.') + suffix);
        QString why;
        if (PlotExporter::saveAs(plot, path, PlotExporter::kWidth, PlotExporter::kHeight, &why))
            written << path;
        else if (errors)
            *errors << why;
    };
    for (const NamedPlot& p : plots())
        save(*p.plot, p.fileBase);
    for (ParameterPlot* p : m_parameters)
        save(*p, QStringLiteral("parameter_%1").arg(PlotExporter::fileSafe(p->yAxis->label())));
    return written;
}

void LivePlotsPanel::enableExportMenu(QCustomPlot* plot) {
    // The image exports join the plot's one context menu (PlotTools: autoscale, channels,
    // the visible data as CSV).
    connect(PlotTools::attach(*plot), &PlotTools::menuRequested, this,
            [this, plot](QMenu* menu) { addExportActions(plot, menu); });
}

void LivePlotsPanel::addExportActions(QCustomPlot* plot, QMenu* menu) {
    menu->addSeparator();
    menu->addAction(tr("Export this plot..."), this, [this, plot] { exportPlotWithDialog(plot); });
    menu->addAction(tr("Export all plots..."), this, &LivePlotsPanel::exportAllWithDialog);
}

void LivePlotsPanel::exportPlotWithDialog(QCustomPlot* plot) {
    const QString png = tr("PNG image (*.png)"), svg = tr("SVG drawing (*.svg)"),
                  pdf = tr("PDF document (*.pdf)");
    QString filter = png;
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export plot"), QString(), QStringList{png, svg, pdf}.join(QStringLiteral(";;")),
        &filter);
    if (path.isEmpty())
        return;
    QString file = path;
    if (QFileInfo(file).suffix().isEmpty())
        file += filter == svg ? QStringLiteral(".svg")
                              : (filter == pdf ? QStringLiteral(".pdf") : QStringLiteral(".png"));
    QString why;
    if (!PlotExporter::saveAs(*plot, file, plot->width(), plot->height(), &why))
        QMessageBox::warning(this, tr("Export failed"), why);
}

void LivePlotsPanel::exportAllWithDialog() {
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Export all plots to"));
    if (dir.isEmpty())
        return;
    QStringList errors;
    for (const QString& suffix :
         {QStringLiteral("png"), QStringLiteral("svg"), QStringLiteral("pdf")})
        exportAll(dir, suffix, &errors);
    if (!errors.isEmpty())
        QMessageBox::warning(this, tr("Export failed"), errors.join(QLatin1Char('\n')));
}

} // namespace hsmu::gui
