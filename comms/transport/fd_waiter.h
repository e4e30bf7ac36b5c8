#pragma once

// Waits on a file descriptor with a deadline and a wake-up pipe, so that a blocking read on
// a worker thread can be cancelled from another thread. Shared by the termios and the
// libserialport backends (both have a plain descriptor underneath).

#include <QDeadlineTimer>

namespace rung::comms::detail {

class FdWaiter {
public:
    FdWaiter();
    ~FdWaiter();
    FdWaiter(const FdWaiter &) = delete;
    FdWaiter &operator=(const FdWaiter &) = delete;

    enum class Result { Ready, Timeout, Cancelled, Hangup, Error };
    // Waits until fd is readable (or writable when `forWrite`).
    Result wait(int fd, QDeadlineTimer deadline, bool forWrite = false);
    void wake();

private:
    int m_pipe[2] = {-1, -1};
};

} // namespace rung::comms::detail
