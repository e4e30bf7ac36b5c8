#pragma once

// The debugging entries of a Simulation menu, one table for the main window
// (debug_controller.h) and the network window (network_debug_controller.h): each entry's
// object name (after the window's prefix: "simulation" or "network"), its text with its access
// key, its key and what it calls. A text or a key changed here changes in both windows; the
// texts are translated in one context ("rung::app::DebugEntries") where the actions are made.
// Keys (docs/user-guide.md): Ctrl+F12 steps one instruction, Shift+F12 finishes the scan,
// Ctrl+B toggles a breakpoint, Ctrl+Shift+B its condition, Ctrl+Shift+L returns from the
// history to live; all clear of the ladder's F5..F9 and Ctrl+F9/F10 and of the other menus.

#include <QKeyCombination>
#include <QStyle>

#include <span>
#include <vector>

class QAction;
class QMenu;
class QObject;

namespace rung::app {

// What the entries call: each window's debugger answers them for what it debugs (the program
// or the network's selected station).
class DebugCommands {
public:
    virtual void stepInstruction() = 0;
    virtual void finishScan() = 0;
    // Where the user is: the instruction list's line when it has the focus, else the ladder
    // cursor's rung (its first instruction).
    virtual void toggleBreakpointHere() = 0;
    virtual void editBreakpointConditionHere() = 0;
    virtual void clearBreakpoints() = 0;
    virtual void returnToLive() = 0;

protected:
    ~DebugCommands() = default;
};

struct DebugEntry {
    const char *name; // after the window's prefix: "StepInstruction"
    const char *text; // QT_TRANSLATE_NOOP("rung::app::DebugEntries", ...)
    QKeyCombination key = QKeyCombination::fromCombined(0); // none
    void (DebugCommands::*call)() = nullptr;
    bool separatorBefore = false;                        // a new group of the menu starts with it
    QStyle::StandardPixmap icon = QStyle::SP_CustomBase; // SP_CustomBase: none
};

// The entries in the order of the menu.
std::span<const DebugEntry> debugEntries();

// Adds the entries to `menu` (named prefix + name, "networkStepInstruction"; texts in the
// language now installed; a key's tooltip "Step Instruction (Ctrl+F12)"), each calling
// `commands` while `receiver` lives; the actions in the table's order.
std::vector<QAction *> addDebugEntries(QMenu *menu, const char *prefix, DebugCommands *commands,
                                       const QObject *receiver);

} // namespace rung::app
