#pragma once

// Pseudo-terminals through termios: libserialport cannot open them (its port lookup needs
// /sys/class/tty and sp_open needs TIOCMGET).
// Either end: open() a path ("/dev/pts/3", a socat link), or createPair() makes a new
// pseudo-terminal and holds its master side, for the virtual PLC (`serve --pty` prints
// peerPath()). A pseudo-terminal carries bytes only: baud, parity and stop bits do not apply.

#include "comms/transport/fd_waiter.h"
#include "comms/transport/transport.h"

#include <memory>

namespace rung::comms {

class PtyTransport final : public Transport {
public:
    explicit PtyTransport(QString path);
    ~PtyTransport() override;

    // A new pseudo-terminal; this transport is its master, open already. nullptr with a
    // message when the system has none to give (or no file descriptor for it). Once closed,
    // a pair cannot be opened again: open() says so (the path would name another terminal).
    static std::unique_ptr<PtyTransport> createPair(QString *error);
    // The path a peer opens (the slave side of a pair made by createPair()).
    QString peerPath() const { return m_peerPath; }

    QString name() const override { return m_path; }
    bool open(QString *error) override;
    void close() override;
    bool isOpen() const override { return m_fd >= 0; }
    bool write(QByteArrayView bytes, QDeadlineTimer deadline, QString *error) override;
    ReadResult read(QDeadlineTimer deadline) override;
    void discardInput() override;
    void cancel() override { m_waiter.wake(); }

private:
    QString m_path;
    QString m_peerPath;
    int m_fd = -1;
    int m_keepPeer = -1; // the master keeps the slave side open so a peer's close is no hang-up
    bool m_pair = false; // made by createPair(): m_fd is the master side
    detail::FdWaiter m_waiter;
};

} // namespace rung::comms
