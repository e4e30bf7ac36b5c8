#include "simulation_controller.h"

#include "editor/document.h"
#include "model/target/address.h"
#include "simulator/session.h"

#include <algorithm>

// Breakpoints and stepping inside a scan (docs/user-guide.md "Breakpoints and stepping").
// The controller keeps the user's breakpoints by rung and place in the rung; the session
// gets them as instruction indices of the program it runs.

namespace rung::app {

int SimulationController::instructionOf(const BreakpointSpec &b) const {
    return instructionOf(m_document->listing().rungFirst, b);
}

int SimulationController::instructionOf(const std::vector<int> &first, const BreakpointSpec &b) {
    if (b.rung < 0 || static_cast<std::size_t>(b.rung) + 1 >= first.size())
        return -1;
    const int at = first[static_cast<std::size_t>(b.rung)] + b.offset;
    return at < first[static_cast<std::size_t>(b.rung) + 1] ? at : -1;
}

std::optional<SimulationController::BreakpointSpec>
SimulationController::placeBreakpoint(const std::vector<int> &first, int instruction,
                                      const BreakpointSpec &condition) {
    const auto rung = std::upper_bound(first.begin(), first.end(), instruction) - first.begin() - 1;
    if (instruction < 0 || rung < 0 || static_cast<std::size_t>(rung) + 1 >= first.size())
        return std::nullopt;
    BreakpointSpec b = condition;
    b.rung = static_cast<int>(rung);
    b.offset = instruction - first[static_cast<std::size_t>(rung)];
    return b;
}

const SimulationController::BreakpointSpec *
SimulationController::breakpointAt(int instruction) const {
    for (const BreakpointSpec &b : m_breakpoints)
        if (instructionOf(b) == instruction && instruction >= 0)
            return &b;
    return nullptr;
}

void SimulationController::setBreakpoint(int instruction, const BreakpointSpec &condition) {
    const std::optional<BreakpointSpec> b =
        placeBreakpoint(m_document->listing().rungFirst, instruction, condition);
    if (!b)
        return;
    std::erase_if(m_breakpoints,
                  [&](const BreakpointSpec &x) { return instructionOf(x) == instruction; });
    m_breakpoints.push_back(*b);
    sendBreakpoints();
}

bool SimulationController::toggleBreakpoint(int instruction) {
    if (breakpointAt(instruction)) {
        removeBreakpoint(instruction);
        return false;
    }
    setBreakpoint(instruction, {});
    return breakpointAt(instruction) != nullptr;
}

void SimulationController::removeBreakpoint(int instruction) {
    std::erase_if(m_breakpoints,
                  [&](const BreakpointSpec &x) { return instructionOf(x) == instruction; });
    sendBreakpoints();
}

void SimulationController::clearBreakpoints() {
    m_breakpoints.clear();
    sendBreakpoints();
}

std::vector<simulator::Breakpoint> SimulationController::engineBreakpoints() const {
    return engineBreakpoints(m_document->listing().rungFirst, m_breakpoints);
}

std::vector<simulator::Breakpoint>
SimulationController::engineBreakpoints(const std::vector<int> &rungFirst,
                                        const std::vector<BreakpointSpec> &specs) {
    std::vector<simulator::Breakpoint> all;
    for (const BreakpointSpec &b : specs) {
        const int at = instructionOf(rungFirst, b);
        if (at < 0)
            continue; // its rung is shorter now: it waits
        simulator::Breakpoint e;
        e.instruction = at;
        e.when = b.when;
        e.device = b.device;
        e.op = b.op;
        e.value = b.value;
        all.push_back(e);
    }
    return all;
}

void SimulationController::sendBreakpoints() {
    // While the session runs the program before an edit with errors, the instructions shown
    // are not the ones it runs: it keeps the breakpoints it has.
    if (m_session && !m_stale)
        m_session->setBreakpoints(engineBreakpoints());
    emit breakpointsChanged();
}

QString SimulationController::conditionText(const BreakpointSpec &b) const {
    return conditionText(m_document->target(), b);
}

QString SimulationController::conditionText(const model::Target &target, const BreakpointSpec &b) {
    using When = simulator::Breakpoint::When;
    const QString device = b.device.valid() ? model::formatAddress(target, b.device) : QString();
    switch (b.when) {
    case When::Always:
        return tr("always");
    case When::Rises:
        return tr("when %1 rises").arg(device);
    case When::Falls:
        return tr("when %1 falls").arg(device);
    case When::IsOn:
        return tr("while %1 is ON").arg(device);
    case When::IsOff:
        return tr("while %1 is OFF").arg(device);
    case When::Compare:
        //: a breakpoint's condition, e.g. "when D10 > 100"
        return tr("when %1 %2 %3")
            .arg(device, QString::fromLatin1(model::compareSymbol(b.op)))
            .arg(b.value);
    }
    return {};
}

bool SimulationController::stepInstruction() {
    returnToLive(); // the step is seen where it happens
    if (!ensureSession())
        return false;
    m_session->stepInstruction();
    return true;
}

void SimulationController::finishScan() {
    returnToLive(); // the step is seen where it happens
    if (m_session)
        m_session->finishScan();
}

void SimulationController::watchStoppedAt() {
    const auto s = m_session ? m_session->snapshot() : nullptr;
    const int at = s && s->pause ? s->pause->instruction : -1;
    if (at == m_stoppedAt)
        return;
    m_stoppedAt = at;
    emit stoppedAtChanged(at);
}

} // namespace rung::app
