#pragma once

// Waiting in a test for what another thread, a process or the event loop will do: poll the
// condition until it holds, never wait a fixed time and then assert (slow when the test
// passes, flaky when the machine is loaded). Every suite's waits come here.

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QThread>

// In a namespace of its own: the rooms' suites have test namespaces of their own
// (rung::test, rung::simulator::test, rung::comms::test), and each takes these by a
// using-declaration.
namespace rung::waits {

// How long a test waits for what must happen: generous, because the CI machine has two cores
// and runs two test processes under a sanitizer; a passing test waits only as long as needed.
constexpr int kPatienceMs = 10000;

// Polls `condition` until it holds, delivering this thread's events meanwhile (signals from a
// worker thread arrive as events; without an event dispatcher there is nothing to deliver);
// false once `ms` have passed. Between polls the thread sleeps a little instead of spinning,
// so that on a loaded machine the worker it waits for gets the core.
template <typename Condition> bool eventually(Condition condition, int ms = kPatienceMs) {
    const QDeadlineTimer deadline(ms);
    while (!condition()) {
        if (deadline.hasExpired())
            return false;
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        QThread::msleep(2);
    }
    return true;
}

} // namespace rung::waits
