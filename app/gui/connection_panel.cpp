// The connection panel's settings form (connection_panel.h): the target's protocols, the port
// or host, the line settings from each protocol's defaults, remembered per family. The live
// side (connecting, testing, state, traffic) is connection_panel_link.cpp.

#include "connection_panel.h"

#include "dialogs.h"
#include "line_settings_form.h"
#include "wheel_guard.h"

#include "comms/driver/connection.h"
#include "comms/driver/protocol_driver.h"
#include "comms/transport/serial_transport.h"
#include "editor/terminal_widgets.h"
#include "model/target/protocol_map.h"
#include "model/target/target.h"

#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QFontDatabase>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QSettings>
#include <QSpinBox>
#include <QStyle>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

namespace rung::app {

namespace {

using comms::ConnectionSettings;
using comms::ProtocolKind;

// The traffic log keeps this many lines (the session's tap keeps its own ring).
constexpr int kTrafficLines = 5000;

QString settingsKey(const QString &name) {
    return QStringLiteral("online/") + name;
}

} // namespace

ConnectionPanel::ConnectionPanel(QWidget *parent)
    : QWidget(parent) {
    setObjectName(QStringLiteral("connectionPanel"));
    build();
    guardWheel(this); // scrolling the dock never changes a setting (issue 31)
    retranslate();
    refreshPorts();
    updateState();
}

ConnectionPanel::~ConnectionPanel() {
    // The views hold the session through QPointer; it goes before the widgets do.
    m_test.reset();
    m_session.reset();
}

void ConnectionPanel::build() {
    auto *layout = new QVBoxLayout(this);
    m_targetLabel = new QLabel;
    m_targetLabel->setObjectName(QStringLiteral("connectionTarget"));
    m_targetLabel->setWordWrap(true);
    layout->addWidget(m_targetLabel);
    m_vpcNote = new QLabel;
    m_vpcNote->setObjectName(QStringLiteral("connectionUnpublished"));
    m_vpcNote->setWordWrap(true);
    m_vpcNote->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_vpcNote);

    m_settingsBox = new QGroupBox;
    m_settingsBox->setObjectName(QStringLiteral("connectionSettings"));
    auto *form = new QFormLayout(m_settingsBox);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    // A narrow dock (a long Hungarian label) puts the label above its field.
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    m_protocol = new QComboBox;
    m_protocol->setObjectName(QStringLiteral("connectionProtocol"));
    // The dock may be narrow: the combos take the width they are given.
    m_protocol->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_protocol->setMinimumContentsLength(8);
    m_protocolLabel = new QLabel;
    form->addRow(m_protocolLabel, m_protocol);
    auto *via = new QHBoxLayout;
    m_viaSerial = new QRadioButton;
    m_viaSerial->setObjectName(QStringLiteral("connectionViaSerial"));
    m_viaTcp = new QRadioButton;
    m_viaTcp->setObjectName(QStringLiteral("connectionViaTcp"));
    m_viaSerial->setChecked(true);
    via->addWidget(m_viaSerial);
    via->addWidget(m_viaTcp);
    via->addStretch();
    form->addRow(via);

    // The port or host and the line (line_settings_form.h), as a network's bridges ask them.
    m_line = new LineSettingsForm(QStringLiteral("connection"));
    showVia(0);
    form->addRow(m_line);

    m_station = new QSpinBox;
    m_station->setObjectName(QStringLiteral("connectionStation"));
    m_timeout = new QSpinBox;
    m_timeout->setObjectName(QStringLiteral("connectionTimeout"));
    m_timeout->setRange(20, 30000);
    m_timeout->setSingleStep(100);
    m_timeout->setValue(1000);
    m_retries = new QSpinBox;
    m_retries->setObjectName(QStringLiteral("connectionRetries"));
    m_retries->setRange(0, 10);
    m_retries->setValue(2);
    m_stationLabel = new QLabel;
    m_timeoutLabel = new QLabel;
    m_retriesLabel = new QLabel;
    form->addRow(m_stationLabel, m_station);
    form->addRow(m_timeoutLabel, m_timeout);
    form->addRow(m_retriesLabel, m_retries);
    layout->addWidget(m_settingsBox);

    // The buttons wrap in a column beside the ladder (dock_layout.h) rather than make the
    // panel wider than it: past its width the panel scrolls and its texts were cut.
    auto *buttonRow = new QWidget;
    auto *buttons = new editor::FlowLayout(buttonRow);
    m_testButton = new QPushButton;
    m_testButton->setObjectName(QStringLiteral("connectionTest"));
    m_connect = new QPushButton;
    m_connect->setObjectName(QStringLiteral("connectionConnect"));
    m_connect->setDefault(true);
    buttons->addWidget(m_testButton);
    buttons->addWidget(m_connect);
    layout->addWidget(buttonRow);

    const auto label = [layout](const char *name) {
        auto *l = new QLabel;
        l->setObjectName(QString::fromLatin1(name));
        l->setWordWrap(true);
        l->setTextInteractionFlags(Qt::TextSelectableByMouse);
        layout->addWidget(l);
        return l;
    };
    m_state = label("connectionState");
    m_state->setStyleSheet(QStringLiteral("QLabel { font-weight: bold; }"));
    m_warning = label("connectionWarning");
    // A warning looks like one: dark amber on pale amber, a sign before it, not bold.
    m_warning->setStyleSheet(
        QStringLiteral("QLabel { color: #5d4000; background: #fff1c4; border: 1px solid #e0b000; "
                       "padding: 2px 4px; }"));
    m_warning->hide();
    m_testResult = label("connectionTestResult");
    m_notice = label("connectionNotice");
    m_statistics = label("connectionStatistics");
    m_command = label("connectionCommand");

    m_trafficBox = new QGroupBox;
    auto *trafficLayout = new QVBoxLayout(m_trafficBox);
    auto *trafficRow = new QWidget;
    auto *trafficButtons = new editor::FlowLayout(trafficRow);
    m_record = new QCheckBox;
    m_record->setObjectName(QStringLiteral("connectionRecordTraffic"));
    m_record->setChecked(true);
    m_clear = new QPushButton;
    m_clear->setObjectName(QStringLiteral("connectionClearTraffic"));
    m_save = new QPushButton;
    m_save->setObjectName(QStringLiteral("connectionSaveTraffic"));
    trafficButtons->addWidget(m_record);
    trafficButtons->addWidget(m_clear);
    trafficButtons->addWidget(m_save);
    trafficLayout->addWidget(trafficRow);
    m_traffic = new QPlainTextEdit;
    m_traffic->setObjectName(QStringLiteral("connectionTraffic"));
    m_traffic->setReadOnly(true);
    m_traffic->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_traffic->setMaximumBlockCount(kTrafficLines);
    m_traffic->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_traffic->setMinimumHeight(m_traffic->fontMetrics().lineSpacing() * 8);
    trafficLayout->addWidget(m_traffic);
    layout->addWidget(m_trafficBox, 1);

    connect(m_protocol, &QComboBox::activated, this, [this] { protocolChosen(); });
    connect(m_viaSerial, &QRadioButton::toggled, this,
            [this](bool serial) { showVia(serial ? 0 : 1); });
    connect(m_testButton, &QPushButton::clicked, this, [this] { testConnection(); });
    connect(m_connect, &QPushButton::clicked, this, [this] {
        if (m_session)
            disconnectFromPlc();
        else
            connectToPlc();
    });
    connect(m_record, &QCheckBox::toggled, this, [this](bool on) {
        if (m_session)
            m_session->setTrafficTap(on);
    });
    connect(m_clear, &QPushButton::clicked, m_traffic, &QPlainTextEdit::clear);
    // Save... is the window's: it owns the file dialogs (main_window_online.cpp).
    connect(m_save, &QPushButton::clicked, this, &ConnectionPanel::saveTrafficRequested);
}

void ConnectionPanel::retranslate() {
    m_settingsBox->setTitle(tr("Settings"));
    m_protocolLabel->setText(tr("Protocol:"));
    m_viaSerial->setText(tr("Serial port"));
    m_viaTcp->setText(tr("TCP"));
    m_line->portBox()->setToolTip(
        tr("A serial port, or a path typed in: a pseudo-terminal such as the one\n"
           "'rungstudio-cli serve --pty' prints, or the link that\n"
           "'serve --pty --link PATH' keeps at PATH, which still leads to the\n"
           "PLC after serve restarts"));
    m_stationLabel->setText(tr("Station:"));
    m_timeoutLabel->setText(tr("Timeout (ms):"));
    m_retriesLabel->setText(tr("Retries:"));
    m_testButton->setText(tr("Test Connection"));
    m_trafficBox->setTitle(tr("Traffic"));
    m_record->setText(tr("Record"));
    m_clear->setText(tr("Clear"));
    m_save->setText(tr("Save..."));
    for (int i = 0; i < m_protocol->count(); ++i)
        m_protocol->setItemText(i,
                                comms::protocolName(ProtocolKind(m_protocol->itemData(i).toInt())));
    if (m_target)
        setTarget(*m_target, m_modelName); // the texts that name the target
    retranslateResults();
    updateState();
}

void ConnectionPanel::changeEvent(QEvent *event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void ConnectionPanel::setTarget(const model::Target &target, const QString &modelName) {
    const bool changed = m_target != &target;
    if (changed && m_session)
        disconnectFromPlc(); // the views would read the new family's devices from the old PLC
    m_target = &target;
    m_modelName = modelName;
    m_targetLabel->setText(modelName.isEmpty()
                               ? tr("PLC: %1").arg(target.displayName)
                               : tr("PLC: %1, model %2").arg(target.displayName, modelName));
    const bool speaks = canConnect();
    m_vpcNote->setVisible(!speaks);
    m_vpcNote->setText(
        tr("The link protocol of the %1 is not published, so the IDE cannot talk to it. "
           "Instead: export the program as a console listing (File > Export Instruction List) and "
           "load "
           "it with the PLC's own tool; to study the link, capture its traffic with "
           "'rungstudio-cli record'.")
            .arg(target.displayName));
    m_settingsBox->setEnabled(speaks);
    if (changed || m_protocol->count() == 0)
        fillProtocols();
    updateState();
}

bool ConnectionPanel::canConnect() const {
    return m_target && !comms::protocolsOf(*m_target).empty();
}

void ConnectionPanel::fillProtocols() {
    m_protocol->clear();
    if (!m_target)
        return;
    for (ProtocolKind kind : comms::protocolsOf(*m_target))
        m_protocol->addItem(comms::protocolName(kind), int(kind));
    // The protocol last used with this family, else the first.
    const int last =
        QSettings().value(settingsKey(QStringLiteral("protocol/") + m_target->id), -1).toInt();
    if (const int i = m_protocol->findData(last); i >= 0)
        m_protocol->setCurrentIndex(i);
    m_protocolLabel->setVisible(m_protocol->count() > 1);
    m_protocol->setVisible(m_protocol->count() > 1);
    protocolChosen();
}

ProtocolKind ConnectionPanel::protocol() const {
    return ProtocolKind(m_protocol->currentData().toInt());
}

void ConnectionPanel::protocolChosen() {
    if (m_protocol->count() == 0)
        return;
    ConnectionSettings s = comms::defaultSettings(protocol());
    QSettings saved;
    s.port = saved.value(settingsKey(QStringLiteral("port"))).toString();
    s.host =
        saved.value(settingsKey(QStringLiteral("host")), QStringLiteral("127.0.0.1")).toString();
    s.tcpPort = quint16(saved.value(settingsKey(QStringLiteral("tcpPort")), 502).toInt());
    s.via = protocol() == ProtocolKind::ModbusTcp ? ConnectionSettings::Via::Tcp
                                                  : ConnectionSettings::Via::Serial;
    setSettings(s);
}

void ConnectionPanel::showVia(int page) {
    m_line->showPage(page == 0 ? LineSettingsForm::Page::Serial : LineSettingsForm::Page::Tcp);
}

QString ConnectionPanel::cannotConnectReason() const {
    return canConnect() ? QString() : m_vpcNote->text();
}

void ConnectionPanel::refreshPorts() {
    m_line->refreshPorts();
}

comms::ConnectionSettings ConnectionPanel::settings() const {
    ConnectionSettings s = comms::defaultSettings(protocol());
    s.via = m_viaTcp->isChecked() ? ConnectionSettings::Via::Tcp : ConnectionSettings::Via::Serial;
    s.port = m_line->port();
    s.serial = m_line->line();
    s.host = m_line->host();
    s.tcpPort = quint16(m_line->tcpPort());
    s.station = m_station->value();
    s.link.timeoutMs = m_timeout->value();
    s.link.retries = m_retries->value();
    return s;
}

void ConnectionPanel::setSettings(const comms::ConnectionSettings &s) {
    if (const int i = m_protocol->findData(int(s.protocol)); i >= 0)
        m_protocol->setCurrentIndex(i);
    (s.via == ConnectionSettings::Via::Tcp ? m_viaTcp : m_viaSerial)->setChecked(true);
    m_line->setPort(s.port);
    m_line->setLine(s.serial);
    m_line->setHost(s.host);
    m_line->setTcpPort(s.tcpPort);
    // The stations the protocol numbers (Vigor 0..255, Modbus 1..247, Host Link 0..31); a
    // PL110 answers 255 too, "any station" (PL110 manual 3.1).
    comms::StationRange stations = comms::stationRange(s.protocol);
    if (const model::ProtocolMap *map =
            m_target ? model::findProtocolMap(*m_target, comms::protocolIdOf(s.protocol)) : nullptr;
        map && map->anyStationUnit > stations.last)
        stations.last = map->anyStationUnit;
    m_station->setRange(stations.first, stations.last);
    m_station->setValue(s.station);
    m_timeout->setValue(s.link.timeoutMs);
    m_retries->setValue(s.link.retries);
}

void ConnectionPanel::remember() const {
    QSettings saved;
    const ConnectionSettings s = settings();
    saved.setValue(settingsKey(QStringLiteral("protocol/") + m_target->id), int(s.protocol));
    if (!s.port.isEmpty())
        saved.setValue(settingsKey(QStringLiteral("port")), s.port);
    saved.setValue(settingsKey(QStringLiteral("host")), s.host);
    saved.setValue(settingsKey(QStringLiteral("tcpPort")), s.tcpPort);
}

bool ConnectionPanel::confirm(const QString &title, const QString &text) {
    if (m_confirmer)
        return m_confirmer(title, text);
    return messageBox(QMessageBox::Question, this, title, text,
                      QMessageBox::Yes | QMessageBox::No) == QMessageBox::Yes;
}

} // namespace rung::app
