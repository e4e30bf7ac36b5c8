#pragma once

// Test vectors as hex bytes, the way the manuals' example frames are written out here:
// "02 30 30 35 31" -> bytes.

#include <QByteArray>
#include <QString>

namespace rung::comms::test {

inline QByteArray bytes(const char *spaced) {
    return QByteArray::fromHex(QByteArray(spaced).replace(' ', ""));
}

} // namespace rung::comms::test
