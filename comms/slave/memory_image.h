#pragma once

// A device image without a program: memory that keeps what is written, laid out as the
// target's (model::MemoryLayout), with forcing. What a PLC in PROGRAM mode is to a master;
// the slave's own tests and a driver's tests serve it without a simulator.

#include "comms/slave/device_image.h"

#include <mutex>

namespace rung::comms::slave {

class MemoryImage final : public DeviceImage {
public:
    explicit MemoryImage(const model::Target &target, OperatingMode mode = OperatingMode::Run);

    std::shared_ptr<const model::Snapshot> snapshot() const override;
    ImageChange apply(const std::vector<model::DeviceCommand> &commands,
                      QDeadlineTimer deadline) override;
    OperatingMode mode() const override;
    ImageChange setMode(OperatingMode mode, QDeadlineTimer deadline) override;

    // For a test or a driver's fixture: how many apply() calls took effect.
    int changes() const;

private:
    mutable std::mutex m_mutex;
    std::shared_ptr<const model::Snapshot> m_snapshot; // replaced whole on every change
    OperatingMode m_mode;
    int m_changes = 0;
};

} // namespace rung::comms::slave
