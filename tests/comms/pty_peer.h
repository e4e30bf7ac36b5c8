#pragma once

// A peer on a real pseudo-terminal: a thread holds the pty's master side (PtyTransport::
// createPair) and answers each request with a responder (a FakeModbusPlc, a FakeHostLinkPlc).
// A request is what arrived before the line went quiet for a moment, as a Modbus RTU slave
// frames by silence. For tests of whole programs (the command-line tool, the session over a
// real pty) and the comms benchmark.

#include "comms/transport/pty_transport.h"
#include "tests/comms/fake_transport.h"

#include <atomic>
#include <chrono>
#include <thread>

namespace rung::comms::test {

// A pty has no baud rate. With a wire speed, an eager PtyPeer answers when a PLC on a serial
// line at that speed could have at the earliest: the request's characters, the silence the
// protocol asks before an answer (Modbus RTU: 3.5 characters), then the answer's characters,
// counted from the request's first byte; the PLC's own turnaround is taken as nothing.
struct PtyWire {
    int bitsPerSecond = 0; // 0: no pacing
    int bitsPerCharacter = 10;
    double silenceCharacters = 0;
    double characterUs() const { return 1e6 * bitsPerCharacter / bitsPerSecond; }
};

class PtyPeer {
public:
    // eager: answer as soon as the responder makes an answer of what arrived (it returns
    // nothing for a request not yet whole), instead of waiting for the line to go quiet; for
    // the benchmark, whose times would otherwise count the wait.
    explicit PtyPeer(FakeTransport::Responder responder, bool eager = false, PtyWire wire = {})
        : m_responder(std::move(responder))
        , m_eager(eager)
        , m_wire(wire) {
        QString error;
        m_master = PtyTransport::createPair(&error);
        if (!m_master) {
            m_error = error;
            return;
        }
        m_thread = std::thread([this] { loop(); });
    }
    ~PtyPeer() {
        m_stop = true;
        if (m_master)
            m_master->cancel();
        if (m_thread.joinable())
            m_thread.join();
    }
    bool ok() const { return m_master != nullptr; }
    QString error() const { return m_error; }
    QString path() const { return m_master ? m_master->peerPath() : QString(); }
    int answered() const { return m_answered; }

private:
    void loop() {
        QByteArray request;
        std::chrono::steady_clock::time_point firstByte;
        while (!m_stop) {
            // Quiet for 3 ms after bytes: the request is whole.
            const ReadResult r = m_master->read(QDeadlineTimer(request.isEmpty() ? 200 : 3));
            if (r.status == ReadResult::Status::Data) {
                if (request.isEmpty())
                    firstByte = std::chrono::steady_clock::now();
                request += r.bytes;
                // A Host Link delimiter (a lone CR asking for the next part, which the
                // responder sent already) is no request.
                while (request.startsWith('\r'))
                    request.remove(0, 1);
                if (m_eager && !request.isEmpty()) {
                    const QList<QByteArray> reply = m_responder(request);
                    if (!reply.isEmpty()) {
                        QString error;
                        double dueUs =
                            m_wire.bitsPerSecond > 0
                                ? (request.size() + m_wire.silenceCharacters) * m_wire.characterUs()
                                : 0;
                        for (const QByteArray &chunk : reply) {
                            if (m_wire.bitsPerSecond > 0) {
                                dueUs += chunk.size() * m_wire.characterUs();
                                std::this_thread::sleep_until(
                                    firstByte + std::chrono::microseconds(qint64(dueUs)));
                            }
                            m_master->write(chunk, QDeadlineTimer(1000), &error);
                        }
                        ++m_answered;
                        request.clear();
                    }
                }
                continue;
            }
            if (r.status != ReadResult::Status::Timeout)
                continue; // cancelled: m_stop is set
            if (request.isEmpty())
                continue;
            QString error;
            for (const QByteArray &chunk : m_responder(request))
                m_master->write(chunk, QDeadlineTimer(1000), &error);
            ++m_answered;
            request.clear();
        }
    }

    FakeTransport::Responder m_responder;
    bool m_eager = false;
    PtyWire m_wire;
    std::unique_ptr<PtyTransport> m_master;
    QString m_error;
    std::atomic<bool> m_stop{false};
    std::atomic<int> m_answered{0};
    std::thread m_thread;
};

} // namespace rung::comms::test
