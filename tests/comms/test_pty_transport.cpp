#include "comms/driver/connection.h"
#include "comms/protocol/vigor_link_master.h"
#include "comms/transport/pty_transport.h"
#include "tests/comms/hex.h"
#include "tests/comms/pty_pair.h"

#include <gtest/gtest.h>

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>

#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <unistd.h>

#include <thread>
#include <vector>

namespace rung::comms {
namespace {

using R = ReadResult::Status;

using test::makePtyPair;
using test::readAll;

// Whether the terminal at `path` has input to read within `ms`, without reading it.
bool readableWithin(const QString &path, int ms) {
    const int fd = ::open(QFile::encodeName(path).constData(), O_RDONLY | O_NOCTTY | O_NONBLOCK);
    if (fd < 0)
        return false;
    pollfd p{fd, POLLIN, 0};
    const bool readable = ::poll(&p, 1, ms) == 1 && (p.revents & POLLIN) != 0;
    ::close(fd);
    return readable;
}

TEST(PtyTransport, AVigorRequestCrossesARealPseudoTerminalByteForByteBothWays) {
    test::PtyPair p = makePtyPair();
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
    test::PtyPair p = makePtyPair();
    ASSERT_TRUE(p.peer);
    QElapsedTimer clock;
    clock.start();
    const auto r = p.peer->read(QDeadlineTimer(50));
    EXPECT_EQ(r.status, R::Timeout);
    EXPECT_GE(clock.elapsed(), 45);
    EXPECT_LT(clock.elapsed(), 1000);
}

TEST(PtyTransport, CancelFromAnotherThreadWakesAWaitingRead) {
    test::PtyPair p = makePtyPair();
    ASSERT_TRUE(p.peer);
    ReadResult result;
    std::thread reader([&] { result = p.peer->read(QDeadlineTimer(QDeadlineTimer::Forever)); });
    // A pause, not a wait for a condition: nothing outside the transport tells that its read
    // is waiting. A cancel before the read ends it Cancelled all the same (the next test), so
    // a loaded machine cannot make this test fail, only test less.
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
    test::PtyPair p = makePtyPair();
    ASSERT_TRUE(p.peer);
    p.master.reset();
    const auto r = p.peer->read(QDeadlineTimer(2000));
    EXPECT_EQ(r.status, R::Failed);
    EXPECT_FALSE(r.message.isEmpty());
}

TEST(PtyTransport, AReplySplitAcrossWritesIsDecodedWhole) {
    test::PtyPair p = makePtyPair();
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

TEST(PtyTransport, ACancelWithNoReadWaitingEndsTheNextReadOnceAndIsNotLost) {
    // transport.h: a cancel() between two reads ends the next read that would wait, once,
    // however many came; data already there comes first.
    test::PtyPair p = makePtyPair();
    ASSERT_TRUE(p.peer);
    p.peer->cancel();
    p.peer->cancel();
    QElapsedTimer clock;
    clock.start();
    EXPECT_EQ(p.peer->read(QDeadlineTimer(5000)).status, R::Cancelled);
    EXPECT_LT(clock.elapsed(), 1000);
    EXPECT_EQ(p.peer->read(QDeadlineTimer(50)).status, R::Timeout);

    QString error;
    ASSERT_TRUE(p.master->write("x", QDeadlineTimer(1000), &error));
    // The kernel hands a pty's bytes to the other side's line discipline later, on a work
    // queue: wait until the peer's side has it to read (a second descriptor of the same
    // terminal sees the same input queue) before the cancel.
    ASSERT_TRUE(readableWithin(p.master->peerPath(), 2000));
    p.peer->cancel();
    const auto first = p.peer->read(QDeadlineTimer(1000));
    EXPECT_EQ(first.status, R::Data);
    EXPECT_EQ(first.bytes, QByteArray("x"));
    EXPECT_EQ(p.peer->read(QDeadlineTimer(1000)).status, R::Cancelled);
}

TEST(PtyTransport, AClosedPairIsNotOpenedAgainAsItsOwnPeer) {
    QString error;
    auto master = PtyTransport::createPair(&error);
    ASSERT_TRUE(master) << error.toStdString();
    const QString path = master->peerPath();
    master->close();
    EXPECT_FALSE(master->isOpen());
    EXPECT_FALSE(master->open(&error));
    EXPECT_FALSE(master->isOpen());
    EXPECT_TRUE(error.contains(path)) << error.toStdString();
    EXPECT_TRUE(error.contains(QLatin1String("make a new one"))) << error.toStdString();
}

int openDescriptors() {
    return int(QDir(QStringLiteral("/proc/self/fd")).entryList(QDir::Files | QDir::System).size());
}

// Leaves exactly `free` file descriptors to the process while it lives.
class DescriptorsLeft {
public:
    explicit DescriptorsLeft(int free) {
        ::getrlimit(RLIMIT_NOFILE, &m_old);
        int highest = 0;
        for (const QString &fd :
             QDir(QStringLiteral("/proc/self/fd")).entryList(QDir::Files | QDir::System))
            highest = std::max(highest, fd.toInt());
        rlimit low = m_old;
        low.rlim_cur = rlim_t(highest + 64);
        ::setrlimit(RLIMIT_NOFILE, &low);
        for (int fd; (fd = ::open("/dev/null", O_RDONLY | O_CLOEXEC)) >= 0;)
            m_fillers.push_back(fd);
        for (int i = 0; i < free && !m_fillers.empty(); ++i) {
            ::close(m_fillers.back());
            m_fillers.pop_back();
        }
    }
    ~DescriptorsLeft() {
        for (int fd : m_fillers)
            ::close(fd);
        ::setrlimit(RLIMIT_NOFILE, &m_old);
    }

private:
    rlimit m_old{};
    std::vector<int> m_fillers;
};

TEST(PtyTransport, RunningOutOfDescriptorsIsAClearErrorAndLeaksNothing) {
    test::PtyPair p = makePtyPair(); // a terminal to open while descriptors are short
    ASSERT_TRUE(p.peer);
    const int before = openDescriptors();
    bool refusedAll = false, madeOne = false;
    for (int free = 0; free <= 6; ++free) {
        QString error;
        std::unique_ptr<PtyTransport> pair;
        std::unique_ptr<PtyTransport> peer;
        bool peerOpened = false;
        {
            const DescriptorsLeft left(free);
            pair = PtyTransport::createPair(&error);
            if (!pair) {
                EXPECT_TRUE(error.startsWith(QLatin1String("Cannot create a pseudo-terminal: ")))
                    << error.toStdString();
                EXPECT_GT(error.size(), 35) << "no cause given";
            }
            if (free == 0)
                refusedAll = !pair;
            madeOne = madeOne || pair;
            QString peerError;
            peer = std::make_unique<PtyTransport>(p.master->peerPath());
            peerOpened = peer->open(&peerError);
            if (!peerOpened) {
                EXPECT_TRUE(peerError.contains(p.master->peerPath())) << peerError.toStdString();
                EXPECT_FALSE(peerError.isEmpty());
            }
        }
        if (free <= 1) { // the wake-up pipe needs two: the peer reports it cannot have one
            EXPECT_FALSE(peerOpened) << free;
        }
        pair.reset();
        peer.reset();
    }
    EXPECT_TRUE(refusedAll);
    EXPECT_TRUE(madeOne);
    EXPECT_EQ(openDescriptors(), before);
}

// A user copies the /dev/pts path that `serve --pty` or socat printed into --port (or the
// connection panel's port box): it works as a port, also through socat's symbolic link,
// though libserialport cannot open a pseudo-terminal.
TEST(PtyTransport, APseudoTerminalNamedAsASerialPortOpensAsOne) {
    QString error;
    std::unique_ptr<PtyTransport> master = PtyTransport::createPair(&error);
    ASSERT_TRUE(master) << error.toStdString();
    QTemporaryDir dir;
    const QString link = dir.filePath(QStringLiteral("ttyV0"));
    ASSERT_TRUE(QFile::link(master->peerPath(), link));
    ConnectionSettings settings = defaultSettings(ProtocolKind::VigorLink);
    for (const QString &port : {master->peerPath(), link}) {
        settings.via = ConnectionSettings::Via::Serial;
        settings.port = port;
        std::unique_ptr<Transport> t = makeTransport(settings);
        ASSERT_TRUE(t->open(&error)) << port.toStdString() << ": " << error.toStdString();
        EXPECT_EQ(t->name(), port);
        ASSERT_TRUE(t->write("\x05"
                             "00",
                             QDeadlineTimer(2000), &error));
        EXPECT_EQ(readAll(*master, 3), QByteArray("\x05"
                                                  "00"));
        t->close();
    }
}

// `serve --pty --link PATH` restarting: the link leads to a pseudo-terminal that is gone, and
// the next start points it at a new one. A master given PATH in between still takes it for a
// pseudo-terminal, and opens the new one through it once it is there.
TEST(PtyTransport, ALinkToAPseudoTerminalThatIsGoneIsStillOneAndOpensWhenItLeadsToOneAgain) {
    QTemporaryDir dir;
    const QString link = dir.filePath(QStringLiteral("plc"));
    ASSERT_TRUE(QFile::link(QStringLiteral("/dev/pts/4000"), link));
    std::unique_ptr<Transport> t = makePortTransport(link, SerialSettings{});
    ASSERT_NE(dynamic_cast<PtyTransport *>(t.get()), nullptr);
    QString error;
    EXPECT_FALSE(t->open(&error));
    EXPECT_TRUE(error.contains(link)) << error.toStdString();
    std::unique_ptr<PtyTransport> master = PtyTransport::createPair(&error);
    ASSERT_TRUE(master) << error.toStdString();
    ASSERT_TRUE(QFile::remove(link));
    ASSERT_TRUE(QFile::link(master->peerPath(), link));
    ASSERT_TRUE(t->open(&error)) << error.toStdString();
    ASSERT_TRUE(t->write("\x05", QDeadlineTimer(2000), &error)) << error.toStdString();
    EXPECT_EQ(readAll(*master, 1), QByteArray("\x05"));
}

// A name that is no pseudo-terminal stays a serial port, and its error names the port.
TEST(PtyTransport, AMissingPortIsASerialPortWhoseErrorNamesIt) {
    std::unique_ptr<Transport> t =
        makePortTransport(QStringLiteral("/dev/ttyNoSuchPort7"), SerialSettings{});
    QString error;
    EXPECT_FALSE(t->open(&error));
    EXPECT_TRUE(error.contains(QLatin1String("/dev/ttyNoSuchPort7"))) << error.toStdString();
    EXPECT_EQ(dynamic_cast<PtyTransport *>(t.get()), nullptr);
}

} // namespace
} // namespace rung::comms
