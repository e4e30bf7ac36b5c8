#pragma once

// A transport for unit tests of the layers above it (the drivers, the online session): no
// port, a script. Each request written takes the next step of the script (or asks the
// responder); its reply comes back in the chunks the step gives, one per read, so a reply
// may arrive split into many reads. A step may also stay silent (the read waits for its
// deadline, as a real one does), or vanish: the port fails mid-request, as an unplugged USB
// adapter does. Thread-safe: the driver's worker reads and writes while the test scripts.

#include "comms/transport/transport.h"

#include <QElapsedTimer>
#include <QList>

#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>

namespace rung::comms::test {

class FakeTransport final : public Transport {
public:
    struct Step {
        enum class Action { Reply, Silence, Vanish };
        QByteArray expect; // the request it answers; empty: any
        QList<QByteArray> chunks;
        Action action = Action::Reply;
    };
    // Whole request in, chunks of the reply out (empty: silence).
    using Responder = std::function<QList<QByteArray>(const QByteArray &request)>;

    explicit FakeTransport(QString name = QStringLiteral("fake0"))
        : m_name(std::move(name)) {}

    // --- the script (any thread) ---
    void reply(QByteArray expect, QList<QByteArray> chunks) {
        push({std::move(expect), std::move(chunks), Step::Action::Reply});
    }
    void reply(QByteArray expect, QByteArray whole) {
        push({std::move(expect), QList<QByteArray>{std::move(whole)}, Step::Action::Reply});
    }
    void silence(QByteArray expect = {}) { push({std::move(expect), {}, Step::Action::Silence}); }
    // The port fails after the request (and after the chunks given, if any).
    void vanish(QList<QByteArray> chunksFirst = {}) {
        push({{}, std::move(chunksFirst), Step::Action::Vanish});
    }
    // Answers whatever the script does not: a PLC in a test.
    void setResponder(Responder responder) {
        std::lock_guard lock(m_mutex);
        m_responder = std::move(responder);
    }
    // The next n open() calls fail (a port that is gone); -1: every one.
    void failOpens(int n, QString why = QStringLiteral("No such file or directory")) {
        std::lock_guard lock(m_mutex);
        m_failOpens = n;
        m_openError = std::move(why);
    }
    // The port goes away now: a waiting read fails, so does every call until open().
    void unplug() {
        std::lock_guard lock(m_mutex);
        m_gone = true;
        m_open = false;
        m_wake.notify_all();
    }

    // --- what happened (any thread) ---
    QList<QByteArray> written() const {
        std::lock_guard lock(m_mutex);
        return m_written;
    }
    // When each write came, in ms since the transport was made.
    QList<double> writeTimes() const {
        std::lock_guard lock(m_mutex);
        return m_writeTimes;
    }
    int writes() const {
        std::lock_guard lock(m_mutex);
        return int(m_written.size());
    }
    int opens() const {
        std::lock_guard lock(m_mutex);
        return m_opens;
    }
    bool scriptDone() const {
        std::lock_guard lock(m_mutex);
        return m_script.empty();
    }
    QString mismatch() const { // a request that was not the one the script expected
        std::lock_guard lock(m_mutex);
        return m_mismatch;
    }

    // --- Transport ---
    QString name() const override { return m_name; }
    bool open(QString *error) override {
        std::lock_guard lock(m_mutex);
        ++m_opens;
        if (m_failOpens != 0) {
            if (m_failOpens > 0)
                --m_failOpens;
            if (error)
                *error = QStringLiteral("Cannot open %1: %2").arg(m_name, m_openError);
            return false;
        }
        m_open = true;
        m_gone = false;
        return true;
    }
    void close() override {
        std::lock_guard lock(m_mutex);
        m_open = false;
        m_pending.clear();
        m_releaseAt.clear();
    }
    bool isOpen() const override {
        std::lock_guard lock(m_mutex);
        return m_open;
    }
    bool write(QByteArrayView bytes, QDeadlineTimer, QString *error) override {
        std::lock_guard lock(m_mutex);
        if (!m_open) {
            if (error)
                *error = QStringLiteral("%1 is not open").arg(m_name);
            return false;
        }
        m_written << bytes.toByteArray();
        m_writeTimes << double(m_clock.nsecsElapsed()) / 1e6;
        // A lone CR is the Host Link delimiter that asks for a reply's next part: the part is
        // already queued.
        if (bytes == QByteArrayView("\r", 1) && m_delimiterParts)
            return true;
        Step step;
        if (!m_script.empty()) {
            step = m_script.front();
            m_script.pop_front();
            if (!step.expect.isEmpty() && step.expect != bytes && m_mismatch.isEmpty())
                m_mismatch = QStringLiteral("expected %1, got %2")
                                 .arg(QString::fromLatin1(step.expect.toHex(' ')),
                                      QString::fromLatin1(bytes.toByteArray().toHex(' ')));
        } else if (m_responder) {
            step.chunks = m_responder(bytes.toByteArray());
            if (step.chunks.isEmpty())
                step.action = Step::Action::Silence;
        } else {
            step.action = Step::Action::Silence;
        }
        double at = double(m_clock.nsecsElapsed()) / 1e6;
        for (const QByteArray &c : step.chunks) {
            at += m_chunkDelayMs;
            m_pending.push_back(c);
            m_releaseAt.push_back(at);
        }
        m_vanishAfter = step.action == Step::Action::Vanish;
        m_wake.notify_all();
        return true;
    }
    ReadResult read(QDeadlineTimer deadline) override {
        std::unique_lock lock(m_mutex);
        for (;;) {
            if (m_gone || !m_open)
                return {ReadResult::Status::Failed,
                        {},
                        QStringLiteral("%1 is gone (unplugged)").arg(m_name)};
            const double now = double(m_clock.nsecsElapsed()) / 1e6;
            if (!m_pending.empty() && m_releaseAt.front() <= now) {
                ReadResult r{ReadResult::Status::Data, m_pending.front(), {}};
                m_pending.pop_front();
                m_releaseAt.pop_front();
                return r;
            }
            if (m_vanishAfter && m_pending.empty()) {
                m_vanishAfter = false;
                m_gone = true;
                m_open = false;
                continue;
            }
            if (m_cancel) {
                m_cancel = false;
                return {ReadResult::Status::Cancelled, {}, {}};
            }
            if (deadline.hasExpired())
                return {ReadResult::Status::Timeout, {}, {}};
            m_wake.wait_for(
                lock, std::chrono::milliseconds(std::max<qint64>(1, deadline.remainingTime())));
        }
    }
    void discardInput() override {
        std::lock_guard lock(m_mutex);
        m_pending.clear();
        m_releaseAt.clear();
    }
    void cancel() override {
        std::lock_guard lock(m_mutex);
        m_cancel = true;
        m_wake.notify_all();
    }
    // Each chunk of a reply comes this long after the one before (a slow line); 0: at once.
    void setChunkDelayMs(int ms) {
        std::lock_guard lock(m_mutex);
        m_chunkDelayMs = ms;
    }
    // Host Link replies in parts: the chunks after a part that ends in CR without "*" are
    // released by the host's delimiter. Tests of split replies queue them all at once.
    void setDelimiterParts(bool on) {
        std::lock_guard lock(m_mutex);
        m_delimiterParts = on;
    }

private:
    void push(Step step) {
        std::lock_guard lock(m_mutex);
        m_script.push_back(std::move(step));
    }

    QString m_name;
    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    std::deque<Step> m_script;
    Responder m_responder;
    std::deque<QByteArray> m_pending;
    std::deque<double> m_releaseAt; // ms on m_clock when each pending chunk may be read
    int m_chunkDelayMs = 0;
    QList<QByteArray> m_written;
    QList<double> m_writeTimes;
    QElapsedTimer m_clock = [] {
        QElapsedTimer t;
        t.start();
        return t;
    }();
    QString m_mismatch;
    QString m_openError;
    int m_failOpens = 0;
    int m_opens = 0;
    bool m_open = false;
    bool m_gone = false;
    bool m_vanishAfter = false;
    bool m_cancel = false;
    bool m_delimiterParts = true;
};

} // namespace rung::comms::test
