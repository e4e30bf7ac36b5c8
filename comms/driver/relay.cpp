#include "comms/driver/relay.h"
#include "comms/tr.h"

#include <QCoreApplication>

namespace rung::comms {

namespace {

// A read wakes this often to see whether the relay is stopping; a byte that arrives is
// passed on at once, whatever this is.
constexpr int kPollMs = 200;
// A side that does not take the bytes within this has stopped working.
constexpr int kWriteMs = 2000;

} // namespace

Relay::Relay(std::unique_ptr<Transport> pc, std::unique_ptr<Transport> plc)
    : m_pc(std::move(pc))
    , m_plc(std::move(plc)) {}

Relay::~Relay() {
    stop();
}

bool Relay::start(QString *error) {
    if (m_running.load() || m_toPlc.joinable())
        return true;
    const struct {
        Transport *side;
        QString label;
    } sides[] = {{m_pc.get(), RelayTr::tr("the PC's side")},
                 {m_plc.get(), RelayTr::tr("the PLC's side")}};
    for (const auto &s : sides) {
        QString why;
        if (!s.side->isOpen() && !s.side->open(&why)) {
            *error = RelayTr::tr("%1 (%2) cannot be opened: %3").arg(s.label, s.side->name(), why);
            m_pc->close();
            m_plc->close();
            return false;
        }
    }
    m_stopping = false;
    m_running = true;
    m_toPlc = std::thread([this] {
        pump(*m_pc, *m_plc, TrafficRecord::Direction::Sent, RelayTr::tr("the PC's side"),
             RelayTr::tr("the PLC's side"));
    });
    m_toPc = std::thread([this] {
        pump(*m_plc, *m_pc, TrafficRecord::Direction::Received, RelayTr::tr("the PLC's side"),
             RelayTr::tr("the PC's side"));
    });
    return true;
}

void Relay::stop() {
    m_stopping = true;
    m_pc->cancel();
    m_plc->cancel();
    if (m_toPlc.joinable())
        m_toPlc.join();
    if (m_toPc.joinable())
        m_toPc.join();
    m_running = false;
    m_pc->close();
    m_plc->close();
}

QString Relay::failure() const {
    std::lock_guard lock(m_failureMutex);
    return m_failure;
}

void Relay::fail(const QString &message) {
    {
        std::lock_guard lock(m_failureMutex);
        if (m_failure.isEmpty())
            m_failure = message;
    }
    // The other direction cannot go on alone: a capture with one side missing would mislead.
    m_running = false;
    m_stopping = true;
    m_pc->cancel();
    m_plc->cancel();
}

void Relay::pump(Transport &from, Transport &to, TrafficRecord::Direction direction,
                 const QString &fromSide, const QString &toSide) {
    while (!m_stopping.load()) {
        ReadResult r = from.read(QDeadlineTimer(kPollMs));
        switch (r.status) {
        case ReadResult::Status::Data: {
            // Recorded before it is passed on: the capture holds what was said even when the
            // other side is gone.
            m_tap.append(direction, r.bytes);
            QString why;
            if (!to.write(r.bytes, QDeadlineTimer(kWriteMs), &why)) {
                fail(RelayTr::tr("%1 (%2) stopped taking bytes: %3").arg(toSide, to.name(), why));
                return;
            }
            break;
        }
        case ReadResult::Status::Failed:
            fail(RelayTr::tr("%1 (%2) failed: %3").arg(fromSide, from.name(), r.message));
            return;
        case ReadResult::Status::Timeout:
        case ReadResult::Status::Cancelled:
            break;
        }
    }
}

QString formatTrafficRecord(const TrafficRecord &record, const QDateTime &start,
                            const QString &sentLabel, const QString &receivedLabel) {
    const QDateTime at = start.addMSecs(record.timeUs / 1000);
    QString line = at.toString(QStringLiteral("HH:mm:ss.zzz")) +
                   QStringLiteral("%1").arg(record.timeUs % 1000, 3, 10, QLatin1Char('0')) +
                   QLatin1Char(' ');
    const QString &label =
        record.direction == TrafficRecord::Direction::Sent ? sentLabel : receivedLabel;
    line += label.leftJustified(std::max(sentLabel.size(), receivedLabel.size()) + 1);
    line += QString::fromLatin1(record.bytes.toHex(' ').toUpper());
    line += QStringLiteral("  |");
    for (const char c : record.bytes)
        line += (c >= 0x20 && c < 0x7f) ? QLatin1Char(c) : QLatin1Char('.');
    line += QLatin1Char('|');
    return line;
}

} // namespace rung::comms
