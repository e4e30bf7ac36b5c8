#pragma once

// Waits on a file descriptor with a deadline and a wake-up pipe, so that a blocking read on
// a worker thread can be cancelled from another thread. Shared by the termios and the
// libserialport backends (both have a plain descriptor underneath).

#include <QDeadlineTimer>
#include <QString>

namespace rung::comms::detail {

class FdWaiter {
public:
    // Makes the wake-up pipe; when the system refuses one (no file descriptors left), ok() is
    // false and error() says why: the transport's open() reports it instead of opening a
    // port that cancel() could not wake.
    FdWaiter();
    ~FdWaiter();
    FdWaiter(const FdWaiter &) = delete;
    FdWaiter &operator=(const FdWaiter &) = delete;

    enum class Result { Ready, Timeout, Cancelled, Hangup, Error };
    // Waits until fd is readable (or writable when `forWrite`).
    Result wait(int fd, QDeadlineTimer deadline, bool forWrite = false);
    // A wake() with nobody waiting ends the next wait() (see Transport::cancel()).
    void wake();
    bool ok() const { return m_pipe[0] >= 0; }
    const QString &error() const { return m_error; }

private:
    int m_pipe[2] = {-1, -1};
    QString m_error;
};

} // namespace rung::comms::detail
