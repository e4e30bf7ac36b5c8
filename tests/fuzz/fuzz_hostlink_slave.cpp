// Any bytes as Omron Host Link C-mode commands to the slave (the virtual PLC's responder over a
// memory image of a CPM1, in the mode the input picks): commands in parts, the CRs that ask
// for an answer's next part, reads, writes, forcing, mode changes. Every answer is a lone CR
// (the delimiter of a command in parts) or a part with a right FCS, no longer than the PLC
// sends, the first of an answer from this unit; the slave holds no more than a command in
// parts and an answer in parts. Input: unit, mode, then the peer's bytes in chunks.
#include "comms/protocol/host_link_slave.h"
#include "comms/slave/host_link_responder.h"
#include "comms/slave/memory_image.h"
#include "tests/fuzz/fuzz_comms_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    using namespace rung;
    using namespace rung::comms;
    static const model::Target &target = model::Target::get(model::Family::Cpm1);
    static const model::ProtocolMap &map =
        *model::findProtocolMap(target, model::ProtocolId::HostLink);
    fuzz::Input in{data, size};
    const int unit = in.byte() % 32;
    const slave::OperatingMode modes[] = {slave::OperatingMode::Program,
                                          slave::OperatingMode::Monitor, slave::OperatingMode::Run};
    auto image = std::make_shared<slave::MemoryImage>(target, modes[in.byte() % 3]);
    slave::HostLinkResponder responder(target, map, unit, image);
    const QByteArray own = "@" + QByteArray::number(unit).rightJustified(2, '0');
    // A command in parts and the parts of an answer not asked for yet.
    const qsizetype bound = hostlink::CommandDecoder::MaxBuffered + 2 * hostlink::MaxText;
    bool pending = false; // parts of an answer wait for the master's CR
    while (!in.done()) {
        const QByteArray chunk = in.chunk();
        const QByteArrayList out = responder.feed(chunk);
        // A CR first asks for the next part; anything else gives the rest of the answer up.
        bool later = pending && !chunk.isEmpty() && chunk.front() == hostlink::Cr;
        if (!chunk.isEmpty() && !later)
            pending = false;
        for (const QByteArray &f : out) {
            if (f == QByteArray(1, hostlink::Cr))
                continue; // the delimiter: send the command's next part
            // FCS "*" CR ends an answer's last part, FCS CR each other one.
            const qsizetype fcsAt = f.size() - (f.endsWith("*\r") ? 4 : 3);
            const bool framed = f.size() <= hostlink::MaxFirstFrame && f.endsWith(hostlink::Cr) &&
                                fcsAt >= 0 &&
                                hostlink::fcs(QByteArrayView(f).first(fcsAt)) == f.mid(fcsAt, 2);
            // The first part of an answer names this unit; a later part holds data only.
            const bool placed = later ? !f.startsWith('@') : f.startsWith(own);
            if (!framed || !placed) {
                std::fprintf(stderr, "the slave sent a frame that is not one: %s\n",
                             f.toHex(' ').constData());
                std::abort();
            }
            later = false;
            pending = !f.endsWith("*\r");
        }
        if (responder.buffered() > bound) {
            std::fprintf(stderr, "the slave holds %lld bytes, its bound is %lld\n",
                         static_cast<long long>(responder.buffered()),
                         static_cast<long long>(bound));
            std::abort();
        }
    }
    return 0;
}
