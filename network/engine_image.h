#pragma once

// A station's engine as the image a slave serves (comms/slave/device_image.h): a request is
// answered from the engine's memory after the scan, a write changes it at once, between
// scans, as a PLC does its communication work after the user program. One thread: the
// network's.

#include "comms/slave/device_image.h"
#include "network/image_writes.h"
#include "simulator/engine.h"

namespace rung::network {

class EngineImage final : public comms::slave::DeviceImage {
public:
    // written: where the writes are marked for the network's history (the station's).
    EngineImage(simulator::Engine *engine, ImageWrites *written)
        : m_engine(engine)
        , m_written(written) {}

    std::shared_ptr<const model::Snapshot> snapshot() const override;
    comms::slave::ImageChange apply(const std::vector<model::DeviceCommand> &commands,
                                    QDeadlineTimer deadline) override;
    // RUN, or MONITOR once a master asked for it (Host Link SC 02: W353, writes are refused in
    // RUN): the program runs in both.
    comms::slave::OperatingMode mode() const override { return m_mode; }
    comms::slave::ImageChange setMode(comms::slave::OperatingMode mode,
                                      QDeadlineTimer deadline) override;

private:
    simulator::Engine *m_engine;
    ImageWrites *m_written;
    void markWritten(const model::DeviceCommand &command);
    // The snapshot of the last scan, taken once for the requests answered after it.
    mutable std::shared_ptr<const model::Snapshot> m_snapshot;
    mutable quint64 m_scans = ~quint64(0);
    comms::slave::OperatingMode m_mode = comms::slave::OperatingMode::Run;
};

} // namespace rung::network
