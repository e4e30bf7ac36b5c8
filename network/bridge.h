#pragma once

// Bridges (docs/network.md, "Bridges"): a station's port put on a real line, a
// pseudo-terminal, a serial port or a TCP connection to a serial device server, so that a
// real HMI polls a simulated slave or a simulated master polls a real device. The network
// then runs at real-time speed: RealTime runs it up to the time elapsed, carries what each
// bridged wire delivers to the real line and puts what the real line brings on the wire as
// if a station on it had sent it. One thread: the caller's.

#include "network/network.h"

#include "comms/transport/transport.h"

#include <QElapsedTimer>

#include <memory>
#include <vector>

namespace rung::network {

class BridgeEndpoint;

class RealTime {
public:
    explicit RealTime(Network &network);
    ~RealTime();
    RealTime(const RealTime &) = delete;
    RealTime &operator=(const RealTime &) = delete;

    // Opens the bridge's line and joins it to the port's wire (a wire of its own when the
    // port is on none). *where says how a peer reaches it: the pseudo-terminal's path, the
    // serial port's or HOST:PORT. False with what, where and why: a port that is not there, a
    // CPU Link or Parallel Link port (their frames are not published), a line that fails.
    bool addBridge(const BridgeDescription &bridge, QString *where, QString *error);
    // As addBridge, with a transport already open (tests: one end of a pseudo-terminal pair).
    bool addBridge(const QString &port, std::unique_ptr<comms::Transport> transport,
                   QString *error);

    // One turn: the network up to the real time elapsed since the first turn, then what the
    // bridges' lines brought, waiting at most waitMs for it. False with *failure when a line
    // failed (an unplugged adapter, a closed connection).
    bool turn(int waitMs, QString *failure);

private:
    Network &m_network;
    QElapsedTimer m_clock;
    qint64 m_startUs = 0;
    std::vector<BridgeEndpoint *> m_bridges; // owned by the network
};

} // namespace rung::network
