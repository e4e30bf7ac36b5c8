#include "comms/transport/pty_transport.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

namespace rung::comms {

namespace {

QString cause() {
    return QString::fromLocal8Bit(std::strerror(errno));
}

bool makeRaw(int fd) {
    termios t{};
    if (::tcgetattr(fd, &t) != 0)
        return false;
    ::cfmakeraw(&t);
    return ::tcsetattr(fd, TCSANOW, &t) == 0;
}

} // namespace

PtyTransport::PtyTransport(QString path)
    : m_path(std::move(path)) {}

PtyTransport::~PtyTransport() {
    close();
}

std::unique_ptr<PtyTransport> PtyTransport::createPair(QString *error) {
    // Every step can fail (no pseudo-terminal left, no file descriptor left): each failure is
    // reported, and nothing made so far is left open.
    const auto refuse = [error](const QString &cause) {
        if (error)
            *error = QCoreApplication::translate("rung::comms::Protocol",
                                                 "Cannot create a pseudo-terminal: %1")
                         .arg(cause);
        return nullptr;
    };
    const int master = ::posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC | O_NONBLOCK);
    if (master < 0)
        return refuse(cause());
    auto t = std::make_unique<PtyTransport>(QString());
    t->m_fd = master; // closed by t from here on
    t->m_pair = true;
    char name[128] = {};
    if (::grantpt(master) != 0 || ::unlockpt(master) != 0)
        return refuse(cause());
    if (const int failed = ::ptsname_r(master, name, sizeof name); failed != 0)
        return refuse(
            QStringLiteral("ptsname: %1").arg(QString::fromLocal8Bit(std::strerror(failed))));
    if (!t->m_waiter.ok())
        return refuse(t->m_waiter.error());
    t->m_peerPath = QString::fromLocal8Bit(name);
    t->m_path = t->m_peerPath;
    t->m_keepPeer = ::open(name, O_RDWR | O_NOCTTY | O_CLOEXEC | O_NONBLOCK);
    if (t->m_keepPeer < 0)
        return refuse(QStringLiteral("%1: %2").arg(t->m_peerPath, cause()));
    if (!makeRaw(t->m_keepPeer)) // no echo, no line editing: bytes pass as they are
        return refuse(QStringLiteral("%1: %2").arg(t->m_peerPath, cause()));
    return t;
}

bool PtyTransport::open(QString *error) {
    if (m_fd >= 0)
        return true;
    if (m_pair) {
        // The pseudo-terminal went with close(): its path may already name another one, and
        // opening it would make this master a peer. A peer has to be told a new path.
        if (error)
            *error = QCoreApplication::translate(
                         "rung::comms::Protocol",
                         "Cannot open %1 again: the pseudo-terminal this program made ended "
                         "when it was closed; make a new one and give its path to the peer")
                         .arg(m_peerPath);
        return false;
    }
    if (!m_waiter.ok()) {
        if (error)
            *error = QCoreApplication::translate("rung::comms::Protocol", "Cannot open %1: %2")
                         .arg(m_path, m_waiter.error());
        return false;
    }
    m_fd = ::open(m_path.toLocal8Bit().constData(), O_RDWR | O_NOCTTY | O_CLOEXEC | O_NONBLOCK);
    if (m_fd < 0) {
        if (error)
            *error = QCoreApplication::translate("rung::comms::Protocol", "Cannot open %1: %2")
                         .arg(m_path, cause());
        return false;
    }
    if (!::isatty(m_fd) || !makeRaw(m_fd)) {
        if (error)
            *error = QCoreApplication::translate("rung::comms::Protocol",
                                                 "Cannot open %1: it is not a terminal")
                         .arg(m_path);
        close();
        return false;
    }
    return true;
}

void PtyTransport::close() {
    for (int *fd : {&m_fd, &m_keepPeer})
        if (*fd >= 0) {
            ::close(*fd);
            *fd = -1;
        }
}

bool PtyTransport::write(QByteArrayView bytes, QDeadlineTimer deadline, QString *error) {
    qsizetype done = 0;
    while (done < bytes.size()) {
        if (m_fd < 0) {
            if (error)
                *error = QCoreApplication::translate("rung::comms::Protocol", "%1 is not open")
                             .arg(m_path);
            return false;
        }
        const auto n = ::write(m_fd, bytes.data() + done, size_t(bytes.size() - done));
        if (n > 0) {
            done += n;
            continue;
        }
        if (n < 0 && errno != EAGAIN && errno != EINTR) {
            if (error)
                *error =
                    QCoreApplication::translate("rung::comms::Protocol", "Writing to %1 failed: %2")
                        .arg(m_path, cause());
            return false;
        }
        if (m_waiter.wait(m_fd, deadline, true) != detail::FdWaiter::Result::Ready) {
            if (error)
                *error = QCoreApplication::translate("rung::comms::Protocol",
                                                     "Writing to %1 did not finish in time")
                             .arg(m_path);
            return false;
        }
    }
    return true;
}

ReadResult PtyTransport::read(QDeadlineTimer deadline) {
    using R = ReadResult::Status;
    while (true) {
        if (m_fd < 0)
            return {
                R::Failed,
                {},
                QCoreApplication::translate("rung::comms::Protocol", "%1 is not open").arg(m_path)};
        char buffer[512];
        const auto n = ::read(m_fd, buffer, sizeof buffer);
        if (n > 0)
            return {R::Data, QByteArray(buffer, n), {}};
        if (n == 0 || (errno != EAGAIN && errno != EINTR))
            return {R::Failed,
                    {},
                    QCoreApplication::translate("rung::comms::Protocol",
                                                "%1 was closed by the other side: %2")
                        .arg(m_path, n == 0 ? QStringLiteral("EOF") : cause())};
        switch (m_waiter.wait(m_fd, deadline)) {
        case detail::FdWaiter::Result::Ready:
            continue;
        case detail::FdWaiter::Result::Timeout:
            return {R::Timeout, {}, {}};
        case detail::FdWaiter::Result::Cancelled:
            return {R::Cancelled, {}, {}};
        case detail::FdWaiter::Result::Hangup:
        case detail::FdWaiter::Result::Error:
            return {R::Failed,
                    {},
                    QCoreApplication::translate("rung::comms::Protocol",
                                                "%1 was closed by the other side")
                        .arg(m_path)};
        }
    }
}

void PtyTransport::discardInput() {
    if (m_fd >= 0)
        ::tcflush(m_fd, TCIFLUSH);
}

} // namespace rung::comms
