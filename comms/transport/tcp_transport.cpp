#include "comms/transport/tcp_transport.h"

#include <QTcpServer>
#include <QTcpSocket>

#include <deque>
#include <unistd.h>

namespace rung::comms {

namespace {

constexpr int SliceMs = 20; // how often a blocking wait looks at cancel()

int slice(const QDeadlineTimer &deadline) {
    const qint64 left = deadline.remainingTime();
    return left < 0 ? SliceMs : int(std::min<qint64>(left, SliceMs));
}

} // namespace

// Keeps the descriptors of incoming connections instead of making sockets of them, so that a
// socket is made in the thread that will use it (QTcpSocket is not to be shared by threads).
class TcpServer::Listener : public QTcpServer {
public:
    std::deque<qintptr> pending;

protected:
    void incomingConnection(qintptr descriptor) override { pending.push_back(descriptor); }
};

TcpTransport::TcpTransport(QString host, quint16 port)
    : m_host(std::move(host))
    , m_port(port) {}

TcpTransport::TcpTransport(std::unique_ptr<QTcpSocket> connected)
    : m_host(connected->peerAddress().toString())
    , m_port(connected->peerPort())
    , m_socket(std::move(connected)) {}

std::unique_ptr<TcpTransport> TcpTransport::fromDescriptor(qintptr descriptor) {
    auto t = std::make_unique<TcpTransport>(QString(), quint16(0));
    t->m_descriptor = descriptor;
    return t;
}

TcpTransport::~TcpTransport() {
    close();
    if (m_descriptor >= 0)
        ::close(int(m_descriptor)); // never opened: the connection is still ours to end
}

QString TcpTransport::name() const {
    return QStringLiteral("%1:%2").arg(m_host).arg(m_port);
}

bool TcpTransport::isOpen() const {
    return m_socket && m_socket->state() == QAbstractSocket::ConnectedState;
}

bool TcpTransport::open(QString *error) {
    if (isOpen())
        return true;
    if (m_descriptor >= 0) {
        m_socket = std::make_unique<QTcpSocket>();
        const qintptr descriptor = std::exchange(m_descriptor, -1);
        if (!m_socket->setSocketDescriptor(descriptor)) {
            if (error)
                *error = QCoreApplication::translate("rung::comms::Protocol",
                                                     "Cannot take the TCP connection: %1")
                             .arg(m_socket->errorString());
            ::close(int(descriptor));
            m_socket.reset();
            return false;
        }
        m_host = m_socket->peerAddress().toString();
        m_port = m_socket->peerPort();
        m_socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        return true;
    }
    m_socket = std::make_unique<QTcpSocket>();
    m_socket->connectToHost(m_host, m_port);
    const QDeadlineTimer deadline(m_openTimeoutMs);
    while (m_socket->state() != QAbstractSocket::ConnectedState) {
        if (m_socket->waitForConnected(slice(deadline)))
            break;
        const bool failed = m_socket->state() == QAbstractSocket::UnconnectedState;
        if (failed || deadline.hasExpired() || m_cancel.exchange(false)) {
            if (error)
                *error = failed ? QCoreApplication::translate("rung::comms::Protocol",
                                                              "Cannot connect to %1: %2")
                                      .arg(name(), m_socket->errorString())
                                : QCoreApplication::translate("rung::comms::Protocol",
                                                              "Cannot connect to %1 within %2 ms")
                                      .arg(name())
                                      .arg(m_openTimeoutMs);
            m_socket.reset();
            return false;
        }
    }
    m_socket->setSocketOption(QAbstractSocket::LowDelayOption, 1); // small frames, no Nagle
    return true;
}

void TcpTransport::close() {
    if (m_socket) {
        m_socket->abort();
        m_socket.reset();
    }
}

bool TcpTransport::write(QByteArrayView bytes, QDeadlineTimer deadline, QString *error) {
    if (!isOpen()) {
        if (error)
            *error =
                QCoreApplication::translate("rung::comms::Protocol", "%1 is not open").arg(name());
        return false;
    }
    if (m_socket->write(bytes.data(), bytes.size()) != bytes.size()) {
        if (error)
            *error =
                QCoreApplication::translate("rung::comms::Protocol", "Writing to %1 failed: %2")
                    .arg(name(), m_socket->errorString());
        return false;
    }
    while (m_socket->bytesToWrite() > 0) {
        if (!m_socket->waitForBytesWritten(slice(deadline)) &&
            (deadline.hasExpired() || !isOpen())) {
            if (error)
                *error = QCoreApplication::translate("rung::comms::Protocol",
                                                     "Writing to %1 did not finish in time")
                             .arg(name());
            return false;
        }
    }
    return true;
}

ReadResult TcpTransport::read(QDeadlineTimer deadline) {
    using R = ReadResult::Status;
    while (true) {
        if (!m_socket)
            return {
                R::Failed,
                {},
                QCoreApplication::translate("rung::comms::Protocol", "%1 is not open").arg(name())};
        if (m_socket->bytesAvailable() > 0)
            return {R::Data, m_socket->readAll(), {}};
        if (m_socket->state() != QAbstractSocket::ConnectedState)
            return {R::Failed,
                    {},
                    QCoreApplication::translate("rung::comms::Protocol",
                                                "%1 was closed by the other side")
                        .arg(name())};
        if (m_cancel.exchange(false))
            return {R::Cancelled, {}, {}};
        if (deadline.hasExpired())
            return {R::Timeout, {}, {}};
        m_socket->waitForReadyRead(slice(deadline));
    }
}

void TcpTransport::discardInput() {
    if (m_socket)
        m_socket->readAll();
}

TcpServer::TcpServer() = default;
TcpServer::~TcpServer() {
    if (m_server)
        for (const qintptr descriptor : m_server->pending)
            ::close(int(descriptor)); // accepted by the system, never taken: ended here
}

bool TcpServer::listen(const QHostAddress &host, quint16 port, QString *error) {
    m_server = std::make_unique<Listener>();
    if (m_server->listen(host, port))
        return true;
    if (error)
        *error = QCoreApplication::translate("rung::comms::Protocol", "Cannot listen on %1:%2: %3")
                     .arg(host.toString())
                     .arg(port)
                     .arg(m_server->errorString());
    m_server.reset();
    return false;
}

quint16 TcpServer::port() const {
    return m_server ? m_server->serverPort() : 0;
}

std::unique_ptr<TcpTransport> TcpServer::accept(QDeadlineTimer deadline) {
    const qintptr descriptor = acceptDescriptor(deadline);
    if (descriptor < 0)
        return nullptr;
    auto transport = TcpTransport::fromDescriptor(descriptor);
    if (!transport->open(nullptr))
        return nullptr;
    return transport;
}

qintptr TcpServer::acceptDescriptor(QDeadlineTimer deadline) {
    if (!m_server)
        return -1;
    while (m_server->pending.empty()) {
        if (m_cancel.exchange(false) || deadline.hasExpired())
            return -1;
        m_server->waitForNewConnection(slice(deadline));
    }
    const qintptr descriptor = m_server->pending.front();
    m_server->pending.pop_front();
    return descriptor;
}

} // namespace rung::comms
