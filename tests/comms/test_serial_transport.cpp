#include "comms/transport/serial_transport.h"

#include <gtest/gtest.h>

namespace rung::comms {
namespace {

TEST(SerialTransport, AMissingPortIsNamedWithTheCause) {
    SerialTransport t(QStringLiteral("/dev/ttyUSB-not-here"), {});
    QString error;
    EXPECT_FALSE(t.open(&error));
    EXPECT_FALSE(t.isOpen());
    EXPECT_TRUE(error.contains(QLatin1String("/dev/ttyUSB-not-here"))) << error.toStdString();
    EXPECT_TRUE(error.contains(QLatin1String("unplugged"))) << error.toStdString();
    EXPECT_EQ(t.read(QDeadlineTimer(10)).status, ReadResult::Status::Failed);
    EXPECT_FALSE(t.write("x", QDeadlineTimer(10), &error));
}

TEST(SerialTransport, ThePortListGivesNamesAndUsbIdsInVidPidForm) {
    // The container may have no serial port at all; what is listed must be well formed.
    for (const auto &port : availableSerialPorts()) {
        EXPECT_FALSE(port.name.isEmpty());
        if (port.usbVendor >= 0) {
            EXPECT_EQ(port.usbId().size(), 9) << port.usbId().toStdString();
        }
    }
    SerialPortInfo ftdi{QStringLiteral("/dev/ttyUSB0"), QStringLiteral("FT232R"), 0x0403, 0x6001};
    EXPECT_EQ(ftdi.usbId(), QLatin1String("0403:6001"));
    EXPECT_TRUE(SerialPortInfo{}.usbId().isEmpty());
}

TEST(SerialSettings, TheRtuGapIsThreeAndAHalfCharactersUpTo19200AndFixedAbove) {
    SerialSettings s;
    s.baud = 9600; // 8N1: 10 bits, 1041 us a character
    EXPECT_EQ(s.characterMicroseconds(), 1041);
    EXPECT_EQ(s.rtuGapMicroseconds(), 3643);
    s.baud = 38400;
    EXPECT_EQ(s.rtuGapMicroseconds(), 1750);
    s.baud = 19200;
    s.dataBits = 7;
    s.parity = SerialSettings::Parity::Even; // Vigor 7E1: still 10 bits
    EXPECT_EQ(s.characterMicroseconds(), 520);
}

} // namespace
} // namespace rung::comms
