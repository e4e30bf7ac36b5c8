#include "comms/slave/vigor_responder.h"

namespace rung::comms::slave {

namespace {

using vigor::Command;
using vigor::ErrorCode;

} // namespace

VigorResponder::VigorResponder(const model::Target &target, const model::ProtocolMap &map,
                               int station, std::shared_ptr<DeviceImage> image, int writeTimeoutMs)
    : Responder(target, map, station, std::move(image), writeTimeoutMs) {}

QByteArray VigorResponder::breakChecksum(QByteArray frame) const {
    if (frame.size() >= 2) // the sum's last digit: another hex digit, still upper case
        frame[frame.size() - 1] = frame.back() == '0' ? '1' : '0';
    return frame;
}

QByteArray VigorResponder::answer(const vigor::Request &request, int errorCode) {
    vigor::Reply reply;
    reply.station = m_replyStation;
    reply.command = request.command;
    reply.error = errorCode;
    if (errorCode != 0)
        ++m_statistics.refused;
    return vigor::encodeReply(reply);
}

QByteArrayList VigorResponder::feed(QByteArrayView bytes) {
    QByteArrayList out;
    m_decoder.feed(bytes);
    while (m_decoder.status() == FrameStatus::Complete) {
        const vigor::Request request = m_decoder.request();
        const int error = m_decoder.errorCode();
        if (!m_decoder.discarded().ok())
            m_lastProblem = m_decoder.discarded().message;
        // A frame for another station, or one whose station cannot be read, is not ours to
        // answer (a shared RS-485 line carries the other PLCs' traffic).
        if (request.station != m_station)
            ++m_statistics.ignored;
        else if (error != 0)
            out << answer(request, error);
        else
            out << respond(request);
        m_decoder.next();
    }
    return out;
}

QByteArray VigorResponder::respond(const vigor::Request &request) {
    const auto snapshot = m_image->snapshot();
    const auto space = model::ProtocolSpace::LinkBytes;
    MappedImage::Change change;
    switch (request.command) {
    case Command::Read: {
        const MappedImage::Units units =
            m_mapped.read(*snapshot, m_image->mode(), space, request.address, request.length);
        if (units.refusal != MappedImage::Refusal::None)
            return answer(request, int(ErrorCode::AddressRange));
        vigor::Reply reply{m_replyStation, request.command, 0, {}};
        for (const std::uint16_t byte : units.values)
            reply.data += char(byte & 0xFF);
        ++m_statistics.answered;
        return vigor::encodeReply(reply);
    }
    case Command::Write: {
        std::vector<std::uint16_t> values;
        for (const char byte : request.data)
            values.push_back(static_cast<quint8>(byte));
        change = m_mapped.write(*snapshot, space, request.address, values);
        break;
    }
    case Command::BitOn:
    case Command::BitOff: {
        const int byte = request.address >> 3;
        const int bit = request.address & 7;
        // B-5: 70h / 71h act on X, Y, M and S, the bit devices.
        const auto d = m_mapped.device(space, byte, bit);
        if (!d || d->part != model::DevicePart::Bit ||
            m_mapped.target().area(d->area).kind != model::AreaKind::Bit)
            return answer(request, int(ErrorCode::AddressRange));
        change = m_mapped.writeBit(space, byte, bit, request.command == Command::BitOn);
        break;
    }
    }
    if (change.refusal != MappedImage::Refusal::None)
        return answer(request, int(ErrorCode::AddressRange));
    const ImageChange done = apply(change);
    if (!done.done()) {
        m_lastProblem = done.message;
        // Refused by the image: the address cannot take it; not applied in time: the
        // "communication error (like STOP)" of B-5.
        return answer(request, done.status == ImageChange::Status::Refused
                                   ? int(ErrorCode::AddressRange)
                                   : int(ErrorCode::Communication));
    }
    ++m_statistics.answered;
    ++m_statistics.writes;
    return answer(request, 0);
}

} // namespace rung::comms::slave
