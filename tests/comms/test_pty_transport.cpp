#include "comms/protocol/vigor_link.h"
#include "comms/transport/pty_transport.h"
#include "tests/comms/hex.h"

#include <gtest/gtest.h>

#include <QElapsedTimer>

#include <thread>

namespace rung::comms {
namespace {

using R = ReadResult::Status;

struct Pair {
    std::unique_ptr<PtyTransport> master;
    std::unique_ptr<PtyTransport> peer;
};

Pair makePair() {
    Pair p;
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
QByteArray readAll(Transport &t, qsizetype size, int ms = 2000) {
    QByteArray out;
    const QDeadlineTimer deadline(ms);
    while (out.size() < size) {
        const auto r = t.read(deadline);
        if (r.status != R::Data)
            break;
        out += r.bytes;
    }
    return out;
}

TEST(PtyTransport, AVigorRequestCrossesARealPseudoTerminalByteForByteBothWays) {
    Pair p = makePair();
    ASSERT_TRUE(p.peer);
    // Every byte value, including CR, ^C and ^S, must pass untouched (raw mode, no echo).
    QByteArray all;
    for (int i = 0; i < 256; ++i)
        all += char(i);
    QString error;
    ASSERT_TRUE(p.peer->write(all, QDeadlineTimer(2000), &error)) << error.toStdString();
    EXPECT_EQ(readAll(*p.master, all.size()), all);
    const QByteArray request = test::bytes("02 30 30 37 30 30 34 30 41 03 39 46");
    ASSERT_TRUE(p.master->write(request, QDeadlineTimer(2000), &error));
    EXPECT_EQ(readAll(*p.peer, request.size()), request);
}

TEST(PtyTransport, AReadWithNothingToReadEndsAtItsDeadline) {
    Pair p = makePair();
    ASSERT_TRUE(p.peer);
    QElapsedTimer clock;
    clock.start();
    const auto r = p.peer->read(QDeadlineTimer(50));
    EXPECT_EQ(r.status, R::Timeout);
    EXPECT_GE(clock.elapsed(), 45);
    EXPECT_LT(clock.elapsed(), 1000);
}

TEST(PtyTransport, CancelFromAnotherThreadWakesAWaitingRead) {
    Pair p = makePair();
    ASSERT_TRUE(p.peer);
    ReadResult result;
    std::thread reader([&] { result = p.peer->read(QDeadlineTimer(QDeadlineTimer::Forever)); });
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    p.peer->cancel();
    reader.join();
    EXPECT_EQ(result.status, R::Cancelled);
}

TEST(PtyTransport, OpeningAMissingPathOrANonTerminalNamesThePathAndTheCause) {
    PtyTransport missing(QStringLiteral("/dev/pts/does-not-exist"));
    QString error;
    EXPECT_FALSE(missing.open(&error));
    EXPECT_TRUE(error.contains(QLatin1String("/dev/pts/does-not-exist")));
    EXPECT_TRUE(error.contains(QLatin1String("No such file")));
    PtyTransport notTty(QStringLiteral("/dev/null"));
    EXPECT_FALSE(notTty.open(&error));
    EXPECT_TRUE(error.contains(QLatin1String("not a terminal")));
    ReadResult r = notTty.read(QDeadlineTimer(10));
    EXPECT_EQ(r.status, R::Failed);
}

TEST(PtyTransport, TheMasterGoingAwayFailsTheReadInsteadOfHanging) {
    Pair p = makePair();
    ASSERT_TRUE(p.peer);
    p.master.reset();
    const auto r = p.peer->read(QDeadlineTimer(2000));
    EXPECT_EQ(r.status, R::Failed);
    EXPECT_FALSE(r.message.isEmpty());
}

TEST(PtyTransport, AReplySplitAcrossWritesIsDecodedWhole) {
    Pair p = makePair();
    ASSERT_TRUE(p.peer);
    const QByteArray reply = test::bytes("06 30 30 35 31 30 30 41 37 39 33 03 30 44");
    vigor::ReplyDecoder d({0, vigor::Command::Read, 0x0081, 2, {}});
    QString error;
    for (qsizetype i = 0; i < reply.size(); i += 3)
        ASSERT_TRUE(p.master->write(reply.mid(i, 3), QDeadlineTimer(1000), &error));
    const QDeadlineTimer deadline(2000);
    while (d.status() == FrameStatus::NeedMore) {
        const auto r = p.peer->read(deadline);
        ASSERT_EQ(r.status, R::Data);
        d.feed(r.bytes);
    }
    ASSERT_EQ(d.status(), FrameStatus::Complete);
    EXPECT_EQ(d.reply().data, test::bytes("A7 93"));
}

} // namespace
} // namespace rung::comms
