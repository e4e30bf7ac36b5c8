#include "comms/slave/slave_server.h"

#include "comms/slave/responder.h"

#include <QCoreApplication>

#include <chrono>

namespace rung::comms::slave {

namespace {

// How long a worker waits for bytes before it looks at the quit flag again (stop() also
// cancels the wait; this bounds a wait that began just after the cancel).
constexpr int kPollMs = 200;
constexpr int kWriteMs = 2000;
constexpr int kSplitPauseMs = 3; // Fault::Split: time between the bytes of an answer

struct FaultName {
    Fault fault;
    const char *name;
};
constexpr FaultName kFaults[] = {
    {Fault::None, "none"},       {Fault::BadChecksum, "bad-checksum"},
    {Fault::Silent, "silent"},   {Fault::WrongStation, "wrong-station"},
    {Fault::Garbage, "garbage"}, {Fault::Truncated, "truncated"},
    {Fault::Split, "split"},
};

void add(SlaveStatistics &to, const SlaveStatistics &from) {
    to.answered += from.answered;
    to.refused += from.refused;
    to.ignored += from.ignored;
    to.dropped += from.dropped;
    to.writes += from.writes;
}

} // namespace

std::optional<Fault> faultFromName(QStringView name) {
    for (const FaultName &f : kFaults)
        if (name == QLatin1String(f.name))
            return f.fault;
    return std::nullopt;
}

QStringList faultNames() {
    QStringList names;
    for (const FaultName &f : kFaults)
        names << QLatin1String(f.name);
    return names;
}

struct SlaveServer::Stream {
    std::unique_ptr<Transport> transport; // under m_mutex once the worker runs
    std::unique_ptr<Responder> responder;
    std::thread thread;
    SlaveStatistics statistics; // the responder's, copied under m_mutex
    QString problem;            // the responder's last problem, as last recorded
    std::atomic<bool> finished{false};
};

SlaveServer::SlaveServer(const model::Target &target, SlaveOptions options,
                         std::shared_ptr<DeviceImage> image)
    : m_target(target)
    , m_map(model::findProtocolMap(target, options.protocol))
    , m_options(std::move(options))
    , m_image(std::move(image)) {}

SlaveServer::~SlaveServer() {
    stop();
}

std::unique_ptr<Responder> SlaveServer::makeResponder() const {
    const int station = m_options.station;
    std::unique_ptr<Responder> r =
        slave::makeResponder(m_target, *m_map, station, m_image, m_options.framing, m_options.line,
                             m_options.writeTimeoutMs);
    if (m_options.fault == Fault::WrongStation)
        r->setReplyStation(station + 1);
    return r;
}

bool SlaveServer::start(std::unique_ptr<Transport> transport, QString *error) {
    if (!m_map) {
        if (error)
            *error = QCoreApplication::translate("rung::comms::Protocol",
                                                 "%1 does not speak this protocol")
                         .arg(m_target.displayName);
        return false;
    }
    auto stream = std::make_unique<Stream>();
    stream->transport = std::move(transport);
    stream->responder = makeResponder();
    Stream *raw = stream.get();
    std::promise<QString> opened;
    std::future<QString> result = opened.get_future();
    {
        std::lock_guard lock(m_mutex);
        m_streams.push_back(std::move(stream));
        // The stream is opened on its worker: a transport is used by one thread only.
        raw->thread = std::thread([this, raw, &opened] { run(*raw, &opened); });
    }
    const QString failure = result.get();
    if (failure.isEmpty())
        return true;
    if (error)
        *error = failure;
    reap();
    return false;
}

bool SlaveServer::listen(const QHostAddress &host, quint16 port, QString *error) {
    if (!m_map || m_acceptor.joinable()) {
        if (error)
            *error = !m_map ? QCoreApplication::translate("rung::comms::Protocol",
                                                          "%1 does not speak this protocol")
                                  .arg(m_target.displayName)
                            : QCoreApplication::translate("rung::comms::Protocol",
                                                          "The slave listens already");
        return false;
    }
    std::promise<QString> listening;
    std::future<QString> result = listening.get_future();
    m_acceptor =
        std::thread([this, host, port, &listening] { acceptLoop(host, port, &listening); });
    const QString failure = result.get();
    if (failure.isEmpty())
        return true;
    m_acceptor.join();
    if (error)
        *error = failure;
    return false;
}

void SlaveServer::stop() {
    m_quit = true;
    {
        std::lock_guard lock(m_mutex);
        if (m_server)
            m_server->cancel();
        for (const auto &s : m_streams)
            if (s->transport)
                s->transport->cancel();
    }
    if (m_acceptor.joinable())
        m_acceptor.join();
    std::list<std::unique_ptr<Stream>> streams;
    {
        std::lock_guard lock(m_mutex);
        streams.swap(m_streams);
    }
    for (const auto &s : streams)
        if (s->thread.joinable())
            s->thread.join();
    std::lock_guard lock(m_mutex);
    for (const auto &s : streams)
        add(m_finished, s->statistics);
}

void SlaveServer::reap() {
    std::list<std::unique_ptr<Stream>> ended;
    {
        std::lock_guard lock(m_mutex);
        for (auto it = m_streams.begin(); it != m_streams.end();)
            if ((*it)->finished.load()) {
                ended.push_back(std::move(*it));
                it = m_streams.erase(it);
            } else {
                ++it;
            }
    }
    for (const auto &s : ended)
        if (s->thread.joinable())
            s->thread.join();
    std::lock_guard lock(m_mutex);
    for (const auto &s : ended)
        add(m_finished, s->statistics);
}

SlaveStatistics SlaveServer::statistics() const {
    std::lock_guard lock(m_mutex);
    SlaveStatistics sum = m_finished;
    for (const auto &s : m_streams)
        add(sum, s->statistics);
    return sum;
}

QString SlaveServer::lastProblem() const {
    std::lock_guard lock(m_mutex);
    return m_lastProblem;
}

void SlaveServer::record(Stream &stream) {
    const Responder &r = *stream.responder;
    std::lock_guard lock(m_mutex);
    stream.statistics = r.statistics();
    if (r.lastProblem() != stream.problem) {
        stream.problem = r.lastProblem();
        m_lastProblem = stream.problem;
    }
}

void SlaveServer::run(Stream &stream, std::promise<QString> *opened) {
    QString error;
    if (m_quit)
        error = QCoreApplication::translate("rung::comms::Protocol", "The slave has been stopped");
    const bool ok = !m_quit && stream.transport->open(&error);
    if (opened)
        opened->set_value(ok ? QString() : error);
    if (ok) {
        serve(stream);
    } else if (!opened) {
        std::lock_guard lock(m_mutex);
        m_lastProblem = error;
    }
    // The transport ends on the thread that used it (a QTcpSocket belongs to its thread).
    std::unique_ptr<Transport> transport;
    {
        std::lock_guard lock(m_mutex);
        transport = std::move(stream.transport);
    }
    transport.reset();
    stream.finished = true;
}

void SlaveServer::serve(Stream &stream) {
    Transport &t = *stream.transport;
    Responder &r = *stream.responder;
    const int silenceUs = r.silenceMicroseconds();
    // A pty or a USB adapter may deliver a frame in pieces a little apart: the silence is
    // never shorter than 2 ms, the poll granularity of the wait.
    const int silenceMs = silenceUs > 0 ? std::max(2, (silenceUs + 999) / 1000) : 0;
    bool unsettled = false; // bytes came since the line was last quiet
    while (!m_quit) {
        const ReadResult got =
            t.read(QDeadlineTimer(unsettled && silenceMs > 0 ? silenceMs : kPollMs));
        switch (got.status) {
        case ReadResult::Status::Data: {
            // Counted before it is sent: a master that has the answer finds it counted.
            const QByteArrayList answers = r.feed(got.bytes);
            record(stream);
            send(stream, answers);
            unsettled = true;
            break;
        }
        case ReadResult::Status::Timeout:
            if (unsettled && silenceMs > 0) {
                const QByteArrayList answers = r.silence();
                record(stream);
                send(stream, answers);
            }
            unsettled = false;
            break;
        case ReadResult::Status::Cancelled:
            break;
        case ReadResult::Status::Failed:
            record(stream);
            {
                std::lock_guard lock(m_mutex);
                m_lastProblem = got.message;
            }
            if (!m_quit && m_options.onFailure)
                m_options.onFailure(got.message);
            return;
        }
    }
}

void SlaveServer::send(Stream &stream, const QByteArrayList &frames) {
    Transport &t = *stream.transport;
    for (QByteArray frame : frames) {
        QString error;
        const bool delimiter = frame.size() == 1 && frame.front() == '\r'; // Host Link's CR
        if (!delimiter) {
            switch (m_options.fault) {
            case Fault::Silent:
                continue;
            case Fault::BadChecksum:
                frame = stream.responder->breakChecksum(frame);
                break;
            case Fault::Garbage:
                // No protocol's start byte (STX, ACK, "@"), no unit a master asks for.
                frame = QByteArray(std::max<qsizetype>(frame.size(), 4), char(0xFE));
                break;
            case Fault::Truncated:
                frame.truncate(frame.size() / 2);
                break;
            case Fault::Split:
                for (const char byte : frame) {
                    if (!t.write(QByteArrayView(&byte, 1), QDeadlineTimer(kWriteMs), &error))
                        break;
                    std::this_thread::sleep_for(std::chrono::milliseconds(kSplitPauseMs));
                }
                continue;
            case Fault::None:
            case Fault::WrongStation:
                break;
            }
        }
        if (!t.write(frame, QDeadlineTimer(kWriteMs), &error)) {
            std::lock_guard lock(m_mutex);
            m_lastProblem = error;
        }
    }
}

void SlaveServer::acceptLoop(const QHostAddress &host, quint16 port,
                             std::promise<QString> *listening) {
    TcpServer server;
    QString error;
    if (!server.listen(host, port, &error)) {
        listening->set_value(error);
        return;
    }
    m_port = server.port();
    {
        std::lock_guard lock(m_mutex);
        m_server = &server;
    }
    listening->set_value(QString());
    while (!m_quit) {
        const qintptr descriptor = server.acceptDescriptor(QDeadlineTimer(kPollMs));
        reap();
        if (descriptor < 0)
            continue;
        auto stream = std::make_unique<Stream>();
        stream->transport = TcpTransport::fromDescriptor(descriptor);
        if (m_clients.load() >= m_options.maxClients) {
            std::lock_guard lock(m_mutex);
            m_lastProblem = QCoreApplication::translate(
                                "rung::comms::Protocol",
                                "A TCP client was refused: %1 clients are served already")
                                .arg(m_options.maxClients);
            continue; // the transport closes the connection
        }
        stream->responder = makeResponder();
        Stream *raw = stream.get();
        ++m_clients;
        std::lock_guard lock(m_mutex);
        m_streams.push_back(std::move(stream));
        raw->thread = std::thread([this, raw] {
            run(*raw, nullptr);
            --m_clients;
        });
    }
    std::lock_guard lock(m_mutex);
    m_server = nullptr;
}

} // namespace rung::comms::slave
