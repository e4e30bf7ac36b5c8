#pragma once

// The virtual PLC: a simulated program that answers a master as the real PLC would. Composed
// here because app/ is the one room that knows both the simulator and comms: a
// SimulatorSession runs the program in real time, a comms::slave::SlaveServer serves it.
//
//  - Reads answer from the session's latest snapshot.
//  - A master's write goes through the session's command inbox, is applied at a scan
//    boundary, and is answered after it took effect (or with the protocol's error).
//  - PROGRAM mode (Host Link SC 00, PL110 SM0 bit 0 = 0) pauses the scan and keeps the image;
//    MONITOR and RUN scan.
//
// The session lives on a thread of the virtual PLC's own, with an event loop, so nothing here
// needs the caller's event loop and nothing blocks the caller's thread but stop(). Qt runs an
// event loop only in an application: without a QCoreApplication, serve() and listen() say so.

#include "comms/slave/slave_server.h"
#include "simulator/program.h"

#include <QThread>

#include <memory>

namespace rung::simulator {
class SimulatorSession;
}

namespace rung::app {

class SessionImage;

class VirtualPlc {
public:
    struct Options {
        comms::slave::SlaveOptions slave;
        qint64 periodMs = 0; // the virtual scan period; 0: the program's
        comms::slave::OperatingMode mode = comms::slave::OperatingMode::Run; // at power-on
    };

    VirtualPlc(std::shared_ptr<const simulator::Program> program, Options options);
    ~VirtualPlc(); // stop()
    VirtualPlc(const VirtualPlc &) = delete;
    VirtualPlc &operator=(const VirtualPlc &) = delete;

    // Serves one byte stream (a pty, a serial port); false with the reason.
    bool serve(std::unique_ptr<comms::Transport> transport, QString *error);
    // Serves TCP clients on host:port (port 0: any free one, see port()).
    bool listen(const QHostAddress &host, quint16 port, QString *error);
    quint16 port() const;
    void stop(); // idempotent

    comms::slave::SlaveStatistics statistics() const;
    QString lastProblem() const;
    // What the slave serves; valid while this VirtualPlc lives (null without an application).
    std::shared_ptr<comms::slave::DeviceImage> image() const;

private:
    bool ready(QString *error) const;

    QThread m_thread;                                 // the session's owner, with an event loop
    simulator::SimulatorSession *m_session = nullptr; // lives on m_thread
    std::shared_ptr<SessionImage> m_image;
    std::unique_ptr<comms::slave::SlaveServer> m_server;
};

} // namespace rung::app
