#pragma once

// What the Host Link's two sides share beyond its interface: host_link.cpp defines it for the
// master's side (host_link_master.cpp) and the slave's (host_link_slave.cpp). Not part of the
// codec's interface: include host_link_master.h or host_link_slave.h instead.

#include "comms/protocol/host_link.h"

#include <QByteArray>

namespace rung::comms::hostlink::detail {

struct AreaHeaders {
    ProtocolSpace space;
    const char *read;
    const char *write; // nullptr: read only
};

// The read and write headers of a space; nullptr when it is not a Host Link space.
const AreaHeaders *headersOf(ProtocolSpace space);

// One received part (without its CR): checks the FCS, returns the text before it and whether
// it is the last part; nullopt when the FCS is wrong.
struct Part {
    QByteArrayView content;
    bool last = false;
    bool fcsOk = false;
    QByteArray received, computed;
};

Part splitPart(QByteArrayView frame);

} // namespace rung::comms::hostlink::detail
