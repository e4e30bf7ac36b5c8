#pragma once

// TCP through QtNetwork: a client (Modbus TCP, or a serial device server carrying RTU frames
// over raw TCP) and a listening server whose accepted connections are transports too (the
// virtual PLC). QTcpSocket is used in its blocking form, so a transport and the server must
// stay on the worker thread that made them; cancel() is the one call from other threads (it
// takes effect within 20 ms: QTcpSocket has no wake-up of its own).

#include "comms/transport/transport.h"

#include <QHostAddress>

#include <atomic>
#include <memory>

class QTcpServer;
class QTcpSocket;

namespace rung::comms {

class TcpTransport final : public Transport {
public:
    TcpTransport(QString host, quint16 port);
    explicit TcpTransport(std::unique_ptr<QTcpSocket> connected); // from TcpServer::accept
    // A connection TcpServer::acceptDescriptor() took: open() makes its socket in the thread
    // that calls it, which is then the one thread that may use it (a slave's client thread).
    static std::unique_ptr<TcpTransport> fromDescriptor(qintptr descriptor);
    ~TcpTransport() override;

    QString name() const override;
    bool open(QString *error) override; // connects, within the open deadline
    void close() override;
    bool isOpen() const override;
    bool write(QByteArrayView bytes, QDeadlineTimer deadline, QString *error) override;
    ReadResult read(QDeadlineTimer deadline) override;
    void discardInput() override;
    void cancel() override { m_cancel = true; }

    void setOpenTimeout(int ms) { m_openTimeoutMs = ms; }

private:
    QString m_host;
    quint16 m_port = 0;
    std::unique_ptr<QTcpSocket> m_socket;
    qintptr m_descriptor = -1; // fromDescriptor(), until open()
    std::atomic<bool> m_cancel{false};
    int m_openTimeoutMs = 3000;
};

class TcpServer {
public:
    TcpServer();
    ~TcpServer();
    // Listens on host:port (port 0: any free port, see port()).
    bool listen(const QHostAddress &host, quint16 port, QString *error);
    quint16 port() const;
    // Waits for the next connection until the deadline or cancel(); nullptr then. The
    // transport is open and belongs to this thread.
    std::unique_ptr<TcpTransport> accept(QDeadlineTimer deadline);
    // The same, as the connection's descriptor (-1 at the deadline or on cancel()), for a
    // server that serves each client on a thread of its own (TcpTransport::fromDescriptor).
    qintptr acceptDescriptor(QDeadlineTimer deadline);
    void cancel() { m_cancel = true; }

private:
    class Listener;
    std::unique_ptr<Listener> m_server;
    std::atomic<bool> m_cancel{false};
};

} // namespace rung::comms
