// Any bytes as the Modbus RTU or TCP reply to a request the input picks, and as requests to
// the slave's decoder (with and without the RTU silence that ends an unknown function).
#include "comms/protocol/modbus_master.h"
#include "comms/protocol/modbus_slave.h"
#include "tests/fuzz/fuzz_comms_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    using namespace rung::comms;
    fuzz::Input in{data, size};
    const auto framing = in.byte() % 2 ? modbus::Framing::Tcp : modbus::Framing::Rtu;
    const std::uint8_t functions[] = {0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x0F, 0x10};
    modbus::Request request;
    request.function = functions[in.byte() % 8];
    request.address = in.word();
    request.count = 1 + in.word() % 2000;
    if (request.function == 0x05)
        request.bits = {true};
    if (request.function == 0x06)
        request.registers = {std::uint16_t(in.word())};
    if (request.function == 0x0F)
        request.bits.assign(std::size_t(request.count), true);
    if (request.function == 0x10)
        request.registers.assign(std::size_t(1 + request.count % 123), 7);
    const int unit = in.byte();
    const std::size_t start = in.at;
    modbus::ReplyDecoder master(framing, unit, request, 1);
    fuzz::feedAll(in, master);
    in.at = start;
    modbus::RequestDecoder slave(framing);
    for (int frames = 0; !in.done() && frames < 64; ++frames) {
        slave.feed(in.chunk());
        fuzz::checkBound(slave);
        if (in.byte() % 4 == 0)
            slave.silence();
        fuzz::checkBound(slave);
        if (slave.status() == FrameStatus::Complete)
            slave.next();
    }
    return 0;
}
