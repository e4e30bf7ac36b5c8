#include "comms/transport/fd_waiter.h"

#include <QCoreApplication>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

namespace rung::comms::detail {

FdWaiter::FdWaiter() {
    if (::pipe2(m_pipe, O_CLOEXEC | O_NONBLOCK) != 0) {
        m_error = QCoreApplication::translate("rung::comms::Protocol",
                                              "no wake-up pipe for cancelling a read: %1")
                      .arg(QString::fromLocal8Bit(std::strerror(errno)));
        m_pipe[0] = m_pipe[1] = -1;
    }
}

FdWaiter::~FdWaiter() {
    for (int fd : m_pipe)
        if (fd >= 0)
            ::close(fd);
}

void FdWaiter::wake() {
    if (m_pipe[1] >= 0) {
        const char one = 1;
        [[maybe_unused]] const auto written = ::write(m_pipe[1], &one, 1);
    }
}

FdWaiter::Result FdWaiter::wait(int fd, QDeadlineTimer deadline, bool forWrite) {
    while (true) {
        pollfd fds[2] = {{fd, short(forWrite ? POLLOUT : POLLIN), 0}, {m_pipe[0], POLLIN, 0}};
        const qint64 left = deadline.remainingTime(); // -1: forever
        const int timeout = left < 0 ? -1 : int(std::min<qint64>(left, 1 << 30));
        const int n = ::poll(fds, m_pipe[0] >= 0 ? 2 : 1, timeout);
        if (n < 0) {
            if (errno == EINTR)
                continue;
            return Result::Error;
        }
        if (n == 0)
            return Result::Timeout;
        if (fds[1].revents & POLLIN) {
            char drain[16];
            while (::read(m_pipe[0], drain, sizeof drain) > 0) {
            }
            return Result::Cancelled;
        }
        if (fds[0].revents & (POLLIN | POLLOUT))
            return Result::Ready;
        if (fds[0].revents & (POLLHUP | POLLERR | POLLNVAL))
            return Result::Hangup;
    }
}

} // namespace rung::comms::detail
