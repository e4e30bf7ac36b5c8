#pragma once

// Test vectors as protocols.md writes them: "02 30 30 35 31" -> bytes.

#include <QByteArray>
#include <QString>

namespace rung::comms::test {

inline QByteArray bytes(const char *spaced) {
    return QByteArray::fromHex(QByteArray(spaced).replace(' ', ""));
}

} // namespace rung::comms::test
