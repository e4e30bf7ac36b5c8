#pragma once

// A scenario run kept for the timing chart (the IDE's Tests dock: a failed expectation opens
// the chart at its instant): the scenario runs again on a fresh engine and the chosen devices
// are recorded scan by scan. A read-only MonitorSource: its history is the run, its snapshot
// the image after the last scan; commands are refused.

#include "scenario.h"

#include "model/image/monitor_source.h"

#include <set>

namespace rung::simulator {

class ScenarioTrace : public model::MonitorSource {
    Q_OBJECT

public:
    // Runs the scenario now (virtual time: a few milliseconds for minutes of a program),
    // recording `devices` and the devices of every expectation.
    ScenarioTrace(const Scenario &scenario, std::shared_ptr<const Program> program,
                  const std::vector<model::Address> &devices, QObject *parent = nullptr);

    const ScenarioResult &result() const { return m_result; }

    bool watchHistory(const model::Address &address) override;
    void
    readHistory(const std::function<void(const model::HistoryRecorder &)> &read) const override;

protected:
    void startCommand(CommandId id, const model::DeviceCommand &command) override;

private:
    void run();

    Scenario m_scenario;
    std::shared_ptr<const Program> m_program;
    model::HistoryRecorder m_history;
    std::set<model::Address> m_watched;
    ScenarioResult m_result;
};

} // namespace rung::simulator
