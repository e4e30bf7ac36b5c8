#include "cli_stop_signals.h"

#include <ctime>

#include <pthread.h>

namespace rung::app {

StopSignals::StopSignals() {
    sigemptyset(&m_signals);
    sigaddset(&m_signals, SIGINT);
    sigaddset(&m_signals, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &m_signals, &m_previous);
}

StopSignals::~StopSignals() {
    pthread_sigmask(SIG_SETMASK, &m_previous, nullptr);
}

bool StopSignals::wait(int ms) {
    const timespec timeout{ms / 1000, (ms % 1000) * 1'000'000L};
    return sigtimedwait(&m_signals, nullptr, &timeout) > 0;
}

} // namespace rung::app
