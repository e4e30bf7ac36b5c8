// Any bytes as the Omron Host Link reply to a command the input picks (over any number of
// parts, with the delimiter taken after each), and as commands to the slave's decoder.
#include "comms/protocol/host_link_master.h"
#include "comms/protocol/host_link_slave.h"
#include "tests/fuzz/fuzz_comms_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    using namespace rung::comms;
    using namespace rung::comms::hostlink;
    fuzz::Input in{data, size};
    constexpr ProtocolSpace spaces[] = {ProtocolSpace::HostLinkIr, ProtocolSpace::HostLinkHr,
                                        ProtocolSpace::HostLinkDm, ProtocolSpace::HostLinkTimerPv,
                                        ProtocolSpace::HostLinkCompletion};
    const int unit = in.byte() % 32;
    Frame command;
    // One read per statement: the order of reads inside one call's arguments is unspecified.
    switch (in.byte() % 8) {
    case 0: {
        const auto space = spaces[in.byte() % 5];
        const int begin = in.word() % 10000;
        const int count = in.word() % 10000;
        command = readCommand(unit, space, begin, count);
        break;
    }
    case 1: {
        const auto space = spaces[in.byte() % 4];
        const int begin = in.word() % 10000;
        const auto words = std::size_t(in.byte());
        command = writeCommand(unit, space, begin, std::vector<std::uint16_t>(words, 0x1234));
        break;
    }
    case 2:
        command = statusCommand(unit);
        break;
    case 3:
        command = modeCommand(unit, Mode::Monitor);
        break;
    case 4: {
        const bool set = in.byte() % 2;
        const int word = in.word() % 10000;
        const int bit = in.byte() % 16;
        command = forceCommand(unit, set, word, bit);
        break;
    }
    case 5:
        command = cancelForceCommand(unit);
        break;
    default:
        command = modelCommand(unit);
        break;
    }
    (void)encode(command);
    const std::size_t start = in.at;
    ReplyDecoder master(command);
    while (!in.done() && master.status() == FrameStatus::NeedMore) {
        master.feed(in.chunk());
        fuzz::checkBound(master);
        (void)master.takeDelimiterRequest();
    }
    if (master.status() == FrameStatus::Failed && master.error().message.isEmpty())
        std::abort();
    if (master.status() == FrameStatus::NeedMore && master.deadlinePassed(100).message.isEmpty())
        std::abort();
    in.at = start;
    CommandDecoder slave;
    for (int frames = 0; !in.done() && frames < 64; ++frames) {
        slave.feed(in.chunk());
        fuzz::checkBound(slave);
        (void)slave.takeDelimiterRequest();
        if (slave.status() == FrameStatus::Complete) {
            (void)parseRead(slave.command().text);
            (void)parseWrite(slave.command().text);
            (void)parseForce(slave.command().text);
            slave.next();
        }
    }
    return 0;
}
