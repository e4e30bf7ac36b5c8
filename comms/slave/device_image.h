#pragma once

// What a slave serves: a PLC's memory image behind an interface of the slave's own, so that
// comms does not know who keeps the image. The virtual PLC (app/) puts a simulator session
// behind it; MemoryImage (memory_image.h) is an image without a program.
//
// Threads: a slave calls these from its worker threads (one per serial line or TCP client),
// never from a UI thread; an implementation must be safe for several of them at once.

#include "model/image/device_command.h"
#include "model/image/snapshot.h"

#include <QDeadlineTimer>
#include <QString>

#include <cstdint>
#include <memory>
#include <vector>

namespace rung::comms::slave {

// Where the PLC stands. PROGRAM: not scanning; MONITOR: scanning, writes allowed; RUN:
// scanning (Host Link refuses writes in RUN, W353; the other protocols write in RUN too).
enum class OperatingMode : std::uint8_t { Program, Monitor, Run };

struct ImageChange {
    enum class Status : std::uint8_t {
        Done,     // the change took effect: a read from now on sees it
        Refused,  // the image cannot take it (message says which device and why)
        TimedOut, // not applied by the deadline (the program's scan is stuck or far too slow)
    };
    Status status = Status::Done;
    QString message; // translated; empty when Done
    bool done() const { return status == Status::Done; }
};

class DeviceImage {
public:
    virtual ~DeviceImage() = default;
    DeviceImage() = default;
    DeviceImage(const DeviceImage &) = delete;
    DeviceImage &operator=(const DeviceImage &) = delete;

    // The latest image; one request is answered from one snapshot. Never null.
    virtual std::shared_ptr<const model::Snapshot> snapshot() const = 0;
    // Applies the commands in order, together (a simulator: at one scan boundary), and returns
    // once they took effect, or why not. Blocks the calling worker thread up to the deadline.
    virtual ImageChange apply(const std::vector<model::DeviceCommand> &commands,
                              QDeadlineTimer deadline) = 0;
    virtual OperatingMode mode() const = 0;
    // PROGRAM stops the scan (the image is kept), MONITOR and RUN start it.
    virtual ImageChange setMode(OperatingMode mode, QDeadlineTimer deadline) = 0;
};

} // namespace rung::comms::slave
