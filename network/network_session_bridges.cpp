#include "network/network_session_bridges.h"

#include "network/bridge.h"
#include "network/network.h"
#include "network/tr.h"

#include "comms/transport/transport.h"

#include <QDeadlineTimer>

#include <algorithm>
#include <utility>

namespace rung::network {

// ---- BridgeLines --------------------------------------------------------------------------

BridgeLines::BridgeLines() = default;
BridgeLines::~BridgeLines() = default;

QString BridgeLines::lineKey(const BridgeDescription &b, const model::SerialSettings &line) {
    // A serial port opened at another rate is another line; a pseudo-terminal or a socket
    // carries bytes only.
    const QString rate =
        b.kind == BridgeDescription::Kind::Serial
            ? QStringLiteral(" %1 %2").arg(line.baud).arg(model::frameFormatText(line))
            : QString();
    return QStringLiteral("%1 %2 %3%4").arg(b.end).arg(int(b.kind)).arg(b.where, rate);
}

std::shared_ptr<comms::Transport> BridgeLines::take(const BridgeDescription &bridge,
                                                    const model::SerialSettings &line,
                                                    QString *reached, QString *error) {
    const QString key = lineKey(bridge, line);
    {
        std::lock_guard lock(m_mutex);
        for (const Line &l : m_lines)
            if (l.key == key) {
                *reached = l.reached;
                return l.transport;
            }
    }
    // Opened outside the lock: a TCP connection may take seconds (cancelOpening ends it).
    std::shared_ptr<comms::Transport> transport =
        openBridgeLine(bridge, line, reached, error, [this](comms::Transport *t) {
            std::lock_guard lock(m_mutex);
            m_opening = t;
        });
    std::lock_guard lock(m_mutex);
    m_opening = nullptr;
    if (!transport)
        return nullptr;
    m_lines.push_back({key, transport, *reached});
    return transport;
}

void BridgeLines::keepOnly(const std::vector<QString> &used) {
    std::vector<Line> closing; // closed outside the lock
    {
        std::lock_guard lock(m_mutex);
        auto unused = std::stable_partition(m_lines.begin(), m_lines.end(), [&](const Line &l) {
            return std::find(used.begin(), used.end(), l.key) != used.end();
        });
        std::move(unused, m_lines.end(), std::back_inserter(closing));
        m_lines.erase(unused, m_lines.end());
    }
}

void BridgeLines::drop(const QString &key) {
    std::vector<Line> closing;
    {
        std::lock_guard lock(m_mutex);
        auto gone = std::stable_partition(m_lines.begin(), m_lines.end(),
                                          [&](const Line &l) { return l.key != key; });
        std::move(gone, m_lines.end(), std::back_inserter(closing));
        m_lines.erase(gone, m_lines.end());
    }
}

void BridgeLines::cancelOpening() {
    std::lock_guard lock(m_mutex);
    if (m_opening)
        m_opening->cancel();
}

std::size_t BridgeLines::size() const {
    std::lock_guard lock(m_mutex);
    return m_lines.size();
}

// ---- SessionBridges -----------------------------------------------------------------------

SessionBridges::SessionBridges(std::shared_ptr<BridgeLines> lines,
                               std::vector<BridgeDescription> bridges)
    : m_lines(std::move(lines)) {
    for (BridgeDescription &b : bridges)
        m_status.push_back({std::move(b), {}, {}, false});
}

SessionBridges::~SessionBridges() = default;

const std::vector<BridgeStatus> &SessionBridges::attach(Network &network) {
    m_live.clear();
    std::vector<QString> used;
    for (std::size_t i = 0; i < m_status.size(); ++i) {
        BridgeStatus &s = m_status[i];
        s.open = false;
        s.error.clear();
        model::SerialSettings line;
        QString why;
        std::shared_ptr<comms::Transport> transport;
        BridgeEndpoint *endpoint = nullptr;
        if (bridgeablePort(network, s.bridge.end, {}, &line, &why))
            transport = m_lines->take(s.bridge, line, &s.reached, &why);
        if (transport)
            endpoint = attachBridgeLine(network, s.bridge.end, transport, &why);
        if (!endpoint) {
            //: %1 the bridged port ("s5/CP2"), %2 why its line did not open
            s.error =
                NetworkSessionTr::tr("%1: the bridge did not open: %2").arg(s.bridge.end, why);
            continue;
        }
        const QString key = BridgeLines::lineKey(s.bridge, line);
        used.push_back(key);
        s.open = true;
        m_live.push_back({i, endpoint, std::move(transport), key});
    }
    m_lines->keepOnly(used);
    std::erase_if(m_held, [&](const auto &held) {
        return std::find(used.begin(), used.end(), held.first) == used.end();
    });
    return m_status;
}

bool SessionBridges::poll(Network &network, const std::function<bool()> &rebuilding) {
    bool changed = false;
    std::vector<QByteArray> got(m_live.size());
    for (std::size_t i = 0; i < m_live.size(); ++i) {
        Live &live = m_live[i];
        BridgeStatus &s = m_status[live.index];
        QString failure = live.endpoint->failure();
        if (failure.isEmpty()) {
            // Whatever is there now. A pseudo-terminal or a serial port is polled without a
            // wait; a TCP socket of a thread without an event loop takes in what came (and a
            // listening one a master) only while it waits, so it gets a millisecond.
            const BridgeDescription::Kind kind = s.bridge.kind;
            const int waitMs =
                kind == BridgeDescription::Kind::Tcp || kind == BridgeDescription::Kind::Listen ? 1
                                                                                                : 0;
            for (int reads = 0; reads < 16; ++reads) {
                const comms::ReadResult r =
                    live.line->read(QDeadlineTimer(reads == 0 ? waitMs : 0));
                if (r.status == comms::ReadResult::Status::Data)
                    got[i] += r.bytes;
                else if (r.status == comms::ReadResult::Status::Failed)
                    failure = r.message;
                if (r.status != comms::ReadResult::Status::Data)
                    break;
            }
        }
        if (failure.isEmpty())
            continue;
        //: %1 the bridged port ("s5/CP2"), %2 what happened to its line
        s.error = NetworkSessionTr::tr("%1: the bridge's line failed: %2 (Stop opens it again)")
                      .arg(s.bridge.end, failure);
        s.open = false;
        m_lines->drop(live.key);
        m_held.erase(live.key);
        live.endpoint = nullptr; // gone below, with what it brought
        changed = true;
    }
    // Asked after the reads: bytes read once a Stop was asked for belong to the new network.
    const bool hold = rebuilding && rebuilding();
    for (std::size_t i = 0; i < m_live.size(); ++i) {
        const Live &live = m_live[i];
        if (!live.endpoint)
            continue;
        const auto held = m_held.find(live.key);
        if (hold) {
            if (!got[i].isEmpty())
                m_held[live.key] += got[i];
            continue;
        }
        QByteArray bytes = std::move(got[i]);
        if (held != m_held.end()) {
            bytes.prepend(held->second);
            m_held.erase(held);
        }
        if (!bytes.isEmpty())
            network.transmit(live.endpoint, bytes);
    }
    std::erase_if(m_live, [](const Live &l) { return l.endpoint == nullptr; });
    return changed;
}

std::size_t SessionBridges::heldBytes() const {
    std::size_t n = 0;
    for (const auto &[key, bytes] : m_held)
        n += std::size_t(bytes.size());
    return n;
}

} // namespace rung::network
