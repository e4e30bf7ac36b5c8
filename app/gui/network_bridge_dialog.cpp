#include "app/gui/network_bridge_dialog.h"

#include "app/gui/line_settings_form.h"
#include "app/gui/network_port_dialog.h"

#include "model/comm/port_spec.h"
#include "model/comm/serial_line.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace rung::app {

namespace {

using BridgeKind = network::BridgeDescription::Kind;

// The formats a bridged serial port may take: the application's own when it has one.
QStringList bridgeFrames(const model::PortApplication &a) {
    return a.fixedFrame ? QStringList{QString::fromLatin1(a.frame)} : portFrameChoices();
}

} // namespace

NetworkBridgeDialog::NetworkBridgeDialog(const network::BridgeDescription &bridge,
                                         const model::PortApplication &application,
                                         const model::SerialSettings &line,
                                         const QJsonObject &settings, QWidget *parent)
    : QDialog(parent)
    , m_bridge(bridge)
    , m_application(application)
    , m_settings(settings)
    , m_baud(line.baud)
    , m_frame(model::frameFormatText(line)) {
    setObjectName(QStringLiteral("networkBridgeDialog"));
    //: %1 a station's port, "s5/CP2"
    setWindowTitle(tr("Bridge of %1").arg(bridge.end));
    auto *layout = new QVBoxLayout(this);
    auto *head = new QLabel(tr("While the network runs, %1 is put on a real line: a master on "
                               "this computer or the network reaches the simulated station, or "
                               "the station reaches a real device.")
                                .arg(bridge.end),
                            this);
    head->setWordWrap(true);
    layout->addWidget(head);
    const QString texts[4] = {tr("&Pseudo-terminal (a master on this computer)"),
                              tr("&Serial port"), tr("TCP: &connect to a serial device server"),
                              tr("TCP: &listen for a master")};
    const char *names[4] = {"bridgePty", "bridgeSerial", "bridgeTcp", "bridgeListen"};
    for (int i = 0; i < 4; ++i) {
        m_kinds[i] = new QRadioButton(texts[i], this);
        m_kinds[i]->setObjectName(QString::fromLatin1(names[i]));
        layout->addWidget(m_kinds[i]);
        connect(m_kinds[i], &QRadioButton::toggled, this, [this](bool on) {
            if (on)
                kindChosen();
        });
    }
    m_line = new LineSettingsForm(QStringLiteral("bridge"), this);
    m_line->portBox()->setToolTip(
        tr("The serial port the real line is on (a USB adapter: /dev/ttyUSB0)"));
    std::vector<int> bauds = application.bauds;
    if (std::find(bauds.begin(), bauds.end(), line.baud) == bauds.end())
        bauds.push_back(line.baud);
    m_line->setBauds(bauds);
    m_line->setFrames(bridgeFrames(application));
    m_line->setLine(line);
    layout->addWidget(m_line);
    m_note = new QLabel(this);
    m_note->setObjectName(QStringLiteral("bridgeNote"));
    m_note->setWordWrap(true);
    layout->addWidget(m_note);
    m_problem = new QLabel(this);
    m_problem->setObjectName(QStringLiteral("bridgeProblem"));
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("QLabel { color: #b00020; }"));
    layout->addWidget(m_problem);
    layout->addStretch();
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(m_buttons);
    connect(m_line, &LineSettingsForm::edited, this, &NetworkBridgeDialog::check);
    connect(m_line->hostEdit(), &QLineEdit::textChanged, this, &NetworkBridgeDialog::check);

    // The bridge as it is.
    const std::optional<network::HostPort> hostPort = network::splitHostPort(bridge.where);
    switch (bridge.kind) {
    case BridgeKind::Serial:
        m_line->setPort(bridge.where);
        break;
    case BridgeKind::Tcp:
    case BridgeKind::Listen:
        if (hostPort) {
            m_line->setHost(hostPort->host);
            m_line->setTcpPort(hostPort->port);
        }
        break;
    case BridgeKind::Pty:
        break;
    }
    setKind(bridge.kind);
    setMinimumWidth(480);
}

void NetworkBridgeDialog::setKind(BridgeKind kind) {
    m_kinds[int(kind)]->setChecked(true);
    kindChosen();
}

BridgeKind NetworkBridgeDialog::kind() const {
    for (int i = 0; i < 4; ++i)
        if (m_kinds[i]->isChecked())
            return BridgeKind(i);
    return BridgeKind::Pty;
}

void NetworkBridgeDialog::kindChosen() {
    const BridgeKind k = kind();
    m_line->setVisible(k != BridgeKind::Pty);
    m_line->showPage(k == BridgeKind::Serial ? LineSettingsForm::Page::Serial
                                             : LineSettingsForm::Page::Tcp);
    if (k == BridgeKind::Listen) {
        m_line->setHostLabel(tr("Listen on:"));
        m_line->setTcpPortRange(0, 65535);
        m_line->tcpPortBox()->setSpecialValueText(tr("any free port"));
        m_line->hostEdit()->setToolTip(
            tr("An IP address of this computer, 0.0.0.0 for all of them, or localhost"));
        if (m_bridge.kind != BridgeKind::Listen && m_line->host() == QLatin1String("127.0.0.1"))
            m_line->setHost(QStringLiteral("0.0.0.0"));
    } else {
        m_line->setHostLabel({});
        m_line->tcpPortBox()->setSpecialValueText({});
        m_line->setTcpPortRange(1, 65535);
        m_line->hostEdit()->setToolTip(tr("The serial device server's host name or IP address"));
    }
    switch (k) {
    case BridgeKind::Pty:
        m_note->setText(tr("A new pseudo-terminal (/dev/pts/N) opens when the network window "
                           "builds the network, and stays while the window is open (Stop keeps "
                           "it). Its path is shown on the port and in the Bridges dock, with a "
                           "Copy button: give it to the master (mbpoll, an HMI, another Rung "
                           "Studio's Connection dock)."));
        break;
    case BridgeKind::Serial:
        m_note->setText(tr("The serial port opens at the port's own rate and format, so that the "
                           "simulated station and the real line agree: changing them here "
                           "changes the port's settings."));
        break;
    case BridgeKind::Tcp:
        m_note->setText(tr("A serial device server in TCP server mode passes the bytes to its "
                           "serial line: the simulated station reaches the real device behind "
                           "it."));
        break;
    case BridgeKind::Listen:
        m_note->setText(tr("A master connects over TCP and sends the serial line's bytes (RTU "
                           "over TCP, not Modbus TCP), one master at a time."));
        break;
    }
    check();
}

network::BridgeDescription NetworkBridgeDialog::bridge() const {
    network::BridgeDescription b = m_bridge;
    b.kind = kind();
    switch (b.kind) {
    case BridgeKind::Pty:
        b.where.clear();
        break;
    case BridgeKind::Serial:
        b.where = m_line->port();
        break;
    case BridgeKind::Tcp:
    case BridgeKind::Listen:
        b.where = QStringLiteral("%1:%2").arg(m_line->host()).arg(m_line->tcpPort());
        break;
    }
    return b;
}

std::optional<QJsonObject> NetworkBridgeDialog::portSettings() const {
    if (kind() != BridgeKind::Serial)
        return std::nullopt;
    const model::SerialSettings line = m_line->line();
    const QString frame = model::frameFormatText(line);
    if (line.baud == m_baud && frame == m_frame)
        return std::nullopt;
    QJsonObject out = m_settings;
    out.insert(QStringLiteral("baud"), line.baud);
    if (!m_application.fixedFrame)
        out.insert(QStringLiteral("frame"), frame);
    return out;
}

QString NetworkBridgeDialog::problem() const {
    switch (kind()) {
    case BridgeKind::Pty:
        return {};
    case BridgeKind::Serial:
        return m_line->port().isEmpty() ? tr("Choose the serial port, or type its name")
                                        : QString();
    case BridgeKind::Tcp:
        return m_line->host().isEmpty() ? tr("Type the device server's host name or IP address")
                                        : QString();
    case BridgeKind::Listen:
        return m_line->host().isEmpty()
                   ? tr("Type the address to listen on (0.0.0.0 for all of them)")
                   : QString();
    }
    return {};
}

void NetworkBridgeDialog::check() {
    const QString why = problem();
    m_problem->setText(why);
    m_problem->setVisible(!why.isEmpty());
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(why.isEmpty());
}

} // namespace rung::app
