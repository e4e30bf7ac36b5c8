#include "comms/protocol/modbus_master.h"
#include "comms/protocol/modbus_slave.h"
#include "comms/transport/tcp_listen_transport.h"
#include "comms/transport/tcp_transport.h"

#include <gtest/gtest.h>

#include <QElapsedTimer>

#include <thread>

namespace rung::comms {
namespace {

using R = ReadResult::Status;

struct Link {
    TcpServer server;
    std::unique_ptr<TcpTransport> client;
    std::unique_ptr<TcpTransport> accepted;
};

// A server on 127.0.0.1 (any free port) and a client connected to it.
std::unique_ptr<Link> connectLoopback() {
    auto link = std::make_unique<Link>();
    QString error;
    EXPECT_TRUE(link->server.listen(QHostAddress::LocalHost, 0, &error)) << error.toStdString();
    link->client = std::make_unique<TcpTransport>(QStringLiteral("127.0.0.1"), link->server.port());
    EXPECT_TRUE(link->client->open(&error)) << error.toStdString();
    link->accepted = link->server.accept(QDeadlineTimer(3000));
    EXPECT_TRUE(link->accepted);
    return link;
}

QByteArray readAll(Transport &t, qsizetype size) {
    QByteArray out;
    const QDeadlineTimer deadline(3000);
    while (out.size() < size) {
        const auto r = t.read(deadline);
        if (r.status != R::Data)
            break;
        out += r.bytes;
    }
    return out;
}

TEST(TcpTransport, AModbusTcpRequestAndReplyCrossTheLoopbackByteForByte) {
    auto link = connectLoopback();
    ASSERT_TRUE(link->accepted);
    modbus::Request request;
    request.function = modbus::ReadHoldingRegisters;
    request.count = 2;
    const QByteArray frame = modbus::tcpFrame(1, 1, modbus::encodeRequestPdu(request));
    QString error;
    ASSERT_TRUE(link->client->write(frame, QDeadlineTimer(3000), &error));
    EXPECT_EQ(readAll(*link->accepted, frame.size()), frame);
    modbus::Response response;
    response.function = modbus::ReadHoldingRegisters;
    response.registers = {0x1234, 0xABCD};
    ASSERT_TRUE(link->accepted->write(modbus::tcpFrame(1, 1, modbus::encodeResponsePdu(response)),
                                      QDeadlineTimer(3000), &error));
    modbus::ReplyDecoder d(modbus::Framing::Tcp, 1, request, 1);
    const QDeadlineTimer deadline(3000);
    while (d.status() == FrameStatus::NeedMore) {
        const auto r = link->client->read(deadline);
        ASSERT_EQ(r.status, R::Data);
        d.feed(r.bytes);
    }
    ASSERT_EQ(d.status(), FrameStatus::Complete);
    EXPECT_EQ(d.response().registers, response.registers);
}

TEST(TcpTransport, AQuietConnectionTimesOutAtTheDeadline) {
    auto link = connectLoopback();
    ASSERT_TRUE(link->accepted);
    QElapsedTimer clock;
    clock.start();
    EXPECT_EQ(link->client->read(QDeadlineTimer(60)).status, R::Timeout);
    EXPECT_GE(clock.elapsed(), 55);
    EXPECT_LT(clock.elapsed(), 1000);
}

TEST(TcpTransport, CancelFromAnotherThreadEndsAWaitingRead) {
    auto link = connectLoopback();
    ASSERT_TRUE(link->accepted);
    ReadResult result;
    std::thread canceller([&] {
        // A pause, not a wait for a condition: nothing outside the transport tells that its
        // read is waiting. If the cancel came first, the read would end Cancelled all the same
        // (the next test), so a loaded machine cannot make this test fail, only test less.
        std::this_thread::sleep_for(std::chrono::milliseconds(30));
        link->client->cancel();
    });
    result = link->client->read(QDeadlineTimer(QDeadlineTimer::Forever));
    canceller.join();
    EXPECT_EQ(result.status, R::Cancelled);
}

TEST(TcpTransport, ACancelWithNoReadWaitingEndsTheNextReadOnceAndIsNotLost) {
    auto link = connectLoopback();
    ASSERT_TRUE(link->accepted);
    link->client->cancel();
    link->client->cancel();
    QElapsedTimer clock;
    clock.start();
    EXPECT_EQ(link->client->read(QDeadlineTimer(5000)).status, R::Cancelled);
    EXPECT_LT(clock.elapsed(), 1000);
    EXPECT_EQ(link->client->read(QDeadlineTimer(50)).status, R::Timeout);
}

TEST(TcpTransport, ThePeerClosingFailsTheReadAndNamesTheConnection) {
    auto link = connectLoopback();
    ASSERT_TRUE(link->accepted);
    link->accepted->close();
    const auto r = link->client->read(QDeadlineTimer(3000));
    EXPECT_EQ(r.status, R::Failed);
    EXPECT_TRUE(r.message.contains(QLatin1String("127.0.0.1:"))) << r.message.toStdString();
}

TEST(TcpTransport, ARefusedConnectionNamesHostPortAndCause) {
    // A port just freed by a server that listened on it: nothing listens there now.
    quint16 port = 0;
    {
        TcpServer s;
        QString error;
        ASSERT_TRUE(s.listen(QHostAddress::LocalHost, 0, &error));
        port = s.port();
    }
    TcpTransport t(QStringLiteral("127.0.0.1"), port);
    QString error;
    EXPECT_FALSE(t.open(&error));
    EXPECT_TRUE(error.contains(QStringLiteral("127.0.0.1:%1").arg(port))) << error.toStdString();
    EXPECT_TRUE(error.contains(QLatin1String("refused"), Qt::CaseInsensitive))
        << error.toStdString();
}

TEST(TcpTransport, AcceptEndsAtItsDeadlineWithNoClient) {
    TcpServer s;
    QString error;
    ASSERT_TRUE(s.listen(QHostAddress::LocalHost, 0, &error));
    EXPECT_EQ(s.accept(QDeadlineTimer(30)), nullptr);
}

// The listening side of a device server (tcp_listen_transport.h): one client at a time,
// bytes both ways; what is written with nobody connected goes nowhere; a client that leaves
// hands the line to the next.
TEST(TcpListenTransport, ServesOneClientAfterTheOther) {
    TcpListenTransport line(QHostAddress::LocalHost, 0);
    QString error;
    ASSERT_TRUE(line.open(&error)) << error.toStdString();
    const quint16 port = quint16(line.name().section(QLatin1Char(':'), 1).toUInt());
    ASSERT_NE(port, 0);
    EXPECT_TRUE(line.write("lost", QDeadlineTimer(1000), &error)); // nobody there
    EXPECT_EQ(line.read(QDeadlineTimer(30)).status, R::Timeout);
    for (const QByteArray &request : {QByteArray("first"), QByteArray("second")}) {
        TcpTransport client(QStringLiteral("127.0.0.1"), port);
        ASSERT_TRUE(client.open(&error)) << error.toStdString();
        ASSERT_TRUE(client.write(request, QDeadlineTimer(3000), &error));
        EXPECT_EQ(readAll(line, request.size()), request);
        EXPECT_TRUE(line.hasClient());
        ASSERT_TRUE(line.write("reply-" + request, QDeadlineTimer(3000), &error));
        EXPECT_EQ(readAll(client, 6 + request.size()), "reply-" + request); // not "lost"
        client.close();
        // The line notices the client left at its next read and waits for another.
        const QDeadlineTimer gone(3000);
        while (line.hasClient() && !gone.hasExpired())
            EXPECT_NE(line.read(QDeadlineTimer(20)).status, R::Failed);
        EXPECT_FALSE(line.hasClient());
    }
}

TEST(TcpListenTransport, CancelEndsTheWaitForAClient) {
    TcpListenTransport line(QHostAddress::LocalHost, 0);
    QString error;
    ASSERT_TRUE(line.open(&error)) << error.toStdString();
    line.cancel();
    QElapsedTimer t;
    t.start();
    EXPECT_EQ(line.read(QDeadlineTimer(5000)).status, R::Cancelled);
    EXPECT_LT(t.elapsed(), 2000);
}

} // namespace
} // namespace rung::comms
