#include "network/bridge.h"

#include "network/station.h"
#include "network/tr.h"

#include "comms/transport/pty_transport.h"
#include "comms/transport/serial_transport.h"
#include "comms/transport/tcp_listen_transport.h"
#include "comms/transport/tcp_transport.h"

#include <QDeadlineTimer>
#include <QThread>

#include <algorithm>

namespace rung::network {

QString bridgeEndName(const QString &port) {
    return QStringLiteral("bridge:") + port;
}

BridgeEndpoint::BridgeEndpoint(const QString &portName, const model::SerialSettings &line,
                               std::shared_ptr<comms::Transport> transport)
    : m_line(line)
    , m_transport(std::move(transport)) {
    name = bridgeEndName(portName);
    owner = name;
}

void BridgeEndpoint::deliver(const QByteArray &bytes, int, qint64) {
    if (bytes.isEmpty() || !m_failure.isEmpty())
        return;
    QString error;
    if (!m_transport->write(bytes, QDeadlineTimer(1000), &error))
        m_failure = error;
}

bool bridgeablePort(Network &network, const QString &portName, const QString &where,
                    model::SerialSettings *line, QString *error) {
    const auto *port = dynamic_cast<StationPort *>(network.endpoint(portName));
    if (!port) {
        *error = where.isEmpty() ? NetworkTr::tr("no station port \"%1\"").arg(portName)
                                 : NetworkTr::tr("%1: no station port \"%2\"").arg(where, portName);
        return false;
    }
    if (!port->config().application->published) {
        *error = NetworkTr::tr("%1 runs %2, whose frames the manual does not publish: it is not "
                               "put on a real line")
                     .arg(port->name, QCoreApplication::translate(
                                          "rung::model::Target", port->config().application->name));
        return false;
    }
    *line = port->line();
    return true;
}

std::unique_ptr<comms::Transport>
openBridgeLine(const BridgeDescription &b, const model::SerialSettings &line, QString *where,
               QString *error, const std::function<void(comms::Transport *)> &opening) {
    std::unique_ptr<comms::Transport> transport;
    switch (b.kind) {
    case BridgeDescription::Kind::Pty: {
        auto pty = comms::PtyTransport::createPair(error);
        if (!pty)
            return nullptr;
        *where = pty->peerPath();
        transport = std::move(pty);
        break;
    }
    case BridgeDescription::Kind::Serial:
        transport = std::make_unique<comms::SerialTransport>(b.where, line);
        *where = b.where;
        break;
    case BridgeDescription::Kind::Tcp: {
        const std::optional<HostPort> hostPort = splitHostPort(b.where);
        if (!hostPort || hostPort->port == 0) {
            *error = NetworkTr::tr("%1.tcp: \"%2\" is not HOST:PORT").arg(b.path, b.where);
            return nullptr;
        }
        transport = std::make_unique<comms::TcpTransport>(hostPort->host, quint16(hostPort->port));
        *where = b.where;
        break;
    }
    case BridgeDescription::Kind::Listen: {
        // Port 0 takes any free port; *where then says which.
        const std::optional<HostPort> hostPort = splitHostPort(b.where);
        const QString hostName = hostPort ? hostPort->host : QString();
        const QHostAddress host = hostName == QLatin1String("localhost")
                                      ? QHostAddress(QHostAddress::LocalHost)
                                      : QHostAddress(hostName);
        if (!hostPort || host.isNull()) {
            *error = NetworkTr::tr("%1.listen: \"%2\" is not ADDRESS:PORT (an IP address of "
                                   "this machine, 0.0.0.0 for all, or localhost)")
                         .arg(b.path, b.where);
            return nullptr;
        }
        transport = std::make_unique<comms::TcpListenTransport>(host, quint16(hostPort->port));
        break;
    }
    }
    if (opening)
        opening(transport.get());
    const bool open = transport->isOpen() || transport->open(error);
    if (opening)
        opening(nullptr); // before the line may go: nobody may cancel it any more
    if (!open)
        return nullptr;
    if (b.kind == BridgeDescription::Kind::Listen)
        *where = transport->name();
    return transport;
}

BridgeEndpoint *attachBridgeLine(Network &network, const QString &portName,
                                 std::shared_ptr<comms::Transport> transport, QString *error) {
    model::SerialSettings line;
    if (!bridgeablePort(network, portName, {}, &line, error))
        return nullptr;
    auto *port = network.endpoint(portName);
    auto bridge = std::make_unique<BridgeEndpoint>(port->name, line, std::move(transport));
    BridgeEndpoint *endpoint = bridge.get();
    network.attach(std::move(bridge), port);
    return endpoint;
}

RealTime::RealTime(Network &network)
    : m_network(network) {}

RealTime::~RealTime() = default;

bool RealTime::addBridge(const BridgeDescription &b, QString *where, QString *error) {
    model::SerialSettings line;
    if (!bridgeablePort(m_network, b.end, b.path, &line, error))
        return false;
    std::unique_ptr<comms::Transport> transport = openBridgeLine(b, line, where, error);
    return transport && addBridge(b.end, std::move(transport), error);
}

bool RealTime::addBridge(const QString &portName, std::unique_ptr<comms::Transport> transport,
                         QString *error) {
    BridgeEndpoint *bridge = attachBridgeLine(m_network, portName, std::move(transport), error);
    if (bridge)
        m_bridges.push_back(bridge);
    return bridge != nullptr;
}

bool RealTime::turn(int waitMs, QString *failure) {
    if (!m_clock.isValid()) {
        m_clock.start();
        m_startUs = m_network.nowUs();
    }
    m_network.runUntil(m_startUs + m_clock.nsecsElapsed() / 1000);
    const int each = m_bridges.empty() ? waitMs : std::max(1, waitMs / int(m_bridges.size()));
    for (BridgeEndpoint *b : m_bridges) {
        if (!b->failure().isEmpty()) {
            *failure = b->failure();
            return false;
        }
        const comms::ReadResult r = b->transport().read(QDeadlineTimer(each));
        if (r.status == comms::ReadResult::Status::Failed) {
            *failure = r.message;
            return false;
        }
        if (r.status == comms::ReadResult::Status::Data) {
            // The real line's bytes go on the wire now, as a station would send them.
            m_network.runUntil(m_startUs + m_clock.nsecsElapsed() / 1000);
            m_network.transmit(b, r.bytes);
        }
    }
    if (m_bridges.empty())
        QThread::msleep(std::max(0, waitMs));
    return true;
}

} // namespace rung::network
