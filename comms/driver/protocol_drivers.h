#pragma once

// The three protocol drivers (protocol_driver.h). Made by makeProtocolDriver(); declared here
// for it and for their own sources.

#include "comms/driver/protocol_driver.h"
#include "comms/protocol/host_link_master.h"
#include "comms/protocol/modbus_master.h"

#include <map>

namespace rung::comms::detail {

// Vigor M / VB / VH Computer Link (Vigor M/VB/VH communication manual, B-5): 51h / 61h over
// the byte map, 70h / 71h for bits. No force, no RUN / STOP, no identification: B-5-3
// documents no command for them.
class VigorLinkDriver final : public ProtocolDriver {
public:
    using ProtocolDriver::ProtocolDriver;
    QString plcName() const override;
    int maxReadUnits(model::ProtocolSpace space) const override;
    int readFrameBytes(model::ProtocolSpace space, int units) const override;
    DriverError readUnits(model::ProtocolSpace space, int start, int count,
                          std::vector<std::uint32_t> *units, const QString &what) override;
    DriverError writeUnits(model::ProtocolSpace space, int start,
                           const std::vector<std::uint32_t> &units, const QString &what) override;
    DriverError writeBit(const model::ProtocolAddress &address, bool on,
                         const QString &what) override;
};

// Modbus RTU (or RTU over raw TCP) and Modbus TCP. Coils 01 / 05 / 0F, discrete inputs 02,
// holding registers 03 / 06 / 10; the map's limit (PL110: 30 words) on register requests.
// Identification from the map's model / version registers (PL110 words 0 and 1).
class ModbusDriver final : public ProtocolDriver {
public:
    ModbusDriver(Link &link, const model::Target &target, const model::ProtocolMap &map,
                 int station, bool tcp);
    QString plcName() const override;
    int maxReadUnits(model::ProtocolSpace space) const override;
    int readFrameBytes(model::ProtocolSpace space, int units) const override;
    DriverError readUnits(model::ProtocolSpace space, int start, int count,
                          std::vector<std::uint32_t> *units, const QString &what) override;
    DriverError writeUnits(model::ProtocolSpace space, int start,
                           const std::vector<std::uint32_t> &units, const QString &what) override;
    DriverError writeBit(const model::ProtocolAddress &address, bool on,
                         const QString &what) override;
    bool identifies() const override;
    DriverError identify(PlcIdentity *identity) override;

private:
    DriverError transact(const modbus::Request &request, modbus::Response *response,
                         const QString &what);
    bool m_tcp;
    int m_transaction = 0;
};

// Omron Host Link C-mode (Omron CPM1/SRM1 programming manual W353, Host Link): RR/WR, RH/WH,
// RD/WD, RC/WC (BCD), RG; bits of IR / HR written by reading the word and writing it back;
// KS / KR / KC force; MS / SC mode; MM model. Writes in RUN are refused by the PLC (end code
// 01): prepareWrite() switches it to MONITOR first and says so.
class HostLinkDriver final : public ProtocolDriver {
public:
    using ProtocolDriver::ProtocolDriver;
    QString plcName() const override;
    int maxReadUnits(model::ProtocolSpace space) const override;
    int readFrameBytes(model::ProtocolSpace space, int units) const override;
    bool bcdUnits(model::ProtocolSpace space) const override;
    DriverError readUnits(model::ProtocolSpace space, int start, int count,
                          std::vector<std::uint32_t> *units, const QString &what) override;
    DriverError writeUnits(model::ProtocolSpace space, int start,
                           const std::vector<std::uint32_t> &units, const QString &what) override;
    DriverError writeBit(const model::ProtocolAddress &address, bool on,
                         const QString &what) override;
    bool canForce() const override { return true; }
    DriverError forceBit(const model::ProtocolAddress &address, bool on,
                         const QString &what) override;
    DriverError releaseAllForces(const QString &what) override;
    bool readsMode() const override { return true; }
    DriverError readMode(PlcMode *mode) override;
    bool setsMode() const override { return true; }
    bool hasMonitorMode() const override { return true; }
    DriverError setMode(PlcMode mode) override;
    DriverError prepareWrite(QString *notice) override;
    bool identifies() const override { return true; }
    DriverError identify(PlcIdentity *identity) override;

private:
    DriverError command(const hostlink::Frame &frame, hostlink::Reply *reply, const QString &what);
    mutable std::map<std::pair<int, int>, int> m_costs; // (space, units) -> bytes
    PlcMode m_mode = PlcMode::Unknown;
};

} // namespace rung::comms::detail
