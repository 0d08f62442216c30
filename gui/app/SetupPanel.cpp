#include "gui/app/SetupPanel.h"

#include "gui/app/LiveText.h"

#include "core/output/ElementUnits.h"
#include "gui/ConfigOverrides.h"
#include "gui/app/PendingUpdatesPanel.h"
#include "gui/app/SiteHealthView.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStyle>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>
#include <limits>
#include <vector>

namespace hsmu::gui {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

QDoubleSpinBox* spin(QWidget* parent, double lo, double hi, int decimals, const QString& suffix) {
    auto* s = new QDoubleSpinBox(parent);
    s->setRange(lo, hi);
    s->setDecimals(decimals);
    s->setSuffix(suffix);
    return s;
}

// A form that fits a narrow dock (1280x720, long translations): a field that does not fit
// beside its label goes below it, labels wrap.
QFormLayout* narrowForm(QWidget* box) {
    auto* form = new QFormLayout(box);
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    return form;
}

QString limitText(double v) {
    return std::isfinite(v) && v > 0.0 ? QString::number(v, 'g', 6) : QStringLiteral("0");
}
} // namespace

SetupPanel::SetupPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("setupPanel"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    m_name = new QLabel(this);
    m_name->setObjectName(QStringLiteral("setupName"));
    m_name->setWordWrap(true);
    // A long path must not widen the dock (nor the window): wrapped, cut, full in the tip.
    m_name->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_name->setMinimumWidth(1);
    layout->addWidget(m_name);
    // No values are shown before a configuration is loaded (no placeholder numbers).
    m_body = new QWidget(this);
    m_body->setObjectName(QStringLiteral("setupBody"));
    auto* body = new QVBoxLayout(m_body);
    body->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_body);
    body->addWidget(buildRunGroup());
    body->addWidget(buildControllerGroup());
    m_sites = new SiteHealthView(this); // sites of the configuration (hidden without)
    body->addWidget(m_sites);

    auto* limitsBox = new QGroupBox(this);
    auto* lv = new QVBoxLayout(limitsBox);
    m_limits = new QTableWidget(0, 4, limitsBox);
    m_limits->setObjectName(QStringLiteral("limitsTable"));
    m_limits->verticalHeader()->hide();
    m_limits->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_limits->setMaximumHeight(110);
    connect(m_limits, &QTableWidget::itemChanged, this, &SetupPanel::markDirty);
    connect(m_limits->horizontalHeader(), &QHeaderView::sectionResized, this,
            &SetupPanel::fitLimitHeaders);
    lv->addWidget(m_limits);
    body->addWidget(limitsBox);
    body->addWidget(buildUpdatingGroup());

    m_apply = new QPushButton(this);
    m_apply->setObjectName(QStringLiteral("applySetup"));
    connect(m_apply, &QPushButton::clicked, this, &SetupPanel::applyRequested);
    body->addWidget(m_apply);
    m_body->hide();
    layout->addStretch(1);
    m_inputs << m_groundMotion << m_recordDt << m_scale << m_dt << m_duration << m_integrator << m_alpha
             << m_controllerKind << m_host << m_port << m_token << m_limits << m_updating << m_threshold;
    setEditable(true);
    m_apply->setEnabled(false);
    LiveText::bind(this, [this, limitsBox] {
        showName();
        limitsBox->setTitle(tr("Safety limits (0 = none; the specimen's units)"));
        m_limitHeaders = {tr("Specimen"), tr("Max |d|"), tr("Max |F|"), tr("Max |Δd| per step")};
        m_limits->setHorizontalHeaderLabels(m_limitHeaders);
        fitLimitHeaders();
        m_apply->setText(tr("Apply (reload the test)"));
    });
}

QWidget* SetupPanel::buildRunGroup() {
    auto* box = new QGroupBox(this);
    auto* form = narrowForm(box);
    m_groundMotion = new QLineEdit(box);
    m_groundMotion->setObjectName(QStringLiteral("groundMotionFile"));
    auto* browse = new QPushButton(box);
    connect(browse, &QPushButton::clicked, this, &SetupPanel::browseGroundMotion);
    auto* gmRow = new QHBoxLayout;
    gmRow->addWidget(m_groundMotion, 1);
    gmRow->addWidget(browse);
    auto* gmLabel = new QLabel(box);
    form->addRow(gmLabel, gmRow);
    m_groundMotionStatus = new QLabel(box);
    m_groundMotionStatus->setObjectName(QStringLiteral("groundMotionStatus"));
    m_groundMotionStatus->setWordWrap(true);
    m_groundMotionStatus->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_groundMotionStatus->setMinimumWidth(1);
    m_groundMotionStatus->setStyleSheet(QStringLiteral("color: #c62828;"));
    m_groundMotionStatus->hide();
    form->addRow(m_groundMotionStatus);
    connect(m_groundMotion, &QLineEdit::editingFinished, this, [this] {
        if (m_groundMotion->isModified()) {
            m_groundMotion->setModified(false);
            emit groundMotionChosen();
        }
    });
    m_recordDt = spin(box, 0.0, 1.0, 5, QStringLiteral(" s"));
    m_recordDt->setObjectName(QStringLiteral("recordTimeStep"));
    form->addRow(new QLabel(box), m_recordDt);
    connect(m_recordDt, &QDoubleSpinBox::editingFinished, this, [this] {
        if (m_recordDt->property("checked").toDouble() != m_recordDt->value()) {
            m_recordDt->setProperty("checked", m_recordDt->value());
            emit groundMotionChosen(); // a one-column file refused for want of it: check again
        }
    });
    m_scale = spin(box, 0.0, 100.0, 3, QString());
    m_scale->setObjectName(QStringLiteral("groundMotionScale"));
    form->addRow(new QLabel(box), m_scale);
    m_dt = spin(box, 1e-5, 1.0, 5, QStringLiteral(" s"));
    m_dt->setObjectName(QStringLiteral("timeStep"));
    form->addRow(new QLabel(box), m_dt);
    m_duration = spin(box, 0.0, 1e5, 2, QStringLiteral(" s"));
    form->addRow(new QLabel(box), m_duration);
    m_integrator = new QComboBox(box);
    m_integrator->addItem(QString(), QStringLiteral("explicitNewmark"));
    m_integrator->addItem(QString(), QStringLiteral("alphaOS"));
    form->addRow(new QLabel(box), m_integrator);
    m_alpha = spin(box, -1.0 / 3.0, 0.0, 3, QString());
    form->addRow(new QLabel(box), m_alpha);
    LiveText::bind(box, [this, box, form, browse, gmLabel] {
        box->setTitle(tr("Run"));
        browse->setText(tr("Browse..."));
        gmLabel->setText(tr("Ground motion file:"));
        m_recordDt->setSpecialValueText(tr("from the file"));
        m_recordDt->setToolTip(
            tr("The time between the record's samples. A file of acceleration values only (one "
               "column) needs it; an AT2 header or a time column gives its own. Not the "
               "integration step dt."));
        setLabel(form, m_recordDt, tr("Record's sample step [s]:"));
        setLabel(form, m_scale, tr("Scale [-]:"));
        setLabel(form, m_dt, tr("Time step dt [s]:"));
        m_duration->setSpecialValueText(tr("whole record"));
        setLabel(form, m_duration, tr("Duration [s]:"));
        m_integrator->setItemText(0, tr("explicit Newmark"));
        m_integrator->setItemText(1, tr("alpha-OS"));
        setLabel(form, m_integrator, tr("Integrator:"));
        setLabel(form, m_alpha, tr("alpha-OS alpha [-]:"));
    });
    connect(m_integrator, &QComboBox::currentIndexChanged, this, [this] {
        m_alpha->setEnabled(m_editable && m_integrator->currentData() == QStringLiteral("alphaOS"));
        markDirty();
    });
    connect(m_groundMotion, &QLineEdit::textEdited, this, &SetupPanel::markDirty);
    for (QDoubleSpinBox* s : {m_recordDt, m_scale, m_dt, m_duration, m_alpha})
        connect(s, &QDoubleSpinBox::valueChanged, this, &SetupPanel::markDirty);
    return box;
}

QWidget* SetupPanel::buildControllerGroup() {
    auto* box = new QGroupBox(this);
    auto* form = narrowForm(box);
    m_controllerKind = new QComboBox(box);
    m_controllerKind->setObjectName(QStringLiteral("controllerKind"));
    // The long kinds (OpenSees adapter ...) must not widen the dock: the box shows what fits
    // (elided), the list shows the whole texts, the tool tip the chosen one.
    m_controllerKind->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_controllerKind->setMinimumContentsLength(14);
    // OpenFresco's protocols (docs/openfresco.md); dataSize and sizes come from the
    // configuration's controller section. adapter: OpenSees' adapter element (OpenSees
    // listens on HOST:PORT; a numerical substructure in an OpenSees model).
    for (const char* scheme : {"builtin", "tcp", "simapp", "generictcp", "adapter", "tls"})
        m_controllerKind->addItem(QString(), QString::fromLatin1(scheme));
    m_host = new QLineEdit(QStringLiteral("127.0.0.1"), box);
    m_host->setObjectName(QStringLiteral("controllerHost"));
    m_port = new QSpinBox(box);
    m_port->setObjectName(QStringLiteral("controllerPort"));
    m_port->setRange(1, 65535);
    m_port->setValue(5600);
    form->addRow(new QLabel(box), m_controllerKind);
    form->addRow(new QLabel(box), m_host);
    form->addRow(new QLabel(box), m_port);
    // What the chosen link needs on the other side (e.g. the adapter's OpenSees model).
    m_linkNote = new QLabel(box);
    m_linkNote->setObjectName(QStringLiteral("linkNote"));
    m_linkNote->setWordWrap(true);
    m_linkNote->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_linkNote->setMinimumWidth(1);
    m_linkNote->hide();
    form->addRow(m_linkNote);
    // The controller's shared secret: kept in memory for this session only, never in the
    // settings file.
    m_token = new QLineEdit(box);
    m_token->setObjectName(QStringLiteral("controllerToken"));
    m_token->setEchoMode(QLineEdit::Password);
    form->addRow(new QLabel(box), m_token);
    auto* testLink = new QPushButton(box);
    testLink->setObjectName(QStringLiteral("testLink"));
    connect(testLink, &QPushButton::clicked, this, &SetupPanel::testLinkRequested);
    form->addRow(QString(), testLink);
    connect(m_token, &QLineEdit::textEdited, this, &SetupPanel::markDirty);
    connect(m_controllerKind, &QComboBox::currentIndexChanged, this, [this] {
        m_controllerKind->setToolTip(m_controllerKind->currentText());
        enableLinkFields();
        showLinkNote();
        markDirty();
    });
    LiveText::bind(box, [this, box, form, testLink] {
        box->setTitle(tr("Controller"));
        const QString kinds[] = {tr("built-in virtual lab"), tr("hsmu-controller over TCP"),
                                 tr("OpenFresco SimApp site"),
                                 tr("OpenFresco GenericTCP controller"),
                                 tr("OpenSees adapter element (numerical substructure)"),
                                 tr("hsmu-controller over TLS (the configuration's tls block)")};
        for (int i = 0; i < m_controllerKind->count(); ++i) {
            m_controllerKind->setItemText(i, kinds[i]);
            m_controllerKind->setItemData(i, kinds[i], Qt::ToolTipRole);
        }
        m_controllerKind->setToolTip(m_controllerKind->currentText());
        setLabel(form, m_controllerKind, tr("Specimens driven by:"));
        setLabel(form, m_host, tr("Host:"));
        setLabel(form, m_port, tr("Port:"));
        m_token->setPlaceholderText(tr("none"));
        m_token->setToolTip(tr("The token hsmu-controller --token expects; not saved"));
        setLabel(form, m_token, tr("Token:"));
        testLink->setText(tr("Test link"));
        testLink->setToolTip(tr("Connect to the controller now (the test is prepared; nothing "
                                "moves before the pre-flight check)"));
        showLinkNote();
    });
    connect(m_host, &QLineEdit::textEdited, this, &SetupPanel::markDirty);
    connect(m_port, &QSpinBox::valueChanged, this, &SetupPanel::markDirty);
    return box;
}

QWidget* SetupPanel::buildUpdatingGroup() {
    auto* box = new QGroupBox(this);
    auto* form = narrowForm(box);
    m_updating = new QCheckBox(box);
    form->addRow(m_updating);
    // One control decides when updates are applied: the Pending updates panel's.
    auto* policy = new QLabel(box);
    policy->setWordWrap(true);
    form->addRow(policy);
    m_threshold = spin(box, 0.001, 10.0, 3, QString());
    form->addRow(new QLabel(box), m_threshold);
    LiveText::bind(box, [this, box, form, policy] {
        box->setTitle(tr("Online model updating"));
        m_updating->setText(tr("enabled"));
        policy->setText(tr("When updates are applied is chosen in the Pending updates "
                           "panel (one setting for the test)."));
        setLabel(form, m_threshold, tr("Fit-error threshold [-]:"));
    });
    connect(m_updating, &QCheckBox::toggled, this, &SetupPanel::markDirty);
    connect(m_threshold, &QDoubleSpinBox::valueChanged, this, &SetupPanel::markDirty);
    return box;
}

void SetupPanel::fitLimitHeaders() {
    // A header wider than its column ("Max |Δd| per ste") is broken at spaces into lines that
    // fit; the header grows to hold them. The whole text is also the tool tip.
    QHeaderView* header = m_limits->horizontalHeader();
    const QFontMetrics fm(header->font());
    const int margin = 2 * header->style()->pixelMetric(QStyle::PM_HeaderMargin, nullptr, header) + 4;
    for (int c = 0; c < m_limitHeaders.size() && c < m_limits->columnCount(); ++c) {
        const int room = header->sectionSize(c) - margin;
        QStringList lines;
        for (const QString& word : m_limitHeaders[c].split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
            const QString joined = lines.isEmpty() ? word : lines.back() + QLatin1Char(' ') + word;
            if (!lines.isEmpty() && fm.horizontalAdvance(joined) <= room)
                lines.back() = joined;
            else
                lines << word;
        }
        QTableWidgetItem* item = m_limits->horizontalHeaderItem(c);
        if (!item)
            continue;
        const QString text = lines.join(QLatin1Char('\n'));
        if (item->text() != text)
            item->setText(text);
        item->setToolTip(m_limitHeaders[c]);
    }
}

void SetupPanel::setGroundMotionStatus(const QString& error) {
    m_groundMotionStatus->setText(error);
    m_groundMotionStatus->setToolTip(error);
    m_groundMotionStatus->setVisible(!error.isEmpty());
}

void SetupPanel::showName() {
    if (!m_loaded) {
        m_name->setText(tr("No configuration loaded: choose a preset or open a file."));
        m_groundMotion->setPlaceholderText(tr("the configuration's record"));
        return;
    }
    m_name->setText(tr("Configuration: %1\n%2")
                        .arg(QString::fromStdString(m_base.name),
                             m_base.sourcePath.empty() ? tr("(built in)")
                                                       : QString::fromStdString(m_base.sourcePath)));
    m_name->setToolTip(m_name->text());
    m_groundMotion->setPlaceholderText(
        m_base.groundMotion.file.empty()
            ? tr("built-in %1 record")
                  .arg(m_base.groundMotion.builtin == "synthetic"
                           ? tr("synthetic") // the configuration's keyword, translated
                           : QString::fromStdString(m_base.groundMotion.builtin))
            : QString::fromStdString(m_base.groundMotion.file));
}

void SetupPanel::setLabel(QFormLayout* form, QWidget* field, const QString& text) {
    if (auto* label = qobject_cast<QLabel*>(form->labelForField(field)))
        label->setText(text);
}

void SetupPanel::enableLinkFields() {
    const QString scheme = m_controllerKind->currentData().toString();
    const bool remote = scheme != QStringLiteral("builtin");
    m_host->setEnabled(remote && m_editable);
    m_port->setEnabled(remote && m_editable);
    // Only hsmu-controller asks for a token; OpenFresco's and OpenSees' peers know none.
    m_token->setEnabled((scheme == QStringLiteral("tcp") || scheme == QStringLiteral("tls")) &&
                        m_editable);
}

void SetupPanel::showLinkNote() {
    const QString scheme = m_controllerKind->currentData().toString();
    QString note;
    if (scheme == QStringLiteral("adapter"))
        note = tr("OpenSees listens: start the model with its `element adapter ... PORT` first "
                  "(its analyze must have at least the test's steps). A step is final once the "
                  "next one is sent: after a hold the test cannot repeat it.");
    m_linkNote->setText(note);
    m_linkNote->setToolTip(note);
    m_linkNote->setVisible(!note.isEmpty());
}

QString SetupPanel::groundMotionStatus() const {
    return m_groundMotionStatus->isHidden() ? QString() : m_groundMotionStatus->text();
}

void SetupPanel::browseGroundMotion() {
    const QString file = QFileDialog::getOpenFileName(
        this, tr("Ground motion record"), QString(),
        tr("Ground motions (*.AT2 *.at2 *.txt *.csv *.dat);;All files (*)"));
    if (file.isEmpty())
        return;
    m_groundMotion->setText(file);
    markDirty();
    emit groundMotionChosen(); // checked and plotted at once
}

void SetupPanel::setSiteMonitor(std::shared_ptr<const SiteMonitor> monitor) {
    m_sites->setMonitor(std::move(monitor));
}

void SetupPanel::setConfig(const TestConfig& cfg) {
    m_base = cfg;
    m_loaded = true;
    m_sites->setConfig(cfg);
    {
        std::vector<QSignalBlocker> blocks;
        blocks.reserve(std::size_t(m_inputs.size()));
        for (QWidget* w : m_inputs)
            blocks.emplace_back(w);
        showName();
        m_body->show();
        setGroundMotionStatus(QString());
        m_groundMotion->clear();
        m_recordDt->setValue(cfg.groundMotion.dt);
        m_recordDt->setProperty("checked", m_recordDt->value());
        m_scale->setValue(cfg.groundMotion.scale);
        m_dt->setValue(cfg.analysis.dt);
        m_duration->setValue(std::max(0.0, cfg.analysis.duration));
        m_integrator->setCurrentIndex(
            std::max(0, m_integrator->findData(QString::fromStdString(cfg.analysis.integrator))));
        m_alpha->setValue(cfg.analysis.alpha);
        m_limits->setRowCount(0);
        for (const ElementSpec& e : cfg.elements) {
            if (!e.experimental)
                continue;
            const int row = m_limits->rowCount();
            m_limits->insertRow(row);
            const ElementUnits u = elementUnits(e.type);
            auto* name = new QTableWidgetItem(QString::fromStdString(e.name));
            name->setFlags(name->flags() & ~Qt::ItemIsEditable);
            name->setToolTip(
                tr("d in %1, F in %2")
                    .arg(QString::fromStdString(u.deformation), QString::fromStdString(u.force)));
            m_limits->setItem(row, 0, name);
            m_limits->setItem(row, 1, new QTableWidgetItem(limitText(e.limits.maxDeformation)));
            m_limits->setItem(row, 2, new QTableWidgetItem(limitText(e.limits.maxForce)));
            m_limits->setItem(row, 3, new QTableWidgetItem(limitText(e.limits.maxIncrement)));
            for (int c = 1; c < 4; ++c)
                m_limits->item(row, c)->setToolTip(c == 2 ? QString::fromStdString(u.force)
                                                          : QString::fromStdString(u.deformation));
        }
        const UpdatingSpec& up = cfg.updating;
        const bool canUpdate = up.enabled || !up.specimen.empty();
        m_updating->setChecked(up.enabled);
        m_updating->setProperty("available", canUpdate);
        m_threshold->setValue(up.inspector.threshold);
    }
    markApplied();
    setEditable(m_editable);
}

std::optional<TestConfig> SetupPanel::edited(QString* error) const {
    auto fail = [error](const QString& why) -> std::optional<TestConfig> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    if (!m_loaded)
        return fail(tr("no configuration loaded"));
    TestConfig cfg = m_base;
    ConfigOverrides o;
    o.groundMotionFile = m_groundMotion->text().trimmed();
    o.recordDt = m_recordDt->value();
    o.scale = m_scale->value();
    o.dt = m_dt->value();
    o.duration = m_duration->value();
    o.applyTo(cfg);
    cfg.analysis.integrator = m_integrator->currentData().toString().toStdString();
    cfg.analysis.alpha = m_alpha->value();
    int row = 0;
    for (ElementSpec& e : cfg.elements) {
        if (!e.experimental)
            continue;
        double v[3];
        for (int c = 1; c < 4; ++c) {
            bool ok = false;
            const QString text = m_limits->item(row, c)->text().trimmed();
            v[c - 1] = text.toDouble(&ok);
            if (!ok || !(v[c - 1] >= 0.0) || !std::isfinite(v[c - 1]))
                return fail(tr("safety limit of %1: '%2' is not a number >= 0")
                                .arg(QString::fromStdString(e.name), text));
            if (v[c - 1] == 0.0)
                v[c - 1] = kInf;
        }
        e.limits.maxDeformation = v[0];
        e.limits.maxForce = v[1];
        e.limits.maxIncrement = v[2];
        ++row;
    }
    if (m_updating->isChecked() && cfg.updating.specimen.empty())
        return fail(tr("this configuration has no updating section to enable"));
    cfg.updating.enabled = m_updating->isChecked();
    cfg.updating.inspector.threshold = m_threshold->value();
    return cfg;
}

std::optional<comms::LinkAddress> SetupPanel::controller(QString* error) const {
    std::string why;
    auto a = comms::LinkAddress::parse(controllerText().toStdString(), &why);
    if (!a && error)
        *error = QString::fromStdString(why);
    return a;
}

QString SetupPanel::controllerText() const {
    const QString scheme = m_controllerKind->currentData().toString();
    if (scheme == QStringLiteral("builtin"))
        return scheme;
    return QStringLiteral("%1://%2:%3").arg(scheme, m_host->text().trimmed()).arg(m_port->value());
}

QString SetupPanel::token() const {
    return m_token->text();
}

void SetupPanel::setControllerAddress(const QString& address) {
    const auto a = comms::LinkAddress::parse(address.toStdString());
    if (!a)
        return;
    using Kind = comms::LinkAddress::Kind;
    const QString scheme = a->kind == Kind::Tcp          ? QStringLiteral("tcp")
                           : a->kind == Kind::SimApp     ? QStringLiteral("simapp")
                           : a->kind == Kind::GenericTcp ? QStringLiteral("generictcp")
                           : a->kind == Kind::Adapter    ? QStringLiteral("adapter")
                           : a->kind == Kind::Tls        ? QStringLiteral("tls")
                                                         : QStringLiteral("builtin");
    m_controllerKind->setCurrentIndex(m_controllerKind->findData(scheme));
    if (a->kind != Kind::Builtin) {
        m_host->setText(QString::fromStdString(a->host));
        m_port->setValue(a->port);
    }
}

void SetupPanel::setEditable(bool editable) {
    m_editable = editable;
    for (QWidget* w : m_inputs)
        w->setEnabled(editable);
    enableLinkFields();
    m_alpha->setEnabled(editable && m_integrator->currentData() == QStringLiteral("alphaOS"));
    m_updating->setEnabled(editable && m_updating->property("available").toBool());
    for (QPushButton* b : findChildren<QPushButton*>())
        b->setEnabled(editable && (b != m_apply || m_dirty));
}

void SetupPanel::markDirty() {
    if (!m_loaded || m_dirty)
        return;
    m_dirty = true;
    m_apply->setEnabled(m_editable);
    emit dirtyChanged(true);
}

void SetupPanel::markApplied() {
    m_dirty = false;
    m_apply->setEnabled(false);
    emit dirtyChanged(false);
}

} // namespace hsmu::gui
