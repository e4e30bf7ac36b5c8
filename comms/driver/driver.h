#pragma once

// A PLC's devices over a protocol, by their own names (X0, D100, 010.00, Q1, V10, SM0.0): the
// device layer above the protocol drivers. Where a device sits on the wire is the target's
// protocol map (model/target/protocol_map.h); the reads a refresh needs come from the request
// planner (planner.h); values land in a memory image laid out as the simulator's
// (model::MemoryLayout), so a monitor reads both the same way.
//
// A write is done when the PLC acknowledged it: every call returns the PLC's answer, and a
// refused write is never sent again. A device the PLC refuses to read is named and left out,
// the others are still read.
//
// Threads: a Driver is used by one thread at a time (the online session's worker, or the
// command-line tool); only link().cancel() may be called from another.

#include "comms/driver/planner.h"
#include "comms/driver/protocol_driver.h"
#include "model/image/device_command.h"
#include "model/image/memory_layout.h"
#include "model/image/snapshot.h"

#include <map>
#include <memory>
#include <optional>
#include <variant>

namespace rung::comms {

class Driver {
public:
    // nullptr with *error when the target has no map for the protocol, or the station is not
    // one the protocol can answer from.
    static std::unique_ptr<Driver> create(const model::Target &target, ProtocolKind protocol,
                                          std::unique_ptr<Transport> transport, int station,
                                          const LinkSettings &settings, QString *error);
    ~Driver();

    const model::Target &target() const { return m_target; }
    ProtocolKind protocolKind() const { return m_kind; }
    Link &link() { return *m_link; }
    ProtocolDriver &protocol() { return *m_protocol; }
    QString plcName() const { return m_protocol->plcName(); }
    const std::shared_ptr<const model::MemoryLayout> &layout() const { return m_layout; }

    // A device as the target writes it; the message of an AddressError otherwise.
    std::variant<model::Address, QString> parseDevice(QStringView text) const;
    QString deviceName(const model::Address &address) const;

    // --- monitoring ---
    struct Placement {
        UnitSpan source;
        int bit = -1;           // a bit inside the source unit; -1: the unit is the value
        int word = -1;          // image word
        std::uint32_t mask = 0; // a bit of the image word; 0: the whole word takes the value
        int bits = 16;          // the value's width (sign)
    };
    struct Plan {
        std::vector<model::Address> devices;
        std::vector<std::vector<Placement>> placements; // per device
        std::vector<PlannedRead> reads;
        std::vector<std::pair<model::Address, QString>> unmapped; // devices with no place
        int bytes() const { return totalBytes(reads); }
    };
    Plan plan(const std::vector<model::Address> &devices) const;
    // Reads the plan's frames and puts the values into words (MemoryLayout order). A device
    // the PLC refuses (an address it lacks) is read alone to tell it from its neighbours and
    // listed in *refused; the error is for what stops the whole refresh (the link).
    DriverError refresh(const Plan &plan, std::vector<std::int32_t> &words,
                        std::vector<std::pair<model::Address, QString>> *refused);
    // The values of devices, as `read` prints them (number()). Fails on the first device that
    // cannot be read.
    DriverError read(const std::vector<model::Address> &devices, std::vector<qint64> *values);
    // The image a refresh fills and the commands execute() takes hold the PLC's words as its
    // memory does, as the simulator's image does: a CPM1 timer's present value 150 is the
    // word 0150h (BCD digits, W353), and RC / WC carry it so. A user reads and types numbers:
    // number() is a device's value as `read` prints it (a bit 0 / 1, a word its signed value
    // of its width, a BCD present value its number; a word that is not BCD as it is), and
    // wordOf() the word that holds a typed number (nullopt with why when it cannot).
    qint64 number(const model::Snapshot &image, const model::Address &device) const;
    std::optional<qint64> wordOf(const model::Address &device, qint64 number, QString *why) const;

    // --- commands (model::DeviceCommand) ---
    // *notice: what the driver did besides (Host Link: switched RUN to MONITOR to write).
    DriverError execute(const model::DeviceCommand &command, QString *notice = nullptr);
    // Bits forced by this driver (Host Link KS / KR), with their values: what a snapshot
    // shows as forced. The protocol has no command that lists forced bits.
    const std::map<model::Address, bool> &forced() const { return m_forced; }

    // --- mode and identification ---
    // Host Link: MS. Otherwise the target's RUN bit (PL110 SM0.0) or its "ON while running"
    // bit (Vigor M9000) when the map reaches it, read with the refresh (runStateDevice()).
    bool readsModeByCommand() const { return m_protocol->readsMode(); }
    model::Address runStateDevice() const { return m_runDevice; }
    DriverError readMode(PlcMode *mode);
    bool canSetMode() const;
    bool hasMonitorMode() const { return m_protocol->hasMonitorMode(); }
    bool canForce() const { return m_protocol->canForce(); }
    DriverError setMode(PlcMode mode);
    DriverError identify(PlcIdentity *identity) { return m_protocol->identify(identity); }

private:
    Driver(const model::Target &target, ProtocolKind kind, std::unique_ptr<Link> link);
    std::vector<Placement> placementsOf(const model::Address &address, QString *why) const;
    std::optional<model::ProtocolAddress> where(const model::Address &address,
                                                model::DevicePart part) const;
    // The PLC keeps the device's value as BCD digits (Host Link RC / WC).
    bool keepsBcd(const model::Address &address) const;
    // Checks the value fits, then (prepareWrite) writes it.
    DriverError writeValue(const model::Address &device, const model::Address &target, qint64 value,
                           const QString &what, QString *notice);
    DriverError prepareWrite(QString *notice);
    QString describeFrame(const Plan &plan, const PlannedRead &read) const;

    const model::Target &m_target;
    ProtocolKind m_kind;
    std::unique_ptr<Link> m_link;
    std::unique_ptr<ProtocolDriver> m_protocol;
    std::shared_ptr<const model::MemoryLayout> m_layout;
    std::vector<UnitSpan> m_segments;
    model::Address m_runDevice;  // read for the mode (RUN bit or "ON while running")
    model::Address m_runControl; // written for RUN / STOP (the RUN bit), when mapped
    std::map<model::Address, bool> m_forced;
};

} // namespace rung::comms
