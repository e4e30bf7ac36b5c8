#pragma once

// A pass-through recorder: two ports joined, every byte passed on at once in both directions
// and recorded with its time. The VPC's link protocol is not published (the VPC user's manual,
// I and V, names the RS232C link to VPC Host Interface and gives no frame format), so nothing
// here speaks it; a VPC user puts the relay between VPC Host Interface and the PLC and keeps
// what the two said to each other. It works the same for any PLC and program.
//
// Threading: one worker per direction reads one side and writes the other, so neither
// direction waits for the other; the tap is read from any thread (TrafficTap). Sent in the
// tap is "from the PC to the PLC", Received "from the PLC to the PC".

#include "comms/driver/traffic.h"
#include "comms/transport/transport.h"

#include <QString>

#include <atomic>
#include <memory>
#include <mutex>
#include <thread>

namespace rung::comms {

class Relay {
public:
    Relay(std::unique_ptr<Transport> pc, std::unique_ptr<Transport> plc);
    ~Relay();
    Relay(const Relay &) = delete;
    Relay &operator=(const Relay &) = delete;

    // Opens both sides (a side already open stays as it is) and starts passing bytes; false
    // with a message naming the side and the port when one cannot be opened.
    bool start(QString *error);
    // Stops both directions and closes both sides; safe to call twice.
    void stop();
    // False once either side has failed (the failure says which and why) or after stop().
    bool running() const { return m_running.load(); }
    // Empty while both sides work.
    QString failure() const;

    const TrafficTap &tap() const { return m_tap; }
    const Transport &pc() const { return *m_pc; }
    const Transport &plc() const { return *m_plc; }

private:
    void pump(Transport &from, Transport &to, TrafficRecord::Direction direction,
              const QString &fromSide, const QString &toSide);
    void fail(const QString &message);

    std::unique_ptr<Transport> m_pc;
    std::unique_ptr<Transport> m_plc;
    TrafficTap m_tap;
    std::atomic<bool> m_running{false};
    std::atomic<bool> m_stopping{false};
    mutable std::mutex m_failureMutex;
    QString m_failure;
    std::thread m_toPlc;
    std::thread m_toPc;
};

// One record as a line of a capture or a traffic log: the time of day to the microsecond,
// the direction (sentLabel or receivedLabel), the bytes in hex and then as ASCII (a dot for
// what is not printable), e.g. "12:30:01.123456 PC>PLC 05 30 31 46  |.01F|".
QString formatTrafficRecord(const TrafficRecord &record, const QDateTime &start,
                            const QString &sentLabel, const QString &receivedLabel);

} // namespace rung::comms
