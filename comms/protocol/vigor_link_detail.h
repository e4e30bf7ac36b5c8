#pragma once

// What the Vigor link's two sides share beyond its interface: vigor_link.cpp defines it for
// the master's side (vigor_link_master.cpp) and the slave's (vigor_link_slave.cpp). Not part
// of the codec's interface: include vigor_link_master.h or vigor_link_slave.h instead.

#include <QByteArray>

namespace rung::comms::vigor::detail {

// Body (station .. ETX) + sum; the caller puts the start byte in front.
QByteArray closeFrame(char start, QByteArray body);

} // namespace rung::comms::vigor::detail
