#pragma once

// A peer on a real pseudo-terminal: a thread holds the pty's master side (PtyTransport::
// createPair) and answers each request with a responder (a FakeModbusPlc, a FakeHostLinkPlc).
// A request is what arrived before the line went quiet for a moment, as a Modbus RTU slave
// frames by silence. For tests of whole programs (the command-line tool, the session over a
// real pty) and the comms benchmark.

#include "comms/transport/pty_transport.h"
#include "tests/comms/fake_transport.h"

#include <atomic>
#include <thread>

namespace rung::comms::test {

class PtyPeer {
public:
    // eager: answer as soon as the responder makes an answer of what arrived (it returns
    // nothing for a request not yet whole), instead of waiting for the line to go quiet; for
    // the benchmark, whose times would otherwise count the wait.
    explicit PtyPeer(FakeTransport::Responder responder, bool eager = false)
        : m_responder(std::move(responder))
        , m_eager(eager) {
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
        while (!m_stop) {
            // Quiet for 3 ms after bytes: the request is whole.
            const ReadResult r = m_master->read(QDeadlineTimer(request.isEmpty() ? 200 : 3));
            if (r.status == ReadResult::Status::Data) {
                request += r.bytes;
                // A Host Link delimiter (a lone CR asking for the next part, which the
                // responder sent already) is no request.
                while (request.startsWith('\r'))
                    request.remove(0, 1);
                if (m_eager && !request.isEmpty()) {
                    const QList<QByteArray> reply = m_responder(request);
                    if (!reply.isEmpty()) {
                        QString error;
                        for (const QByteArray &chunk : reply)
                            m_master->write(chunk, QDeadlineTimer(1000), &error);
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
    std::unique_ptr<PtyTransport> m_master;
    QString m_error;
    std::atomic<bool> m_stop{false};
    std::atomic<int> m_answered{0};
    std::thread m_thread;
};

} // namespace rung::comms::test
