#pragma once

// SIGINT and SIGTERM (Ctrl+C, kill) end a command that runs until stopped (serve, record):
// taken by the thread that makes a StopSignals alone, with sigtimedwait, never by a handler.

#include <csignal>

namespace rung::app {

class StopSignals {
public:
    // Blocks the two signals in this thread: made before any thread starts, so that every
    // thread started after inherits the mask and the signals come to this one.
    StopSignals();
    // The mask as it was.
    ~StopSignals();
    StopSignals(const StopSignals &) = delete;
    StopSignals &operator=(const StopSignals &) = delete;

    // Waits at most `ms` for either signal; true when one came.
    bool wait(int ms);

private:
    sigset_t m_signals;
    sigset_t m_previous;
};

} // namespace rung::app
