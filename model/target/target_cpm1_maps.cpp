#include "model/target/protocol_map.h"

#include <QCoreApplication>

// Omron CPM1 Host Link areas (Omron CPM1/SRM1 programming manual W353, Host Link): IR/SR
// channels through RR / WR, HR through RH / WH, DM through RD / WD, timer / counter present values
// through RC / WC and their completion flags through RG. A channel's bit is that word's bit. RR
// reads IR and SR to channel 255 (W353's IR/SR area, 000..255); SR 253..255 hold the flags the PLC
// sets (253.13 always ON, the arithmetic flags 255.03..255.07), which RR reads and WR may not
// write. RD / WD reach DM 0000..1023 and 6144..6655; the DM words past 6655 are the PLC's but not
// the protocol's.

namespace rung::model::detail {

std::vector<ProtocolMap> cpm1ProtocolMaps() {
    using P = DevicePart;
    using S = ProtocolSpace;
    ProtocolMap m;
    m.protocol = ProtocolId::HostLink;
    m.description = QT_TRANSLATE_NOOP("rung::model::Target", "Omron Host Link (C-mode)");
    m.modelCode = 0x11; // MM: "C2000H/CQM1/CPM1/CPM1A/SRM1" (W353 6-3-28)
    m.ranges = {
        {"IN", P::Value, S::HostLinkIr, 0, 0},
        {"IN", P::Bit, S::HostLinkIr, 0, 0},
        {"OUT", P::Value, S::HostLinkIr, 10, 10},
        {"OUT", P::Bit, S::HostLinkIr, 10, 10},
        {"WR", P::Value, S::HostLinkIr, 200, 200},
        {"WR", P::Bit, S::HostLinkIr, 200, 200},
        {"SR", P::Value, S::HostLinkIr, 232, 232, 252},
        {"SR", P::Bit, S::HostLinkIr, 232, 232, 252},
        {"SR", P::Value, S::HostLinkIr, 253, 253, 255, true},
        {"SR", P::Bit, S::HostLinkIr, 253, 253, 255, true},
        {"HR", P::Value, S::HostLinkHr, 0, 0},
        {"HR", P::Bit, S::HostLinkHr, 0, 0},
        {"DM", P::Value, S::HostLinkDm, 0, 0},
        {"DMR", P::Value, S::HostLinkDm, 6144, 6144, 6655},
        {"TIM", P::Value, S::HostLinkTimerPv, 0, 0},
        {"CNT", P::Value, S::HostLinkTimerPv, 0, 0},
        {"TIM", P::Bit, S::HostLinkCompletion, 0, 0},
        {"CNT", P::Bit, S::HostLinkCompletion, 0, 0},
    };
    return {m};
}

} // namespace rung::model::detail
