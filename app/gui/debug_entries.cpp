#include "app/gui/debug_entries.h"

#include "app/gui/keyed_action.h"

#include <QCoreApplication>
#include <QMenu>

#include <array>

namespace rung::app {

namespace {

constexpr const char *kContext = "rung::app::DebugEntries";

const std::array<DebugEntry, 6> kEntries{{
    {"StepInstruction", QT_TRANSLATE_NOOP("rung::app::DebugEntries", "S&tep Instruction"),
     Qt::CTRL | Qt::Key_F12, &DebugCommands::stepInstruction, true, QStyle::SP_ArrowRight},
    {"FinishScan", QT_TRANSLATE_NOOP("rung::app::DebugEntries", "F&inish Scan"),
     Qt::SHIFT | Qt::Key_F12, &DebugCommands::finishScan},
    {"ToggleBreakpoint", QT_TRANSLATE_NOOP("rung::app::DebugEntries", "Toggle &Breakpoint"),
     Qt::CTRL | Qt::Key_B, &DebugCommands::toggleBreakpointHere},
    {"BreakpointCondition",
     QT_TRANSLATE_NOOP("rung::app::DebugEntries", "Breakpoint Co&ndition..."),
     Qt::CTRL | Qt::SHIFT | Qt::Key_B, &DebugCommands::editBreakpointConditionHere},
    {"RemoveAllBreakpoints",
     QT_TRANSLATE_NOOP("rung::app::DebugEntries", "Remove All Brea&kpoints"),
     QKeyCombination::fromCombined(0), &DebugCommands::clearBreakpoints},
    {"ReturnToLive", QT_TRANSLATE_NOOP("rung::app::DebugEntries", "Return to &Live"),
     Qt::CTRL | Qt::SHIFT | Qt::Key_L, &DebugCommands::returnToLive, true},
}};

} // namespace

std::span<const DebugEntry> debugEntries() {
    return kEntries;
}

std::vector<QAction *> addDebugEntries(QMenu *menu, const char *prefix, DebugCommands *commands,
                                       const QObject *receiver) {
    std::vector<QAction *> made;
    for (const DebugEntry &e : kEntries) {
        if (e.separatorBefore)
            menu->addSeparator();
        const QByteArray name = QByteArray(prefix) + e.name;
        QAction *a = addKeyedAction(
            menu, receiver, name.constData(), QCoreApplication::translate(kContext, e.text),
            QKeySequence(e.key), [commands, call = e.call] { (commands->*call)(); });
        if (e.icon != QStyle::SP_CustomBase)
            a->setIcon(menu->style()->standardIcon(e.icon));
        made.push_back(a);
    }
    return made;
}

} // namespace rung::app
