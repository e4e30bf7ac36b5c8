// Any bytes as requests to the Vigor Computer Link slave (the virtual PLC's responder over a
// memory image of a Vigor): decoded, answered through the protocol map, written into the
// image. Every answer is an ACK frame of the slave's station with a right sum; the slave never
// holds more than its decoder's bound. Input: the station byte, then the peer's bytes in chunks.
#include "comms/protocol/vigor_link_slave.h"
#include "comms/slave/memory_image.h"
#include "comms/slave/vigor_responder.h"
#include "tests/fuzz/fuzz_comms_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    using namespace rung;
    using namespace rung::comms;
    static const model::Target &target = model::Target::get(model::Family::Vigor);
    static const model::ProtocolMap &map =
        *model::findProtocolMap(target, model::ProtocolId::VigorLink);
    fuzz::Input in{data, size};
    const int station = in.byte();
    auto image = std::make_shared<slave::MemoryImage>(target);
    slave::VigorResponder responder(target, map, station, image);
    QByteArray own;
    own += "0123456789ABCDEF"[station >> 4];
    own += "0123456789ABCDEF"[station & 15];
    // <ACK> station(2) command(2) error(2) data... <ETX> sum(2)
    const auto valid = [&own](const QByteArray &f) {
        return f.size() >= 10 && f.size() <= vigor::MaxReplyFrame && f.front() == vigor::Ack &&
               f.mid(1, 2) == own && f.at(f.size() - 3) == vigor::Etx &&
               fuzz::isUpperHex(f.mid(1, f.size() - 4)) &&
               vigor::sum(f.mid(1, f.size() - 3)) == f.right(2);
    };
    fuzz::serveAll(in, responder, vigor::RequestDecoder::MaxBuffered, false, valid);
    return 0;
}
