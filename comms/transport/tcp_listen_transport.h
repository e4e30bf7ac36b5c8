#pragma once

// The listening side of a serial device server: a port on this machine that a master (an HMI,
// a SCADA, pymodbus with an RTU framer) connects to, carrying the serial line's bytes over raw
// TCP (what ser2net and the Moxa NPort's "TCP server" mode do). One client at a time: when it
// leaves, the next one that connects takes the line. With no client connected, what is written
// is dropped, as on a line nobody listens to. Blocking, on the thread that opened it; cancel()
// from any thread (tcp_transport.h).

#include "comms/transport/tcp_transport.h"

#include <mutex>

namespace rung::comms {

class TcpListenTransport final : public Transport {
public:
    TcpListenTransport(QHostAddress host, quint16 port); // port 0: any free port
    ~TcpListenTransport() override;

    QString name() const override;      // HOST:PORT, the port chosen once open
    bool open(QString *error) override; // listens
    void close() override;
    bool isOpen() const override;
    bool write(QByteArrayView bytes, QDeadlineTimer deadline, QString *error) override;
    // Takes a waiting connection when no client is there, then reads from the client; a client
    // that left is not a failure of the line: Timeout, and the next connection is taken.
    ReadResult read(QDeadlineTimer deadline) override;
    void discardInput() override;
    void cancel() override;

    bool hasClient() const { return m_client != nullptr; }

private:
    QHostAddress m_host;
    quint16 m_port = 0;
    std::unique_ptr<TcpServer> m_server;
    // Replaced on the owner's thread only, under the mutex, so that cancel() from another
    // thread never meets a client being destroyed.
    std::unique_ptr<TcpTransport> m_client;
    std::mutex m_clientMutex;
    void setClient(std::unique_ptr<TcpTransport> client);
};

} // namespace rung::comms
