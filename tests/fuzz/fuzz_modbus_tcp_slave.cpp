// Any bytes as Modbus TCP requests to the slave (the virtual PLC's responder over a memory
// image of a Vigor with the CP2 map, or of a PL110): decoded, answered through the map,
// written into the image. Every answer is an MBAP frame (protocol 0, its length field the
// frame's) of a unit this slave answers as, with a well-formed PDU; the slave never holds
// more than its decoder's bound. Input: map, station, then the peer's bytes in chunks.
#include "tests/fuzz/fuzz_modbus_slave.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    using namespace rung::comms;
    fuzz::Input in{data, size};
    fuzz::ModbusSlave slave(in, modbus::Framing::Tcp);
    const auto valid = [&slave](const QByteArray &f) {
        if (f.size() < 9 || f.size() > modbus::MaxTcpFrame || f[2] != 0 || f[3] != 0 ||
            !slave.answersAs(std::uint8_t(f[6]), modbus::Framing::Tcp))
            return false;
        const int length = std::uint8_t(f[4]) << 8 | std::uint8_t(f[5]);
        return length == f.size() - 6 && fuzz::validResponsePdu(QByteArrayView(f).sliced(7));
    };
    fuzz::serveAll(in, slave.responder, modbus::RequestDecoder::MaxBuffered, false, valid);
    return 0;
}
