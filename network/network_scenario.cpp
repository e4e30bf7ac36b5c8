#include "network/network_scenario.h"

#include "network/net_trace.h"
#include "network/station.h"
#include "network/tr.h"

namespace rung::network {

namespace {

class NetworkSubject final : public simulator::ScenarioSubject {
public:
    explicit NetworkSubject(std::unique_ptr<Network> network)
        : m_network(std::move(network)) {}

    simulator::Engine *engineFor(const QString &written, QString *device, QString *error) override {
        Station *s = stationDevice(*m_network, written, device, error);
        return s ? &s->engine() : nullptr;
    }
    qint64 defaultPeriodMs() const override { return m_network->description().periodMs; }
    void start(qint64 periodMs) override { m_stepUs = periodMs * 1000; }
    // Each station keeps its own period; a step is the scenario's period of virtual time, at
    // whose end every scan ending then has run (as `simulate` prints a network's row).
    void step() override {
        m_nowUs += m_stepUs;
        m_network->runUntil(m_nowUs);
    }
    void releaseAll() override {
        for (const auto &s : m_network->stations())
            s->engine().releaseAll();
    }
    QStringList runtimeErrors() const override {
        QStringList out;
        for (const auto &s : m_network->stations())
            for (const simulator::RuntimeError &e : s->engine().runtimeErrors())
                //: %1 the station, %2 the step, %3 what went wrong
                out << NetworkTr::tr("%1: runtime error at step %2: %3")
                           .arg(s->name())
                           .arg(e.instruction)
                           .arg(e.message);
        return out;
    }

private:
    std::unique_ptr<Network> m_network;
    qint64 m_stepUs = 10000;
    qint64 m_nowUs = 0;
};

} // namespace

std::unique_ptr<simulator::ScenarioSubject>
networkScenarioSubject(const QString &path, const ProgramLoader &loader, QStringList *errors) {
    NetworkDescription description;
    QString error;
    if (!readNetworkFile(path, &description, &error)) {
        *errors << error;
        return nullptr;
    }
    std::unique_ptr<Network> network = Network::build(description, loader, &error);
    if (!network) {
        *errors << error.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        return nullptr;
    }
    return std::make_unique<NetworkSubject>(std::move(network));
}

} // namespace rung::network
