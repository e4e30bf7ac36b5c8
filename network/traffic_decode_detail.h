#pragma once

// What the Traffic view's decoders of each protocol share (traffic_decode.cpp: Vigor and
// MODBUS, traffic_decode_host_link.cpp: Host Link): the texts of addresses, data and faults,
// the verdict on a reply, and the last request on a wire.

#include "network/traffic_decode.h"

#include "comms/protocol/host_link_master.h"
#include "comms/protocol/host_link_slave.h"
#include "comms/protocol/modbus_master.h"
#include "comms/protocol/vigor_link_master.h"
#include "model/target/protocol_map.h"

#include <QString>

#include <optional>
#include <vector>

namespace rung::network {

namespace decode_detail {

// A word as four hexadecimal digits.
QString hex4(int value);

// The device at a unit of a space as the target writes it; empty when the map has none.
QString deviceAt(const model::Target *target, model::ProtocolId protocol,
                 model::ProtocolSpace space, int unit, int bit);

// The device with the address on the wire beside it ("DM 0000 (0000)"); the raw address alone
// where no device is known.
QString withDevice(const QString &device, const QString &raw);

// The first `count` bits as 0s and 1s.
QString bitsText(const std::vector<bool> &bits, int count);

// A frame of no protocol as a reader would quote it: printable characters as they are, the
// others as C escapes.
QString quoted(QByteArrayView bytes);

// A frame that stops before its end; bytes after a frame's end.
QString truncatedText(qsizetype size);
QString extraText(qsizetype size);

// A master's reply decoder's verdict on a whole frame, into `f`: the PLC's error or exception
// code (its text by codeText), or what is wrong with the frame; true when the reply reads.
template <typename ReplyDecoder>
bool verdict(const ReplyDecoder &decoder, qsizetype size, QString (*codeText)(int),
             DecodedFrame &f) {
    switch (decoder.status()) {
    case comms::FrameStatus::NeedMore:
        f.problem = truncatedText(size);
        return false;
    case comms::FrameStatus::Failed:
        if (decoder.error().kind == comms::ProtocolError::Kind::DeviceError) {
            f.errorCode = decoder.error().code;
            f.errorText = codeText(f.errorCode);
        } else {
            f.problem = decoder.error().message;
        }
        return false;
    case comms::FrameStatus::Complete:
        return true;
    }
    return false;
}

} // namespace decode_detail

// For the two decoders' files (the only ones that include this header).
using decode_detail::bitsText;
using decode_detail::deviceAt;
using decode_detail::extraText;
using decode_detail::hex4;
using decode_detail::quoted;
using decode_detail::truncatedText;
using decode_detail::verdict;
using decode_detail::withDevice;

struct TrafficDecoder::Pending {
    TrafficDecoder::End::Speaks speaks = TrafficDecoder::End::Speaks::Nothing;
    QString sender;
    const End *slave = nullptr;
    int station = 0;
    bool ascii = false;
    comms::vigor::Request vigor;
    comms::modbus::Request modbus;
    // Host Link: the command (or a command in parts so far), a reply in parts so far, the
    // parts seen of either, and the command's address and count as decoded.
    comms::hostlink::Frame hostLink;
    std::optional<comms::hostlink::CommandDecoder> hostLinkCommand;
    std::optional<comms::hostlink::ReplyDecoder> hostLinkReply;
    int parts = 0;
    int rawAddress = -1;
    QString address;
    int count = -1;
};

} // namespace rung::network
