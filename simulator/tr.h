#pragma once

// The translation contexts of simulator/'s messages outside a class of their own, each
// declared once: a file's texts go through its context, EngineTr::tr("..."). lupdate takes the
// context from the class a tr() call names, so each is a class, not an alias of one.

#include <QCoreApplication>

namespace rung::simulator {

struct CommandInboxTr {
    Q_DECLARE_TR_FUNCTIONS(rung::simulator::CommandInbox)
};
struct CompilerTr {
    Q_DECLARE_TR_FUNCTIONS(rung::simulator::Compiler)
};
struct EngineTr {
    Q_DECLARE_TR_FUNCTIONS(rung::simulator::Engine)
};
struct HistorySourceTr {
    Q_DECLARE_TR_FUNCTIONS(rung::simulator::HistorySource)
};
struct ScenarioTr {
    Q_DECLARE_TR_FUNCTIONS(rung::simulator::Scenario)
};
struct SimulatorSessionTr {
    Q_DECLARE_TR_FUNCTIONS(rung::simulator::SimulatorSession)
};
struct TraceTr {
    Q_DECLARE_TR_FUNCTIONS(rung::simulator::Trace)
};

} // namespace rung::simulator
