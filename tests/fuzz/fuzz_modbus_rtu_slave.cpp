// Any bytes as Modbus RTU requests to the slave (the virtual PLC's responder over a memory
// image of a Vigor with the CP2 map, or of a PL110), with silences between chunks where the
// input says: decoded, answered through the map, written into the image. Every answer is an
// RTU frame from this slave's unit with a right CRC and a well-formed PDU; the slave never
// holds more than its decoder's bound. Input: map, station, then chunks each followed by the
// byte that says whether the line goes quiet.
#include "tests/fuzz/fuzz_modbus_slave.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    using namespace rung::comms;
    fuzz::Input in{data, size};
    fuzz::ModbusSlave slave(in, modbus::Framing::Rtu);
    const auto valid = [&slave](const QByteArray &f) {
        if (f.size() < 5 || f.size() > modbus::MaxRtuFrame ||
            !slave.answersAs(std::uint8_t(f[0]), modbus::Framing::Rtu))
            return false;
        const std::uint16_t crc = modbus::crc16(QByteArrayView(f).first(f.size() - 2));
        return std::uint8_t(f[f.size() - 2]) == (crc & 0xFF) &&
               std::uint8_t(f[f.size() - 1]) == (crc >> 8) &&
               fuzz::validResponsePdu(QByteArrayView(f).sliced(1, f.size() - 3));
    };
    fuzz::serveAll(in, slave.responder, modbus::RequestDecoder::MaxBuffered, true, valid);
    return 0;
}
