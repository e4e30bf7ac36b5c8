#pragma once

// Omron Host Link, C-mode commands (Omron CPM1/SRM1 programming manual W353, Host Link; the
// C200HS manual), both sides, no I/O. This file holds what both sides share; the master's side
// is host_link_master.h, the slave's host_link_slave.h.
//   command  "@" unit(2 decimal) header(2) text FCS(2 hex) "*" CR
//   response "@" unit header end-code(2 hex) text FCS "*" CR
// FCS = XOR of every character from "@" (or the frame's first character) to the end of the
// text. A frame over 131 characters is split: the first holds at most 131 characters, each
// later one at most 128; a frame that is not the last ends in FCS CR (no "*"), and the other
// side answers a lone CR (the delimiter) before the next part comes.

#include "comms/protocol/protocol_error.h"
#include "model/target/protocol_map.h"

#include <QByteArray>
#include <QList>

#include <cstdint>

namespace rung::comms::hostlink {

inline constexpr char Cr = '\r';
inline constexpr int MaxFirstFrame = 131;
inline constexpr int MaxLaterFrame = 128;
// The longest legal text of a command or reply, all parts joined: a count is four decimal
// digits, so a write carries at most a begin word and 9999 words of four hex digits.
inline constexpr int MaxWords = 9999;
inline constexpr int MaxText = 4 + 4 * MaxWords;
// Characters the slave holds while looking for a part's CR: a part too long for the PLC
// (over 131) still gets its end code 18 up to this length; beyond it the bytes are noise.
inline constexpr int MaxPartBuffer = 4 * MaxFirstFrame;

// The word areas the read / write commands reach are the Host Link spaces of the protocol
// maps (model::ProtocolSpace::HostLinkIr .. HostLinkCompletion: RR/WR, RH/WH, RD/WD, RC/WC,
// RG), so a driver passes what the CPM1 map gives without a translation table of its own.
using model::ProtocolSpace;

enum class Mode : std::uint8_t { Program = 0x00, Monitor = 0x02, Run = 0x03 };

// End codes (W353, Host Link commands).
enum EndCode : std::uint8_t {
    Normal = 0x00,
    NotInRun = 0x01,
    NotInMonitor = 0x02,
    WriteProtected = 0x03,
    AddressOver = 0x04,
    NotInProgram = 0x0B,
    FcsError = 0x13,
    FormatError = 0x14,
    EntryNumberError = 0x15,
    NotSupported = 0x16,
    FrameLengthError = 0x18,
};

struct Frame {
    int unit = 0;
    QByteArray header; // "RD", "MS", ...
    int endCode = -1;  // responses only; -1 for a command
    QByteArray text;   // everything after the header (and end code), all parts joined
};

// The characters' XOR as two upper-case hex digits.
QByteArray fcs(QByteArrayView characters);

// A whole frame as it goes on the wire: one string per part (split over 131 characters;
// word data is split on whole words, as the PLC does: 30 words, then 31 per part).
QList<QByteArray> encode(const Frame &frame);

QString endCodeText(int code);

// Which space a read / write header reaches; false when it is neither.
bool spaceOfHeader(QByteArrayView header, ProtocolSpace &space, bool &write);

} // namespace rung::comms::hostlink
