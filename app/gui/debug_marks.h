#pragma once

// What a debugger shows in a program's two views, the same in the main window
// (debug_controller.h) and for a network's station (network_debug_controller.h): the
// instruction where the user is, the breakpoints marked on the ladder's rungs and the list's
// lines, and the instruction a scan stopped before. A list "in step" shows the program's
// canonical text (Document::listingText()); a text as typed has lines of its own, and its
// lines are then not marked.

#include "app/gui/simulation_controller.h"

#include <QString>

#include <vector>

namespace rung::editor {
class Document;
class IlEditor;
class LadderView;
} // namespace rung::editor

namespace rung::app {

// The first instruction of a rung (index in the program), -1 where the list has none (a
// comment alone, a rung beyond the program).
int firstInstructionOfRung(const editor::Document &document, int rung);

// The instruction where the user is: the list's line when the list has the focus, else the
// ladder cursor's rung; -1 for none. `where` names the place ("line 3", "rung 2").
int instructionHere(const editor::Document &document, const editor::LadderView &ladder,
                    const editor::IlEditor &il, bool listInStep, QString *where);

// Why there is nowhere to stop, as the status bar says it: a 1-based line of the list, a
// 0-based rung, a place named by instructionHere().
QString noInstructionOnLine(int line);
QString noInstructionInRung(int rung);
QString noInstructionAt(const QString &where);

// The breakpoints marked in both views (conditional ones drawn apart).
void markBreakpoints(const editor::Document &document,
                     const std::vector<SimulationController::BreakpointSpec> &breakpoints,
                     editor::LadderView &ladder, editor::IlEditor &il, bool listInStep);

// The instruction a scan stopped before (-1: none) marked in both views: its cell in the
// ladder (an output in the output column), its line in the list.
void markStoppedAt(const editor::Document &document, int instruction, editor::LadderView &ladder,
                   editor::IlEditor &il, bool listInStep);

} // namespace rung::app
