#include "app/virtual_plc/virtual_plc.h"

#include "app/tr.h"
#include "simulator/session.h"

#include <QCoreApplication>

#include <condition_variable>
#include <mutex>
#include <unordered_map>

namespace rung::app {

namespace {

using comms::slave::ImageChange;
using comms::slave::OperatingMode;

// One wait of a slave worker for the owner thread: the commands it submitted, or a mode change.
struct Pending {
    std::mutex mutex;
    std::condition_variable done;
    int remaining = 0;
    bool failed = false;
    QString error;
    bool finished() const { return remaining == 0; }
};

} // namespace

// The session behind the slave's image interface. Slave workers call it; everything that
// touches the session runs on the session's owner thread (m_context's), and the worker waits
// for the answer up to its deadline.
class SessionImage final : public comms::slave::DeviceImage {
public:
    SessionImage(simulator::SimulatorSession *session, OperatingMode mode,
                 std::shared_ptr<const model::MemoryLayout> layout)
        : m_session(session)
        , m_mode(mode) {
        // What a reader sees before the session's first snapshot: the power-on image.
        auto empty = std::make_shared<model::Snapshot>();
        empty->layout = std::move(layout);
        const auto words = static_cast<std::size_t>(empty->layout->wordCount());
        empty->words.assign(words, 0);
        empty->forceMask.assign(words, 0);
        empty->forceValue.assign(words, 0);
        empty->coils.assign(static_cast<std::size_t>(empty->layout->elementStateCount()), false);
        m_empty = std::move(empty);
        // Runs on the owner thread: the session emits there.
        QObject::connect(session, &model::MonitorSource::commandFinished, session,
                         [this](model::MonitorSource::CommandId id, bool ok, const QString &e) {
                             finished(id, ok, e);
                         });
    }

    std::shared_ptr<const model::Snapshot> snapshot() const override {
        auto s = m_session->snapshot();
        return s ? s : m_empty;
    }

    ImageChange apply(const std::vector<model::DeviceCommand> &commands,
                      QDeadlineTimer deadline) override {
        auto pending = std::make_shared<Pending>();
        pending->remaining = int(commands.size());
        if (commands.empty())
            return {};
        post(pending, [this, pending, commands] {
            for (const model::DeviceCommand &c : commands)
                m_waiting.emplace(m_session->submit(c), pending);
        });
        return wait(*pending, deadline);
    }

    OperatingMode mode() const override { return m_mode.load(); }

    ImageChange setMode(OperatingMode mode, QDeadlineTimer deadline) override {
        auto pending = std::make_shared<Pending>();
        pending->remaining = 1;
        post(pending, [this, pending, mode] {
            if (mode == OperatingMode::Program)
                m_session->pause();
            else
                m_session->run();
            m_mode = mode;
            settle(*pending, true, {});
        });
        return wait(*pending, deadline);
    }

    // Ends every wait (the virtual PLC stops): the workers answer and can be joined.
    void shutdown() {
        std::lock_guard lock(m_mutex);
        m_shutdown = true;
        for (const auto &p : m_open) {
            std::lock_guard plock(p->mutex);
            p->failed = true;
            p->remaining = 0;
            p->error = VirtualPlcTr::tr("the virtual PLC is stopping");
            p->done.notify_all();
        }
    }

private:
    void post(const std::shared_ptr<Pending> &pending, std::function<void()> work) {
        {
            std::lock_guard lock(m_mutex);
            if (m_shutdown) {
                settle(*pending, false, VirtualPlcTr::tr("the virtual PLC is stopping"));
                return;
            }
            m_open.push_back(pending);
        }
        QMetaObject::invokeMethod(m_session, std::move(work), Qt::QueuedConnection);
    }

    static void settle(Pending &p, bool ok, const QString &error) {
        std::lock_guard lock(p.mutex);
        if (!ok && !p.failed) {
            p.failed = true;
            p.error = error;
        }
        if (p.remaining > 0)
            --p.remaining;
        p.done.notify_all();
    }

    // Owner thread.
    void finished(model::MonitorSource::CommandId id, bool ok, const QString &error) {
        const auto it = m_waiting.find(id);
        if (it == m_waiting.end())
            return;
        settle(*it->second, ok, error);
        m_waiting.erase(it);
    }

    ImageChange wait(Pending &p, QDeadlineTimer deadline) {
        std::unique_lock lock(p.mutex);
        const bool done = p.done.wait_until(lock, deadline.deadline<std::chrono::steady_clock>(),
                                            [&p] { return p.finished(); });
        ImageChange result;
        if (!done)
            result = {
                ImageChange::Status::TimedOut,
                VirtualPlcTr::tr("the simulation did not take the write within the time allowed")};
        else if (p.failed)
            result = {ImageChange::Status::Refused, p.error};
        lock.unlock();
        forget(&p);
        return result;
    }

    void forget(const Pending *p) {
        std::lock_guard lock(m_mutex);
        std::erase_if(m_open, [p](const auto &o) { return o.get() == p; });
    }

    simulator::SimulatorSession *m_session;
    std::atomic<OperatingMode> m_mode;
    std::shared_ptr<const model::Snapshot> m_empty;
    // Owner thread only: the commands a worker waits for.
    std::unordered_map<model::MonitorSource::CommandId, std::shared_ptr<Pending>> m_waiting;
    std::mutex m_mutex; // guards what follows
    std::vector<std::shared_ptr<Pending>> m_open;
    bool m_shutdown = false;
};

VirtualPlc::VirtualPlc(std::shared_ptr<const simulator::Program> program, Options options) {
    // The session's thread runs an event loop, which Qt allows only in an application.
    if (!QCoreApplication::instance())
        return;
    m_thread.setObjectName(QStringLiteral("virtual PLC"));
    m_thread.start();
    const OperatingMode mode = options.mode;
    const qint64 period = options.periodMs;
    std::shared_ptr<const model::MemoryLayout> layout = program->layout;
    const model::Target &target = layout->target();
    // The session is made, started and later destroyed on its own thread.
    auto *anchor = new QObject;
    anchor->moveToThread(&m_thread);
    QMetaObject::invokeMethod(
        anchor,
        [this, program, mode, period] {
            m_session = new simulator::SimulatorSession(program);
            if (period > 0)
                m_session->setPeriodMs(period);
            if (mode != OperatingMode::Program)
                m_session->run();
        },
        Qt::BlockingQueuedConnection);
    anchor->deleteLater();
    m_image = std::make_shared<SessionImage>(m_session, mode, layout);
    m_server =
        std::make_unique<comms::slave::SlaveServer>(target, std::move(options.slave), m_image);
}

VirtualPlc::~VirtualPlc() {
    stop();
    if (m_session) {
        simulator::SimulatorSession *session = m_session;
        m_session = nullptr;
        QMetaObject::invokeMethod(
            session, [session] { delete session; }, Qt::BlockingQueuedConnection);
    }
    if (m_thread.isRunning()) {
        m_thread.quit();
        m_thread.wait();
    }
}

bool VirtualPlc::ready(QString *error) const {
    if (m_server)
        return true;
    if (error)
        *error =
            VirtualPlcTr::tr("The virtual PLC needs a QCoreApplication for its simulation thread");
    return false;
}

bool VirtualPlc::serve(std::unique_ptr<comms::Transport> transport, QString *error) {
    return ready(error) && m_server->start(std::move(transport), error);
}

bool VirtualPlc::listen(const QHostAddress &host, quint16 port, QString *error) {
    return ready(error) && m_server->listen(host, port, error);
}

quint16 VirtualPlc::port() const {
    return m_server ? m_server->port() : 0;
}

void VirtualPlc::stop() {
    if (!m_server)
        return;
    m_image->shutdown();
    m_server->stop();
}

comms::slave::SlaveStatistics VirtualPlc::statistics() const {
    return m_server ? m_server->statistics() : comms::slave::SlaveStatistics{};
}

QString VirtualPlc::lastProblem() const {
    return m_server ? m_server->lastProblem() : QString();
}

std::shared_ptr<comms::slave::DeviceImage> VirtualPlc::image() const {
    return m_image;
}

} // namespace rung::app
