#pragma once

// The translation contexts of app/'s messages outside a class of their own (the command-line
// tool, the virtual PLC; the windows' classes have their own), each declared once: a file's
// texts go through its context, CliTr::tr("..."). lupdate takes the context from the class a
// tr() call names, so each is a class, not an alias of one.

#include <QCoreApplication>

namespace rung::app {

struct CliTr {
    Q_DECLARE_TR_FUNCTIONS(rung::app::Cli)
};
struct DiffTr {
    Q_DECLARE_TR_FUNCTIONS(rung::app::Diff)
};
struct NetworkTr {
    Q_DECLARE_TR_FUNCTIONS(rung::app::Network)
};
struct OnlineTr {
    Q_DECLARE_TR_FUNCTIONS(rung::app::Online)
};
struct PortOptionsTr {
    Q_DECLARE_TR_FUNCTIONS(rung::app::PortOptions)
};
struct RecordTr {
    Q_DECLARE_TR_FUNCTIONS(rung::app::Record)
};
struct ServeTr {
    Q_DECLARE_TR_FUNCTIONS(rung::app::Serve)
};
struct SimulateTr {
    Q_DECLARE_TR_FUNCTIONS(rung::app::Simulate)
};
struct TerminalTr {
    Q_DECLARE_TR_FUNCTIONS(rung::app::Terminal)
};
struct TestTr {
    Q_DECLARE_TR_FUNCTIONS(rung::app::Test)
};
struct VirtualPlcTr {
    Q_DECLARE_TR_FUNCTIONS(rung::app::VirtualPlc)
};

} // namespace rung::app
