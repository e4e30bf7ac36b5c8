#include "scenario_trace.h"
#include "simulator/tr.h"

#include <QCoreApplication>

namespace rung::simulator {

namespace {

// Enough changes for every scan of a long run of a toggling bit (an hour at 10 ms).
constexpr std::size_t kChanges = 400000;

} // namespace

ScenarioTrace::ScenarioTrace(const Scenario &scenario, std::shared_ptr<const Program> program,
                             const std::vector<model::Address> &devices, QObject *parent)
    : MonitorSource(parent)
    , m_scenario(scenario)
    , m_program(std::move(program))
    , m_history(m_program->layout, kChanges) {
    for (const model::Address &a : devices)
        if (m_history.watch(a))
            m_watched.insert(a);
    run();
}

void ScenarioTrace::run() {
    m_history.clear();
    std::shared_ptr<Snapshot> last;
    m_result = runScenario(m_scenario, m_program, [&](const Engine &engine) {
        m_history.record(engine.statistics().scans, engine.statistics().timeMs,
                         engine.words().data());
        last = std::make_shared<Snapshot>(engine.snapshot());
    });
    if (last)
        publishSnapshot(last, true);
    setRunState(RunState::Paused);
}

bool ScenarioTrace::watchHistory(const model::Address &address) {
    if (m_watched.contains(address))
        return true;
    // A device not recorded yet: the run again, with it (the run is virtual time, quick).
    if (!m_history.watch(address))
        return false;
    m_watched.insert(address);
    run();
    return true;
}

void ScenarioTrace::readHistory(
    const std::function<void(const model::HistoryRecorder &)> &read) const {
    read(m_history);
}

void ScenarioTrace::startCommand(CommandId id, const model::DeviceCommand &) {
    finishCommand(id, false, ScenarioTr::tr("a scenario's run is read-only"));
}

} // namespace rung::simulator
