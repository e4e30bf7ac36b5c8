#pragma once

// Commands for an Engine from other threads. Any thread posts; the engine's thread applies
// them all at the start of the next scan (Engine::attach), so no other thread touches engine
// state and the engine itself stays single-threaded. Each command's result goes to the
// completion callback, on the engine's thread, in the order the commands were posted.

#include "model/image/device_command.h"

#include <QString>

#include <atomic>
#include <functional>
#include <mutex>
#include <variant>
#include <vector>

namespace rung::simulator {

class Engine;

struct PowerCycle {}; // power off and on: non-retentive areas clear

struct EngineCommand {
    quint64 id = 0;
    std::variant<model::DeviceCommand, PowerCycle> what;
};

class CommandInbox {
public:
    // error is translated and empty when ok.
    using Completion = std::function<void(quint64 id, bool ok, const QString &error)>;

    explicit CommandInbox(Completion completion = {});

    void post(EngineCommand command); // any thread
    // Cheap enough to ask every scan.
    bool pending() const { return m_pending.load(std::memory_order_acquire); }
    // Engine thread: applies and completes every posted command; returns how many.
    int applyTo(Engine &engine);

private:
    std::atomic<bool> m_pending{false};
    std::mutex m_mutex;
    std::vector<EngineCommand> m_queue;
    std::vector<EngineCommand> m_taken; // reused between calls
    Completion m_completion;
};

// Applies one command; false with a translated reason when the device cannot take it.
bool applyCommand(Engine &engine, const EngineCommand &command, QString *error);

} // namespace rung::simulator
