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

// The real line's end on a wire: what the wire delivers is written to the line.
class BridgeEndpoint final : public Endpoint {
public:
    BridgeEndpoint(const QString &portName, const model::SerialSettings &line,
                   std::unique_ptr<comms::Transport> transport)
        : m_line(line)
        , m_transport(std::move(transport)) {
        name = QStringLiteral("bridge:") + portName;
        owner = name;
    }
    const model::SerialSettings &lineSettings() const override { return m_line; }
    void deliver(const QByteArray &bytes, int, qint64) override {
        if (bytes.isEmpty() || !m_failure.isEmpty())
            return;
        QString error;
        if (!m_transport->write(bytes, QDeadlineTimer(1000), &error))
            m_failure = error;
    }
    comms::Transport &transport() { return *m_transport; }
    QString m_failure;

private:
    model::SerialSettings m_line;
    std::unique_ptr<comms::Transport> m_transport;
};

RealTime::RealTime(Network &network)
    : m_network(network) {}

RealTime::~RealTime() = default;

bool RealTime::addBridge(const BridgeDescription &b, QString *where, QString *error) {
    const StationPort *port = dynamic_cast<StationPort *>(m_network.endpoint(b.end));
    if (!port) {
        *error = NetworkTr::tr("%1: no station port \"%2\"").arg(b.path, b.end);
        return false;
    }
    std::unique_ptr<comms::Transport> transport;
    switch (b.kind) {
    case BridgeDescription::Kind::Pty: {
        auto pty = comms::PtyTransport::createPair(error);
        if (!pty)
            return false;
        *where = pty->peerPath();
        transport = std::move(pty);
        break;
    }
    case BridgeDescription::Kind::Serial:
        transport = std::make_unique<comms::SerialTransport>(b.where, port->line());
        *where = b.where;
        break;
    case BridgeDescription::Kind::Tcp: {
        const qsizetype colon = b.where.lastIndexOf(QLatin1Char(':'));
        bool ok = false;
        const uint tcpPort = colon > 0 ? b.where.mid(colon + 1).toUInt(&ok) : 0;
        if (!ok || tcpPort == 0 || tcpPort > 65535) {
            *error = NetworkTr::tr("%1.tcp: \"%2\" is not HOST:PORT").arg(b.path, b.where);
            return false;
        }
        transport = std::make_unique<comms::TcpTransport>(b.where.left(colon), quint16(tcpPort));
        *where = b.where;
        break;
    }
    case BridgeDescription::Kind::Listen: {
        // Port 0 takes any free port; *where then says which.
        const qsizetype colon = b.where.lastIndexOf(QLatin1Char(':'));
        bool ok = false;
        const uint tcpPort = colon > 0 ? b.where.mid(colon + 1).toUInt(&ok) : 0;
        const QString hostName = b.where.left(std::max<qsizetype>(colon, 0));
        const QHostAddress host = hostName == QLatin1String("localhost")
                                      ? QHostAddress(QHostAddress::LocalHost)
                                      : QHostAddress(hostName);
        if (!ok || tcpPort > 65535 || host.isNull()) {
            *error = NetworkTr::tr("%1.listen: \"%2\" is not ADDRESS:PORT (an IP address of "
                                   "this machine, 0.0.0.0 for all, or localhost)")
                         .arg(b.path, b.where);
            return false;
        }
        transport = std::make_unique<comms::TcpListenTransport>(host, quint16(tcpPort));
        break;
    }
    }
    if (!transport->isOpen() && !transport->open(error))
        return false;
    if (b.kind == BridgeDescription::Kind::Listen)
        *where = transport->name();
    return addBridge(b.end, std::move(transport), error);
}

bool RealTime::addBridge(const QString &portName, std::unique_ptr<comms::Transport> transport,
                         QString *error) {
    auto *port = dynamic_cast<StationPort *>(m_network.endpoint(portName));
    if (!port) {
        *error = NetworkTr::tr("no station port \"%1\"").arg(portName);
        return false;
    }
    if (!port->config().application->published) {
        *error = NetworkTr::tr("%1 runs %2, whose frames the manual does not publish: it is not "
                               "put on a real line")
                     .arg(port->name, QCoreApplication::translate(
                                          "rung::model::Target", port->config().application->name));
        return false;
    }
    auto bridge = std::make_unique<BridgeEndpoint>(port->name, port->line(), std::move(transport));
    m_bridges.push_back(bridge.get());
    m_network.attach(std::move(bridge), port);
    return true;
}

bool RealTime::turn(int waitMs, QString *failure) {
    if (!m_clock.isValid()) {
        m_clock.start();
        m_startUs = m_network.nowUs();
    }
    m_network.runUntil(m_startUs + m_clock.nsecsElapsed() / 1000);
    const int each = m_bridges.empty() ? waitMs : std::max(1, waitMs / int(m_bridges.size()));
    for (BridgeEndpoint *b : m_bridges) {
        if (!b->m_failure.isEmpty()) {
            *failure = b->m_failure;
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
