#include "comms/protocol/host_link.h"

#include "comms/protocol/ascii_hex.h"
#include "comms/protocol/host_link_detail.h"

namespace rung::comms::hostlink {

namespace {

using comms::detail::appendDecimal;
using comms::detail::appendHex;
using comms::detail::hex2;
using detail::AreaHeaders;
using detail::Part;

constexpr AreaHeaders areaHeaders[] = {
    {ProtocolSpace::HostLinkIr, "RR", "WR"},
    {ProtocolSpace::HostLinkHr, "RH", "WH"},
    {ProtocolSpace::HostLinkDm, "RD", "WD"},
    {ProtocolSpace::HostLinkTimerPv, "RC", "WC"},
    {ProtocolSpace::HostLinkCompletion, "RG", nullptr},
};

bool isWordHeader(QByteArrayView header) {
    for (const auto &h : areaHeaders)
        if (header == QByteArrayView(h.read) && h.space != ProtocolSpace::HostLinkCompletion)
            return true;
        else if (h.write && header == QByteArrayView(h.write))
            return true;
    return false;
}

} // namespace

const AreaHeaders *detail::headersOf(ProtocolSpace space) {
    for (const auto &h : areaHeaders)
        if (h.space == space)
            return &h;
    return nullptr;
}

Part detail::splitPart(QByteArrayView frame) {
    Part p;
    p.last = frame.endsWith('*');
    const QByteArrayView body = p.last ? frame.chopped(1) : frame;
    if (body.size() < 2)
        return p;
    p.content = body.chopped(2);
    p.received = body.last(2).toByteArray();
    p.computed = fcs(p.content);
    p.fcsOk = p.received == p.computed;
    return p;
}

QByteArray fcs(QByteArrayView characters) {
    int value = 0;
    for (char c : characters)
        value ^= static_cast<quint8>(c);
    QByteArray out;
    appendHex(out, value, 2);
    return out;
}

QList<QByteArray> encode(const Frame &frame) {
    QByteArray content("@");
    appendDecimal(content, frame.unit, 2);
    content += frame.header;
    if (frame.endCode >= 0)
        appendHex(content, frame.endCode, 2);
    const qsizetype dataStart =
        content.size() + (frame.endCode < 0 && frame.header.startsWith('W') ? 4 : 0);
    const int unit = isWordHeader(frame.header) ? 4 : 1;
    content += frame.text;

    QList<QByteArray> parts;
    qsizetype pos = 0;
    bool first = true;
    while (true) {
        const qsizetype room = (first ? MaxFirstFrame : MaxLaterFrame) - 4; // FCS "*" CR
        if (content.size() - pos <= room) {
            const QByteArray chunk = content.mid(pos);
            parts << chunk + fcs(chunk) + "*" + Cr;
            return parts;
        }
        qsizetype end = pos + room;
        if (end > dataStart)
            end -= (end - dataStart) % unit;
        const QByteArray chunk = content.mid(pos, end - pos);
        parts << chunk + fcs(chunk) + Cr;
        pos = end;
        first = false;
    }
}

QString endCodeText(int code) {
    const QString hex = hex2(code);
    switch (code) {
    case Normal:
        return QCoreApplication::translate("rung::comms::Protocol",
                                           "normal completion (end code %1)")
            .arg(hex);
    case NotInRun:
        return QCoreApplication::translate(
                   "rung::comms::Protocol",
                   "not executable in RUN mode (end code %1): switch the PLC to "
                   "MONITOR to write")
            .arg(hex);
    case NotInMonitor:
        return QCoreApplication::translate("rung::comms::Protocol",
                                           "not executable in MONITOR mode (end code %1)")
            .arg(hex);
    case WriteProtected:
        return QCoreApplication::translate("rung::comms::Protocol",
                                           "the PLC's memory is write-protected (end code %1)")
            .arg(hex);
    case AddressOver:
        return QCoreApplication::translate(
                   "rung::comms::Protocol",
                   "address over: the area ends before the last word asked for "
                   "(end code %1)")
            .arg(hex);
    case NotInProgram:
        return QCoreApplication::translate("rung::comms::Protocol",
                                           "not executable in PROGRAM mode (end code %1)")
            .arg(hex);
    case FcsError:
        return QCoreApplication::translate(
                   "rung::comms::Protocol",
                   "the PLC received the command with a wrong FCS (end code %1): noise "
                   "on the line or a wrong parity setting")
            .arg(hex);
    case FormatError:
        return QCoreApplication::translate("rung::comms::Protocol",
                                           "the PLC found the command's format wrong (end code %1)")
            .arg(hex);
    case EntryNumberError:
        return QCoreApplication::translate("rung::comms::Protocol",
                                           "a number in the command is out of range (end code %1)")
            .arg(hex);
    case NotSupported:
        return QCoreApplication::translate("rung::comms::Protocol",
                                           "the PLC does not support the command (end code %1)")
            .arg(hex);
    case FrameLengthError:
        return QCoreApplication::translate("rung::comms::Protocol",
                                           "the command's frame is too long (end code %1)")
            .arg(hex);
    }
    return QCoreApplication::translate("rung::comms::Protocol", "end code %1").arg(hex);
}

bool spaceOfHeader(QByteArrayView header, ProtocolSpace &space, bool &write) {
    for (const auto &h : areaHeaders) {
        if (header == QByteArrayView(h.read)) {
            space = h.space;
            write = false;
            return true;
        }
        if (h.write && header == QByteArrayView(h.write)) {
            space = h.space;
            write = true;
            return true;
        }
    }
    return false;
}

} // namespace rung::comms::hostlink
