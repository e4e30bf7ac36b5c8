#pragma once

// Commands for an Engine from other threads. Any thread posts; the engine's thread applies
// them all before its next scan (apply), so no other thread touches engine state and the
// engine itself stays single-threaded. Each command's result goes to the completion callback,
// on the engine's thread, in the order the commands were posted, when the engine's thread
// calls complete(): a driver that publishes snapshots publishes first, so a reader told of a
// completion finds its effect in the latest snapshot.

#include "engine.h"

#include "model/image/device_command.h"

#include <QString>

#include <atomic>
#include <functional>
#include <mutex>
#include <variant>
#include <vector>

namespace rung::simulator {

struct PowerCycle {}; // power off and on: non-retentive areas clear
struct Reset {};      // a fresh PLC's power-on state: every area clear, forces released
// An online edit: the program runs from the next scan boundary on with the image kept
// (Engine::replaceProgram), then stops at these breakpoints of its own.
struct ReplaceProgram {
    std::shared_ptr<const Program> program;
    std::vector<Breakpoint> breakpoints;
};

struct EngineCommand {
    quint64 id = 0; // 0: nobody waits for it, no completion
    std::variant<model::DeviceCommand, PowerCycle, Reset, ReplaceProgram> what;
};

class CommandInbox {
public:
    // error is translated and empty when ok.
    using Completion = std::function<void(quint64 id, bool ok, const QString &error)>;

    explicit CommandInbox(Completion completion = {});

    void post(EngineCommand command); // any thread
    // Cheap enough to ask every scan.
    bool pending() const { return m_pending.load(std::memory_order_acquire); }
    struct Applied {
        int commands = 0;
        bool reset = false; // a Reset was among them
    };
    // Engine thread: applies every posted command, in posting order; their results wait for
    // complete(). `before` (when given) sees each command just before it is applied (the
    // session's history records it there).
    Applied apply(Engine &engine, const std::function<void(const EngineCommand &)> &before = {});
    // Engine thread: hands the results of the commands applied so far to the completion.
    void complete();

private:
    struct Result {
        quint64 id;
        bool ok;
        QString error;
    };

    std::atomic<bool> m_pending{false};
    std::mutex m_mutex;
    std::vector<EngineCommand> m_queue;
    std::vector<EngineCommand> m_taken; // reused between calls
    std::vector<Result> m_results;      // engine thread only
    Completion m_completion;
};

// Applies one command; false with a translated reason when the device cannot take it.
bool applyCommand(Engine &engine, const EngineCommand &command, QString *error);

} // namespace rung::simulator
