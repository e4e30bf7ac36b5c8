#pragma once

// A new pseudo-terminal with both ends open, for tests that talk through a real one: the
// master side (PtyTransport::createPair) and a PtyTransport opened on its peer path.

#include "comms/transport/pty_transport.h"

#include <gtest/gtest.h>

#include <QDeadlineTimer>

#include <memory>

namespace rung::comms::test {

struct PtyPair {
    std::unique_ptr<PtyTransport> master;
    std::unique_ptr<PtyTransport> peer;
};

inline PtyPair makePtyPair() {
    PtyPair p;
    QString error;
    p.master = PtyTransport::createPair(&error);
    EXPECT_TRUE(p.master) << error.toStdString();
    if (!p.master)
        return p;
    EXPECT_TRUE(p.master->peerPath().startsWith(QLatin1String("/dev/pts/")));
    p.peer = std::make_unique<PtyTransport>(p.master->peerPath());
    EXPECT_TRUE(p.peer->open(&error)) << error.toStdString();
    return p;
}

// Reads until `size` bytes arrived or a read returns something other than data.
inline QByteArray readAll(Transport &t, qsizetype size, int ms = 2000) {
    QByteArray out;
    const QDeadlineTimer deadline(ms);
    while (out.size() < size) {
        const ReadResult r = t.read(deadline);
        if (r.status != ReadResult::Status::Data)
            break;
        out += r.bytes;
    }
    return out;
}

} // namespace rung::comms::test
