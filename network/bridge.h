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

#include <functional>
#include <memory>
#include <vector>

namespace rung::network {

// The name of the real line's end beside a port ("bridge:s5/CP2"); a port on no wire gets a
// wire of the same name when the bridge opens (Network::attach).
QString bridgeEndName(const QString &port);

// The real line's end on a wire: what the wire delivers is written to the line. The line is
// shared: the IDE keeps a bridge's pseudo-terminal open across the networks a Stop builds
// again (network_session_bridges.cpp), so that a master on it need not be told a new path.
class BridgeEndpoint final : public Endpoint {
public:
    BridgeEndpoint(const QString &portName, const model::SerialSettings &line,
                   std::shared_ptr<comms::Transport> transport);
    const model::SerialSettings &lineSettings() const override { return m_line; }
    void deliver(const QByteArray &bytes, int errors, qint64 atUs) override;
    comms::Transport &transport() { return *m_transport; }
    // Why the last write to the line failed; empty while it works.
    const QString &failure() const { return m_failure; }

private:
    model::SerialSettings m_line;
    std::shared_ptr<comms::Transport> m_transport;
    QString m_failure;
};

// The line a bridge of `port` ("s5/CP2") carries: the port's rate and format. False with what
// and why when it cannot be bridged: no such station port, or a CPU Link or Parallel Link
// port (their frames are not published). `where` names the bridge ("bridges[0]"), may be "".
bool bridgeablePort(Network &network, const QString &port, const QString &where,
                    model::SerialSettings *line, QString *error);
// Opens a bridge's real line: a new pseudo-terminal, the serial port at `line`'s rate and
// format, a TCP connection to a device server, or a socket listening for a master. *reached
// says how a peer reaches it (the pseudo-terminal's path, the serial port's name, HOST:PORT).
// Null with what, where and why. Blocks while it connects: not for the UI thread.
// `opening`, when given, is told of the line before it opens and of null once the opening is
// over (to cancel() a connection that takes long from another thread meanwhile).
std::unique_ptr<comms::Transport>
openBridgeLine(const BridgeDescription &bridge, const model::SerialSettings &line, QString *reached,
               QString *error, const std::function<void(comms::Transport *)> &opening = {});
// Joins an open line to the port's wire (a wire of its own when the port is on none); the
// network owns the endpoint, which it returns (null with why when the port cannot be bridged).
BridgeEndpoint *attachBridgeLine(Network &network, const QString &port,
                                 std::shared_ptr<comms::Transport> transport, QString *error);

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
