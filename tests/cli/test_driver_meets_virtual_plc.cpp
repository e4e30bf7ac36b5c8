// Our master (comms::Driver, devices by name) against our slave (the virtual PLC running a
// program) for every protocol, over a real pseudo-terminal and TCP loopback: read, write,
// force and RUN / STOP where the protocol has them. Each side was also tested against real
// peers (mbpoll, libmodbus, pymodbus) and the manuals' example frames; this is the two
// meeting.

#include "comms/driver/driver.h"
#include "comms/transport/pty_transport.h"
#include "comms/transport/tcp_transport.h"
#include "tests/cli/virtual_plc_fixture.h"

#include <gtest/gtest.h>

#include <limits>
#include <variant>

namespace rung::test {
namespace {

using comms::DriverError;
using comms::PlcMode;
using comms::ProtocolKind;
using model::DeviceCommand;
using model::ProtocolId;

// 010.00 follows HR 00.00, 010.01 follows the input 000.01; DM 0001 = DM 0000.
constexpr const char *kCpm1 = "; target: cpm1\n"
                              "LD HR 00.00\nOUT 010.00\nLD 000.01\nOUT 010.01\n"
                              "LD 253.13\nMOV(21) DM 0000 DM 0001\nEND(01)\n";

struct Master {
    std::unique_ptr<comms::Driver> driver;

    Master(const char *target, ProtocolKind kind, std::unique_ptr<comms::Transport> transport,
           int station) {
        comms::LinkSettings link;
        link.timeoutMs = 1000;
        link.retries = 2;
        QString error;
        driver = comms::Driver::create(*model::Target::byId(QString::fromLatin1(target)), kind,
                                       std::move(transport), station, link, &error);
        EXPECT_TRUE(driver) << error.toStdString();
        if (driver) {
            EXPECT_TRUE(driver->link().open(&error)) << error.toStdString();
        }
    }
    model::Address at(const char *device) const {
        const auto parsed = driver->parseDevice(QString::fromLatin1(device));
        EXPECT_TRUE(std::holds_alternative<model::Address>(parsed)) << device;
        return std::holds_alternative<model::Address>(parsed) ? std::get<model::Address>(parsed)
                                                              : model::Address{};
    }
    // The device's value as `read` prints it; INT64_MIN when it cannot be read.
    qint64 value(const char *device) {
        std::vector<qint64> values;
        const DriverError e = driver->read({at(device)}, &values);
        EXPECT_TRUE(e.ok()) << device << ": " << e.message.toStdString();
        return e.ok() && !values.empty() ? values.front() : std::numeric_limits<qint64>::min();
    }
    DriverError run(DeviceCommand::Kind kind, const char *device, qint64 value = 0,
                    QString *notice = nullptr) {
        return driver->execute({kind, at(device), value}, notice);
    }
    bool becomes(const char *device, qint64 expected) {
        return eventually([&] { return value(device) == expected; });
    }
};

std::unique_ptr<comms::Transport> ptyTo(const VirtualPlcUnderTest &plc) {
    return std::make_unique<comms::PtyTransport>(plc.path);
}

TEST(DriverMeetsVirtualPlc, VigorComputerLinkOnAPty) {
    VirtualPlcUnderTest plc(kFollowerVigor, {ProtocolId::VigorLink, comms::modbus::Framing::Rtu, 0},
                            false);
    ASSERT_TRUE(plc.ready());
    Master m("vigor", ProtocolKind::VigorLink, ptyTo(plc), 0);
    ASSERT_TRUE(m.driver);
    EXPECT_EQ(m.value("Y0"), 0);
    ASSERT_TRUE(m.run(DeviceCommand::Kind::WriteBit, "M0", 1).ok()); // 70h
    EXPECT_TRUE(m.becomes("Y0", 1));
    ASSERT_TRUE(m.run(DeviceCommand::Kind::WriteWord, "D0", -1234).ok()); // 61h
    EXPECT_TRUE(m.becomes("D1", -1233));
    PlcMode mode = PlcMode::Unknown;
    ASSERT_TRUE(m.driver->readMode(&mode).ok());
    EXPECT_EQ(mode, PlcMode::Run); // M9000 is ON while the program runs
    // The link has no force and no RUN / STOP: said, not faked.
    EXPECT_EQ(m.run(DeviceCommand::Kind::Force, "M0", 1).kind, DriverError::Kind::Unsupported);
    EXPECT_FALSE(m.driver->canSetMode());
}

TEST(DriverMeetsVirtualPlc, Pl110ModbusRtuOnAPtyWithRunAndStop) {
    VirtualPlcUnderTest plc(kFollowerPl110, {ProtocolId::Modbus, comms::modbus::Framing::Rtu, 1},
                            false);
    ASSERT_TRUE(plc.ready());
    Master m("pl110", ProtocolKind::ModbusRtu, ptyTo(plc), 1);
    ASSERT_TRUE(m.driver);
    ASSERT_TRUE(m.run(DeviceCommand::Kind::WriteBit, "M1", 1).ok());
    EXPECT_TRUE(m.becomes("Q2", 1));
    ASSERT_TRUE(m.run(DeviceCommand::Kind::WriteWord, "V0", 321).ok());
    EXPECT_TRUE(m.becomes("V1", 321));
    // SM0 bit 0 is RUN (PL110 manual 2.1.2, 3.2): STOP keeps the image, the program stops
    // following.
    ASSERT_TRUE(m.driver->canSetMode());
    ASSERT_TRUE(m.driver->setMode(PlcMode::Stop).ok());
    PlcMode mode = PlcMode::Unknown;
    ASSERT_TRUE(m.driver->readMode(&mode).ok());
    EXPECT_NE(mode, PlcMode::Run);
    ASSERT_TRUE(m.run(DeviceCommand::Kind::WriteWord, "V0", 7).ok());
    EXPECT_EQ(m.value("V1"), 321);
    ASSERT_TRUE(m.driver->setMode(PlcMode::Run).ok());
    EXPECT_TRUE(m.becomes("V1", 7));
}

TEST(DriverMeetsVirtualPlc, VigorCp2ModbusOverTcpLoopback) {
    VirtualPlcUnderTest plc(kFollowerVigor, {ProtocolId::Modbus, comms::modbus::Framing::Tcp, 1},
                            true);
    ASSERT_TRUE(plc.ready());
    Master m("vigor", ProtocolKind::ModbusTcp,
             std::make_unique<comms::TcpTransport>(QStringLiteral("127.0.0.1"), plc.port), 1);
    ASSERT_TRUE(m.driver);
    ASSERT_TRUE(m.run(DeviceCommand::Kind::WriteWord, "D0", 99).ok());
    EXPECT_TRUE(m.becomes("D1", 100));
    ASSERT_TRUE(m.run(DeviceCommand::Kind::WriteBit, "M0", 1).ok());
    EXPECT_TRUE(m.becomes("Y0", 1));
    ASSERT_TRUE(m.run(DeviceCommand::Kind::WriteBit, "M0", 0).ok());
    EXPECT_TRUE(m.becomes("Y0", 0));
}

TEST(DriverMeetsVirtualPlc, Cpm1HostLinkOnAPtyWritesThroughMonitorAndForces) {
    VirtualPlcUnderTest plc(kCpm1, {ProtocolId::HostLink, comms::modbus::Framing::Rtu, 0}, false);
    ASSERT_TRUE(plc.ready());
    Master m("cpm1", ProtocolKind::HostLink, ptyTo(plc), 0);
    ASSERT_TRUE(m.driver);
    PlcMode mode = PlcMode::Unknown;
    ASSERT_TRUE(m.driver->readMode(&mode).ok()); // MS
    EXPECT_EQ(mode, PlcMode::Run);
    // A CPM1 in RUN refuses writes: the driver goes to MONITOR first and says so.
    QString notice;
    ASSERT_TRUE(m.run(DeviceCommand::Kind::WriteWord, "DM 0000", 0x1234, &notice).ok());
    EXPECT_FALSE(notice.isEmpty());
    ASSERT_TRUE(m.driver->readMode(&mode).ok());
    EXPECT_EQ(mode, PlcMode::Monitor);
    EXPECT_TRUE(m.becomes("DM 0001", m.value("DM 0000")));
    // KS: an input forced ON against the wiring (the CIO area; Omron CPM1/SRM1 programming
    // manual W353, Host Link); HR cannot be.
    const DriverError forced = m.run(DeviceCommand::Kind::Force, "000.01", 1);
    ASSERT_TRUE(forced.ok()) << forced.message.toStdString();
    EXPECT_TRUE(m.becomes("010.01", 1));
    EXPECT_EQ(m.driver->forced().size(), 1u);
    // Host Link releases all forced bits at once (KC), not one: said, with what to do.
    const DriverError one = m.run(DeviceCommand::Kind::Release, "000.01");
    EXPECT_FALSE(one.ok());
    EXPECT_TRUE(one.message.contains(QLatin1String("KC"))) << one.message.toStdString();
    const DriverError all = m.driver->execute({DeviceCommand::Kind::ReleaseAll, {}, 0});
    ASSERT_TRUE(all.ok()) << all.message.toStdString();
    EXPECT_TRUE(m.becomes("010.01", 0));
    EXPECT_TRUE(m.driver->forced().empty());
    const DriverError hr = m.run(DeviceCommand::Kind::Force, "HR 00.00", 1);
    EXPECT_FALSE(hr.ok());
    EXPECT_TRUE(hr.message.contains(QLatin1String("HR00.00"))) << hr.message.toStdString();
    // SC: back to RUN.
    ASSERT_TRUE(m.driver->setMode(PlcMode::Run).ok());
    ASSERT_TRUE(m.driver->readMode(&mode).ok());
    EXPECT_EQ(mode, PlcMode::Run);
}

TEST(DriverMeetsVirtualPlc, Cpm1HostLinkReadsTheIrAndSrWordsTo255AsTheCliDoes) {
    // RR reads the IR and SR words 000..255 (Omron CPM1/SRM1 manual W353, Host Link RR; the
    // Omron CPM1 guide 3.5, memory map):
    // the input channel 000, the flags 253.13 (always ON) and 255.06 (EQ) and their words.
    VirtualPlcUnderTest plc(kCpm1, {ProtocolId::HostLink, comms::modbus::Framing::Rtu, 0}, false);
    ASSERT_TRUE(plc.ready());
    ASSERT_TRUE(plc.scanned());
    Master m("cpm1", ProtocolKind::HostLink, ptyTo(plc), 0);
    ASSERT_TRUE(m.driver);
    std::vector<model::Address> devices;
    for (const char *d : {"000", "253.13", "255.06", "253", "254", "255", "000.01"})
        devices.push_back(m.at(d));
    const comms::Driver::Plan plan = m.driver->plan(devices);
    for (const auto &[device, why] : plan.unmapped)
        ADD_FAILURE() << why.toStdString();
    EXPECT_EQ(m.value("253.13"), 1);
    EXPECT_EQ(m.value("253") & 0x2000, 0x2000);
    EXPECT_EQ(m.value("000"), 0);
    EXPECT_EQ(m.value("255.06"), m.value("255") >> 6 & 1);
    // The flags are the PLC's: WR to 253 is refused (end code 04), and nothing changes.
    const DriverError refused = m.run(DeviceCommand::Kind::WriteWord, "253", 0);
    EXPECT_EQ(refused.kind, DriverError::Kind::Refused) << refused.message.toStdString();
    EXPECT_EQ(m.value("253.13"), 1);
}

} // namespace
} // namespace rung::test
