// Any bytes as the Vigor Computer Link reply to a request the input picks, and as requests
// to the slave's decoder.
#include "comms/protocol/vigor_link_master.h"
#include "comms/protocol/vigor_link_slave.h"
#include "tests/fuzz/fuzz_comms_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    using namespace rung::comms;
    fuzz::Input in{data, size};
    const vigor::Command commands[] = {vigor::Command::Read, vigor::Command::Write,
                                       vigor::Command::BitOn, vigor::Command::BitOff};
    vigor::Request request;
    request.station = in.byte();
    request.command = commands[in.byte() % 4];
    request.address = in.word();
    request.length = 1 + in.byte() % 128;
    const std::size_t start = in.at;
    vigor::ReplyDecoder master(request);
    fuzz::feedAll(in, master);
    in.at = start;
    vigor::RequestDecoder slave;
    for (int frames = 0; !in.done() && frames < 64; ++frames) {
        slave.feed(in.chunk());
        fuzz::checkBound(slave);
        if (slave.status() == FrameStatus::Complete)
            slave.next();
    }
    return 0;
}
