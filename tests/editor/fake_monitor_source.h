#pragma once

// A MonitorSource for tests of the layer above it: the test publishes the snapshots it wants
// seen, and commands are recorded and answered at once (ok, or the error the test chose).

#include "model/image/monitor_source.h"
#include "tests/eventually.h"

#include <QSignalSpy>

#include <functional>
#include <vector>

namespace rung::test {

using waits::eventually;
using waits::kPatienceMs;

class FakeMonitorSource : public model::MonitorSource {
public:
    using MonitorSource::MonitorSource;

    // The image of a target with every device zero.
    std::shared_ptr<model::Snapshot> blank(const model::Target &target) {
        m_layout = std::make_shared<const model::MemoryLayout>(target);
        auto snapshot = std::make_shared<model::Snapshot>();
        snapshot->layout = m_layout;
        const auto words = static_cast<std::size_t>(m_layout->wordCount());
        snapshot->words.assign(words, 0);
        snapshot->forceMask.assign(words, 0);
        snapshot->forceValue.assign(words, 0);
        return snapshot;
    }
    void publish(std::shared_ptr<const model::Snapshot> snapshot) {
        publishSnapshot(std::move(snapshot));
    }
    // Publishes the image of `target` that `fill` makes and waits until the readers were
    // told; false when they were not.
    bool publishFilled(const model::Target &target,
                       const std::function<void(model::Snapshot &)> &fill) {
        auto snapshot = blank(target);
        fill(*snapshot);
        QSignalSpy changed(this, &MonitorSource::snapshotChanged);
        publish(snapshot);
        return changed.wait(waits::kPatienceMs);
    }
    void setState(RunState state) { setRunState(state); }
    void setError(const QString &text) { setErrorText(text); }

    std::vector<model::DeviceCommand> commands;
    QString failWith; // empty: every command succeeds
    QString refusal;  // forceRefusal(): empty, the source can force
    QString forceRefusal() const override { return refusal; }

protected:
    void startCommand(CommandId id, const model::DeviceCommand &command) override {
        commands.push_back(command);
        finishCommand(id, failWith.isEmpty(), failWith);
    }

private:
    std::shared_ptr<const model::MemoryLayout> m_layout;
};

} // namespace rung::test
