#include "comms/driver/link.h"

#include <QCoreApplication>
#include <QElapsedTimer>

#include <chrono>
#include <thread>

namespace rung::comms {

namespace {

using R = ReadResult::Status;

QString withCause(const QString &what, const QString &cause) {
    return QCoreApplication::translate("rung::comms::Driver", "%1: %2").arg(what, cause);
}

} // namespace

Link::Link(std::unique_ptr<Transport> transport, LinkSettings settings)
    : m_transport(std::move(transport))
    , m_settings(settings) {}

Link::~Link() = default;

bool Link::open(QString *error) {
    return m_transport->open(error);
}

void Link::close() {
    m_transport->close();
}

void Link::cancel() {
    m_transport->cancel();
}

bool Link::send(QByteArrayView bytes, QString *error) {
    if (m_settings.gapUs > 0 && m_lastTraffic.isValid()) {
        const qint64 quietUs = m_lastTraffic.nsecsElapsed() / 1000;
        if (quietUs < m_settings.gapUs)
            std::this_thread::sleep_for(std::chrono::microseconds(m_settings.gapUs - quietUs));
    }
    m_tap->append(TrafficRecord::Direction::Sent, bytes);
    {
        std::lock_guard lock(m_statsMutex);
        m_stats.bytesSent += quint64(bytes.size());
    }
    const bool ok =
        m_transport->write(bytes, QDeadlineTimer(std::max(m_settings.timeoutMs, 100)), error);
    m_lastTraffic.start();
    return ok;
}

void Link::drain() {
    // The rest of a broken reply may still be on its way: wait for the line to go quiet.
    const QDeadlineTimer limit(std::max(m_settings.timeoutMs, m_settings.drainMs));
    while (!limit.hasExpired()) {
        const ReadResult r = m_transport->read(QDeadlineTimer(m_settings.drainMs));
        if (r.status != R::Data)
            break;
        m_tap->append(TrafficRecord::Direction::Received, r.bytes);
        std::lock_guard lock(m_statsMutex);
        m_stats.bytesReceived += quint64(r.bytes.size());
    }
    m_transport->discardInput();
}

DriverError Link::exchange(QByteArrayView request, ReplySink &sink, const QString &what,
                           bool expectReply) {
    using K = DriverError::Kind;
    if (!m_transport->isOpen())
        return {K::LinkDown, 0,
                withCause(what, QCoreApplication::translate("rung::comms::Driver", "%1 is not open")
                                    .arg(m_transport->name()))};
    m_transport->discardInput();
    ProtocolError last;
    for (int attempt = 0; attempt <= std::max(0, m_settings.retries); ++attempt) {
        {
            std::lock_guard lock(m_statsMutex);
            ++m_stats.requests;
            if (attempt > 0)
                ++m_stats.retries;
        }
        sink.restart();
        QString error;
        QElapsedTimer clock;
        clock.start();
        if (!send(request, &error)) {
            std::lock_guard lock(m_statsMutex);
            ++m_stats.errors;
            return {K::LinkDown, 0, withCause(what, error)};
        }
        if (!expectReply)
            return {};
        // The request takes its wire time to leave a serial port after write() returns.
        const qint64 sendingMs =
            (qint64(request.size()) * m_settings.characterUs + 999) / 1000;
        QDeadlineTimer deadline(m_settings.timeoutMs + sendingMs);
        FrameStatus status = FrameStatus::NeedMore;
        while (status == FrameStatus::NeedMore) {
            ReadResult r = m_transport->read(deadline);
            if (r.status == R::Data) {
                m_lastTraffic.start();
                if (m_settings.characterUs > 0)
                    deadline = QDeadlineTimer(m_settings.timeoutMs); // the next byte's wait
                m_tap->append(TrafficRecord::Direction::Received, r.bytes);
                {
                    std::lock_guard lock(m_statsMutex);
                    m_stats.bytesReceived += quint64(r.bytes.size());
                }
                status = sink.feed(r.bytes);
                if (status == FrameStatus::NeedMore && sink.takeDelimiterRequest() &&
                    !send(QByteArrayView("\r", 1), &error)) {
                    std::lock_guard lock(m_statsMutex);
                    ++m_stats.errors;
                    return {K::LinkDown, 0, withCause(what, error)};
                }
                continue;
            }
            if (r.status == R::Cancelled)
                return {K::Cancelled, 0,
                        withCause(what,
                                  QCoreApplication::translate("rung::comms::Driver", "cancelled"))};
            if (r.status == R::Failed) {
                std::lock_guard lock(m_statsMutex);
                ++m_stats.errors;
                return {K::LinkDown, 0, withCause(what, r.message)};
            }
            break; // the deadline passed
        }
        if (status == FrameStatus::Complete) {
            const double ms = double(clock.nsecsElapsed()) / 1e6;
            std::lock_guard lock(m_statsMutex);
            ++m_stats.replies;
            ++m_goodExchanges;
            m_stats.lastRoundTripMs = ms;
            m_stats.minRoundTripMs =
                m_goodExchanges == 1 ? ms : std::min(m_stats.minRoundTripMs, ms);
            m_stats.maxRoundTripMs = std::max(m_stats.maxRoundTripMs, ms);
            m_stats.meanRoundTripMs += (ms - m_stats.meanRoundTripMs) / double(m_goodExchanges);
            return {};
        }
        last = status == FrameStatus::Failed ? sink.error()
                                             : sink.deadlinePassed(m_settings.timeoutMs);
        if (last.kind == ProtocolError::Kind::Truncated) {
            std::lock_guard lock(m_statsMutex);
            ++m_stats.timeouts;
        }
        if (!last.retryable())
            break;
        if (status == FrameStatus::Failed)
            drain();
    }
    std::lock_guard lock(m_statsMutex);
    ++m_stats.errors;
    switch (last.kind) {
    case ProtocolError::Kind::DeviceError:
        ++m_stats.refusals;
        return {K::Refused, last.code, withCause(what, last.message)};
    case ProtocolError::Kind::Truncated:
        return {K::NoReply, 0,
                withCause(what, m_settings.retries > 0
                                    ? QCoreApplication::translate("rung::comms::Driver",
                                                                  "%1 (%2 attempts)")
                                          .arg(last.message)
                                          .arg(m_settings.retries + 1)
                                    : last.message)};
    case ProtocolError::Kind::Garbage:
    case ProtocolError::Kind::BadChecksum:
        return {K::Garbled, 0,
                withCause(what, m_settings.retries > 0
                                    ? QCoreApplication::translate("rung::comms::Driver",
                                                                  "%1 (%2 attempts)")
                                          .arg(last.message)
                                          .arg(m_settings.retries + 1)
                                    : last.message)};
    default:
        return {K::WrongPeer, 0, withCause(what, last.message)};
    }
}

LinkStatistics Link::statistics() const {
    std::lock_guard lock(m_statsMutex);
    return m_stats;
}

void Link::countRefresh(double ms, int frames, int bytes) {
    std::lock_guard lock(m_statsMutex);
    ++m_stats.refreshes;
    m_stats.lastRefreshMs = ms;
    m_stats.framesPerRefresh = frames;
    m_stats.bytesPerRefresh = bytes;
}

void Link::countReconnect() {
    std::lock_guard lock(m_statsMutex);
    ++m_stats.reconnects;
}

} // namespace rung::comms
