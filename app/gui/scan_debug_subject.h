#pragma once

// What the Scan Debugger (scan_debugger_view.h) shows and acts on: a simulation whose scan may
// stop inside, its program and its breakpoints. The main window's simulation is one
// (SimulationController, adapted in scan_debugger_view.cpp); a station of a simulated network
// is another (network_debug_controller.h). The subject says when something changed; the view
// reads everything again from it.

#include "app/gui/simulation_controller.h"

#include "model/image/snapshot.h"

#include <QObject>

#include <memory>
#include <vector>

namespace rung::editor {
class Document;
}

namespace rung::app {

class ScanDebugSubject : public QObject {
    Q_OBJECT

public:
    using BreakpointSpec = SimulationController::BreakpointSpec;
    using QObject::QObject;

    // The program shown (its list, lines and rungs); never null.
    virtual editor::Document *document() const = 0;
    // Whether a simulation is there to step at all.
    virtual bool active() const = 0;
    // The live state (its pause: where a scan stopped); null when off.
    virtual std::shared_ptr<const model::Snapshot> snapshot() const = 0;
    // False while a past scan is shown in place of the live one (stepping makes no sense).
    virtual bool live() const { return true; }
    virtual std::vector<BreakpointSpec> breakpoints() const = 0;
    virtual int instructionOf(const BreakpointSpec &b) const = 0;
    virtual QString conditionText(const BreakpointSpec &b) const = 0;
    // What the view's buttons ask.
    virtual void stepInstruction() = 0;
    virtual void finishScan() = 0;
    virtual void proceed() = 0; // Continue: run on
    virtual void removeBreakpoint(int instruction) = 0;
    virtual void clearBreakpoints() = 0;

signals:
    // The breakpoints changed (or the program they are read against).
    void breakpointsChanged();
    // The state changed: run state, the stopped scan's place, another program.
    void stateChanged();
};

} // namespace rung::app
