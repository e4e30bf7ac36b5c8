#include "comms/transport/tcp_listen_transport.h"

#include <QCoreApplication>

namespace rung::comms {

TcpListenTransport::TcpListenTransport(QHostAddress host, quint16 port)
    : m_host(std::move(host))
    , m_port(port) {}

TcpListenTransport::~TcpListenTransport() = default;

QString TcpListenTransport::name() const {
    return QStringLiteral("%1:%2").arg(m_host.toString()).arg(m_server ? m_server->port() : m_port);
}

bool TcpListenTransport::open(QString *error) {
    if (m_server)
        return true;
    auto server = std::make_unique<TcpServer>();
    if (!server->listen(m_host, m_port, error))
        return false;
    m_server = std::move(server);
    return true;
}

void TcpListenTransport::setClient(std::unique_ptr<TcpTransport> client) {
    std::unique_ptr<TcpTransport> gone;
    const std::lock_guard lock(m_clientMutex);
    gone = std::exchange(m_client, std::move(client));
}

void TcpListenTransport::close() {
    setClient(nullptr);
    m_server.reset();
}

bool TcpListenTransport::isOpen() const {
    return m_server != nullptr;
}

bool TcpListenTransport::write(QByteArrayView bytes, QDeadlineTimer deadline, QString *error) {
    if (!m_server) {
        if (error)
            *error =
                QCoreApplication::translate("rung::comms::Protocol", "%1 is not open").arg(name());
        return false;
    }
    if (!m_client)
        return true; // nobody on the line: the bytes go nowhere, as on an open line
    QString lost;
    if (!m_client->write(bytes, deadline, &lost))
        setClient(nullptr); // the client went; the line stays for the next one
    return true;
}

ReadResult TcpListenTransport::read(QDeadlineTimer deadline) {
    using R = ReadResult::Status;
    if (!m_server)
        return {R::Failed,
                {},
                QCoreApplication::translate("rung::comms::Protocol", "%1 is not open").arg(name())};
    if (!m_client) {
        std::unique_ptr<TcpTransport> client = m_server->accept(deadline);
        if (!client) // the deadline, or cancel() before it
            return {deadline.hasExpired() ? R::Timeout : R::Cancelled, {}, {}};
        setClient(std::move(client));
    }
    ReadResult r = m_client->read(deadline);
    if (r.status == R::Failed) {
        setClient(nullptr); // closed by the client: listen for the next one
        return {R::Timeout, {}, {}};
    }
    return r;
}

void TcpListenTransport::discardInput() {
    if (m_client)
        m_client->discardInput();
}

void TcpListenTransport::cancel() {
    if (m_server)
        m_server->cancel();
    const std::lock_guard lock(m_clientMutex);
    if (m_client)
        m_client->cancel();
}

} // namespace rung::comms
