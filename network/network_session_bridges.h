#pragma once

// Bridges of a network simulated in the IDE (docs/network.md, "Bridges in the IDE"): the
// network file's bridges (a pseudo-terminal, a serial port, a TCP connection or a listening
// socket) put on real lines while NetworkSession runs the network, as `rungstudio-cli serve`
// does. The lines are opened, read, written and closed on the session's worker thread, never
// on the owner (UI) thread: a serial port or a TCP connection may take seconds to open.
//
// The lines are kept in a pool (BridgeLines) that outlives a network and a session: Stop
// builds the network again and an edit builds a new session, and a master already on the
// pseudo-terminal keeps its path. A line no bridge uses any more is closed at the next attach.

#include "network/network_file.h"

#include "model/comm/serial_line.h"

#include <QString>

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

namespace rung::comms {
class Transport;
}

namespace rung::network {

class BridgeEndpoint;
class Network;

// A bridge as the owner thread sees it.
struct BridgeStatus {
    BridgeDescription bridge;
    QString reached; // where a peer reaches it ("/dev/pts/5", "0.0.0.0:5020"); "" until open
    QString error;   // what, where and why it could not open or failed; "" while it works
    bool open = false;
    friend bool operator==(const BridgeStatus &, const BridgeStatus &) = default;
};

// The open lines of one network window's bridges. Thread-safe; its lines are opened and
// closed by a session's worker (and closed by its destructor).
class BridgeLines {
public:
    BridgeLines();
    ~BridgeLines();
    BridgeLines(const BridgeLines &) = delete;
    BridgeLines &operator=(const BridgeLines &) = delete;

    // The line of `bridge` at `line`'s rate and format: the one kept for the same bridge, or
    // one opened now; null with what and why. *reached: where a peer reaches it.
    std::shared_ptr<comms::Transport> take(const BridgeDescription &bridge,
                                           const model::SerialSettings &line, QString *reached,
                                           QString *error);
    // Closes the lines that are not among `used` (their keys, lineKey).
    void keepOnly(const std::vector<QString> &used);
    // Forgets a line that failed, so that the next take opens it again.
    void drop(const QString &key);
    // Any thread: a line being opened now gives up (a TCP connection that takes long), so
    // that a session ending does not wait for it.
    void cancelOpening();
    // Lines open now (tests).
    std::size_t size() const;

    static QString lineKey(const BridgeDescription &bridge, const model::SerialSettings &line);

private:
    struct Line {
        QString key;
        std::shared_ptr<comms::Transport> transport;
        QString reached;
    };
    mutable std::mutex m_mutex;
    std::vector<Line> m_lines;
    comms::Transport *m_opening = nullptr; // under m_mutex: the line being opened
};

// The worker's side: a network's bridges joined to their lines, and what the lines brought
// put on the wires. Worker thread only.
class SessionBridges {
public:
    SessionBridges(std::shared_ptr<BridgeLines> lines, std::vector<BridgeDescription> bridges);
    ~SessionBridges();

    // Takes (or opens) every bridge's line and joins it to `network` (a network built again
    // after Stop gets the same lines); the statuses after it.
    const std::vector<BridgeStatus> &attach(Network &network);
    // What the lines brought goes on the wires now, as the bridged station's peer sent it;
    // true when a status changed (a line failed). `rebuilding` is asked after the lines are
    // read: while it says a new network is coming (Stop), what they brought waits for it, so
    // that a master's request sent after Stop and Run is answered by the new network rather
    // than lost with the old one.
    bool poll(Network &network, const std::function<bool()> &rebuilding = {});
    const std::vector<BridgeStatus> &statuses() const { return m_status; }
    // Bytes read and waiting for the network that comes after a Stop (tests).
    std::size_t heldBytes() const;

private:
    struct Live {
        std::size_t index; // into m_status
        BridgeEndpoint *endpoint = nullptr;
        std::shared_ptr<comms::Transport> line;
        QString key;
    };
    std::shared_ptr<BridgeLines> m_lines;
    std::vector<BridgeStatus> m_status;
    std::vector<Live> m_live;
    std::map<QString, QByteArray> m_held; // by line key: read while a new network was coming
};

} // namespace rung::network
