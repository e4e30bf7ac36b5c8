#include "main_window.h"

#include "layout_controller.h"

#include "about_dialog.h"
#include "dialogs.h"
#include "file_controller.h"
#include "file_dialogs.h"
#include "language.h"
#include "listing_controller.h"
#include "online_controller.h"
#include "simulation_menu.h"
#include "symbol_table.h"

#include "app/languages.h"
#include "model/target/target_lists.h"

#include "editor/il_editor.h"
#include "editor/ladder_view.h"
#include "editor/tool_icons.h"
#include "editor/watch_list_view.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QDockWidget>
#include <QFile>
#include <QKeyEvent>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QToolBar>

// The menus, the toolbar and their actions: what each entry does and its shortcut.

namespace rung::app {

namespace {

// The ladder view reads these keys itself (as it reads typing into a cell), so they work the
// same with or without the menu; the action carries the key for the menu to show, and only
// fires while its menu is open, never in the list editor, where the keys mean other things.
void showKeyInMenu(QAction *action, const QKeySequence &key) {
    action->setShortcut(key);
    action->setShortcutContext(Qt::WidgetShortcut);
}

} // namespace

void MainWindow::buildActions() {
    // Built again, whole, when the language changes (retranslate()): every object made here is
    // owned by a menu or the toolbar, and every connection's context is one of them, so that
    // what the old menus held goes with them.
    QMenu *file = menuBar()->addMenu(tr("&File"));
    QToolBar *bar = new QToolBar(tr("Main"), this);
    m_toolBar = bar;
    if (QToolBar *old = findChild<QToolBar *>(QStringLiteral("mainToolBar"))) {
        insertToolBar(old, bar);
        removeToolBar(old);
        delete old;
    } else {
        addToolBar(bar);
    }
    bar->setObjectName(QStringLiteral("mainToolBar"));
    bar->setIconSize(QSize(24, 24));
    bar->setToolButtonStyle(Qt::ToolButtonIconOnly); // the names and keys are in the tooltips
    m_files->addActions(file, bar);                  // file_controller.cpp
    bar->addSeparator();

    QMenu *edit = menuBar()->addMenu(tr("&Edit"));
    QAction *undo = m_listing->undoAction(false, edit);
    undo->setShortcut(QKeySequence::Undo);
    QAction *redo = m_listing->undoAction(true, edit);
    // Ctrl+Y as well, as on Windows, once: the platform's Redo may already be it.
    QList<QKeySequence> redoKeys = QKeySequence::keyBindings(QKeySequence::Redo);
    if (!redoKeys.contains(QKeySequence(Qt::CTRL | Qt::Key_Y)))
        redoKeys << QKeySequence(Qt::CTRL | Qt::Key_Y);
    redo->setShortcuts(redoKeys);
    undo->setIcon(editor::toolIcon(editor::ToolIcon::Undo));
    redo->setIcon(editor::toolIcon(editor::ToolIcon::Redo));
    edit->addAction(undo);
    edit->addAction(redo);
    bar->addAction(undo);
    bar->addAction(redo);
    bar->addSeparator();
    edit->addSeparator();
    // The palette: what F5..F9 do, as the vendor tools have it.
    auto pressKey = [this](Qt::Key key, Qt::KeyboardModifiers mods = Qt::NoModifier) {
        return [this, key, mods] {
            m_ladder->setFocus();
            QApplication::postEvent(m_ladder, new QKeyEvent(QEvent::KeyPress, key, mods));
        };
    };
    struct Tool {
        QString text;
        editor::ToolIcon icon;
        QKeySequence key;
        std::function<void()> run;
        bool onToolbar = true; // the parallel NC and edge contacts: the menu and their keys
    };
    const std::vector<Tool> tools = {
        {tr("Normally &Open Contact"), editor::ToolIcon::OpenContact, QKeySequence(Qt::Key_F5),
         pressKey(Qt::Key_F5)},
        {tr("Normally &Closed Contact"), editor::ToolIcon::ClosedContact, QKeySequence(Qt::Key_F6),
         pressKey(Qt::Key_F6)},
        {tr("&Parallel Contact"), editor::ToolIcon::ParallelContact,
         QKeySequence(Qt::SHIFT | Qt::Key_F5), pressKey(Qt::Key_F5, Qt::ShiftModifier)},
        {tr("&Rising-Edge Contact"), editor::ToolIcon::RisingContact,
         QKeySequence(Qt::SHIFT | Qt::Key_F7), pressKey(Qt::Key_F7, Qt::ShiftModifier)},
        {tr("&Falling-Edge Contact"), editor::ToolIcon::FallingContact,
         QKeySequence(Qt::SHIFT | Qt::Key_F8), pressKey(Qt::Key_F8, Qt::ShiftModifier)},
        {tr("Parall&el Normally Closed Contact"), editor::ToolIcon::ClosedContact,
         QKeySequence(Qt::SHIFT | Qt::Key_F6), pressKey(Qt::Key_F6, Qt::ShiftModifier), false},
        {tr("Parallel Ri&sing-Edge Contact"), editor::ToolIcon::RisingContact,
         QKeySequence(Qt::ALT | Qt::Key_F7), pressKey(Qt::Key_F7, Qt::AltModifier), false},
        {tr("Parallel Fallin&g-Edge Contact"), editor::ToolIcon::FallingContact,
         QKeySequence(Qt::ALT | Qt::Key_F8), pressKey(Qt::Key_F8, Qt::AltModifier), false},
        {tr("Co&il"), editor::ToolIcon::Coil, QKeySequence(Qt::Key_F7), pressKey(Qt::Key_F7)},
        {tr("I&nstruction"), editor::ToolIcon::Instruction, QKeySequence(Qt::Key_F8),
         pressKey(Qt::Key_F8)},
        {tr("&Horizontal Wire"), editor::ToolIcon::HorizontalWire, QKeySequence(Qt::Key_F9),
         [this] { m_ladder->placeWire(); }},
        {tr("&Vertical Link"), editor::ToolIcon::VerticalLink, QKeySequence(Qt::SHIFT | Qt::Key_F9),
         [this] { m_ladder->toggleLink(); }},
    };
    // The menu acts at the cursor, as the keys do. The toolbar's palette is a set of tools: pick
    // one, then each click on a cell places its element there, until Esc, a right click or the
    // select tool (CX-Programmer and drawing programs work this way).
    auto *palette = new QActionGroup(bar);
    QAction *pointer = bar->addAction(editor::toolIcon(editor::ToolIcon::Pointer), tr("Select"));
    pointer->setToolTip(tr("Select (Esc)"));
    pointer->setCheckable(true);
    pointer->setChecked(true);
    palette->addAction(pointer);
    connect(pointer, &QAction::triggered, this, [this] { m_ladder->armTool({}); });
    // The palette's entries in a submenu of their own: with them the Edit menu had more
    // entries than letters for access keys.
    QMenu *place = edit->addMenu(tr("Place &Element"));
    for (const Tool &t : tools) {
        const QString name = QString(t.text).remove(QLatin1Char('&'));
        QAction *a = place->addAction(editor::toolIcon(t.icon), t.text, this, t.run);
        showKeyInMenu(a, t.key);
        if (!t.onToolbar)
            continue;
        QAction *tool = bar->addAction(editor::toolIcon(t.icon), name);
        tool->setToolTip(tr("%1 (%2): click the cells to place it")
                             .arg(name, t.key.toString(QKeySequence::NativeText)));
        tool->setCheckable(true);
        tool->setData(t.key);
        palette->addAction(tool);
        connect(tool, &QAction::triggered, this, [this, key = t.key, text = name] {
            m_ladder->armTool(key);
            m_ladder->setFocus();
            statusBar()->showMessage(
                tr("%1: click a cell to place it; Esc or a right click ends").arg(text));
        });
    }
    connect(m_ladder, &editor::LadderView::toolArmed, palette,
            [this, palette, pointer](const QKeySequence &key) {
                if (key.isEmpty()) {
                    pointer->setChecked(true);
                    // The tool's hint goes with the tool; any other message stays.
                    for (QAction *a : palette->actions())
                        if (statusBar()->currentMessage() ==
                            tr("%1: click a cell to place it; Esc or a right click ends")
                                .arg(a->text()))
                            statusBar()->clearMessage();
                    return;
                }
                for (QAction *a : palette->actions())
                    if (a->data().value<QKeySequence>() == key)
                        a->setChecked(true);
            });
    edit->addSeparator();
    // Ctrl+X/C/V act on rungs in the ladder; the listing keeps its own text clipboard keys.
    for (QAction *a : {edit->addAction(tr("Cu&t Rung"), this, [this] { copyRung(true); }),
                       edit->addAction(tr("&Copy Rung"), this, [this] { copyRung(false); }),
                       edit->addAction(tr("&Paste Rungs"), this, &MainWindow::pasteRungs)}) {
        a->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        m_ladder->addAction(a);
    }
    edit->actions().at(edit->actions().size() - 3)->setShortcut(QKeySequence::Cut);
    edit->actions().at(edit->actions().size() - 2)->setShortcut(QKeySequence::Copy);
    edit->actions().at(edit->actions().size() - 1)->setShortcut(QKeySequence::Paste);
    edit->addAction(tr("&Find Device..."), this, &MainWindow::findDeviceDialog)
        ->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_F));
    edit->addAction(tr("Find &Next"), this, [this] { findDevice(m_findText, false); })
        ->setShortcut(QKeySequence(Qt::Key_F3));
    edit->addAction(tr("Find Pre&vious"), this, [this] { findDevice(m_findText, true); })
        ->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F3));
    edit->addAction(tr("Replace &Device..."), this, &MainWindow::replaceDevice)
        ->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_H)); // QKeySequence::Replace: none on Linux
    edit->addSeparator();
    edit->addAction(tr("&Import Symbols (CSV)..."), this, [this] {
        const QString path =
            askOpenFile(this, tr("Import Symbols"), m_document->path(), tr("CSV files (*.csv)"));
        QString error;
        if (!path.isEmpty() && !m_symbols->importCsv(path, &error))
            messageBox(QMessageBox::Critical, this, tr("Cannot import"), error);
    });
    edit->addAction(tr("E&xport Symbols (CSV)..."), this, &MainWindow::exportSymbols);
    edit->addSeparator();
    edit->addAction(tr("Add to Watc&h List"), this,
                    [this] { m_watch->addDevice(m_ladder->deviceAtCursor()); })
        ->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_W));
    edit->addAction(tr("Rung Co&mment..."), this, &MainWindow::editRungComment)
        ->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_M));
    QAction *ports =
        edit->addAction(tr("Communic&ation Ports..."), this, &MainWindow::editCommunicationPorts);
    ports->setObjectName(QStringLiteral("communicationPorts"));
    ports->setStatusTip(tr("The PLC's own port settings, kept in the project: what Ladder "
                           "Master calls the 2nd COM Port Setting, CPU Link, the PL110's "
                           "COM1 / EXP1 / COM2 protocols"));
    showKeyInMenu(edit->addAction(tr("In&sert Rung"), this, [this] { m_ladder->insertRung(); }),
                  QKeySequence(Qt::SHIFT | Qt::Key_Insert));
    showKeyInMenu(edit->addAction(tr("De&lete Rung"), this, [this] { m_ladder->deleteRung(); }),
                  QKeySequence(Qt::SHIFT | Qt::Key_Delete));
    showKeyInMenu(edit->addAction(tr("Insert R&ow"), this, [this] { m_ladder->insertRow(); }),
                  QKeySequence(Qt::CTRL | Qt::Key_Insert));
    showKeyInMenu(edit->addAction(tr("Delete Ro&w"), this, [this] { m_ladder->deleteRow(); }),
                  QKeySequence(Qt::CTRL | Qt::Key_Delete));

    QMenu *view = menuBar()->addMenu(tr("&View"));
    m_layout->addActions(view); // side by side, reset the layout (layout_controller.cpp)
    view->addSeparator();
    QAction *names = view->addAction(tr("Show Symbol &Names"));
    names->setCheckable(true);
    names->setToolTip(tr("Names from the symbol table in place of the addresses"));
    connect(names, &QAction::toggled, this, [this](bool on) {
        m_ladder->setNamesFirst(on);
        QSettings().setValue(QStringLiteral("view/namesFirst"), on);
    });
    names->setChecked(QSettings().value(QStringLiteral("view/namesFirst"), false).toBool());
    QAction *fit = view->addAction(tr("&Fit Ladder to Width"));
    fit->setCheckable(true);
    fit->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_0));
    connect(fit, &QAction::toggled, m_ladder, &editor::LadderView::setFitWidth);
    connect(m_ladder, &editor::LadderView::fitWidthChanged, fit, [fit](bool on) {
        fit->setChecked(on);
        QSettings().setValue(QStringLiteral("view/fitWidth"), on);
    });
    fit->setChecked(QSettings().value(QStringLiteral("view/fitWidth"), true).toBool());
    view->addAction(tr("Zoom &In"), this, [this] { m_ladder->setZoom(m_ladder->zoom() * 1.15); })
        ->setShortcut(QKeySequence::ZoomIn);
    view->addAction(tr("Zoom &Out"), this, [this] { m_ladder->setZoom(m_ladder->zoom() / 1.15); })
        ->setShortcut(QKeySequence::ZoomOut);
    view->addAction(tr("&Check Program"), this, [this] { m_listing->refreshFromDocument(); })
        ->setShortcut(Qt::Key_F4);
    addPanelActions(view);             // main_window_panels.cpp
    m_simulationMenu->addActions(bar); // simulation_menu.cpp
    m_online->addActions(bar, view);   // online_controller.cpp

    QMenu *language = menuBar()->addMenu(tr("&Language"));
    auto *group = new QActionGroup(language);
    const QString current = currentLanguage();
    // Each language by its own name, whatever the interface speaks now.
    for (const auto &[code, name] : kLanguages) {
        QAction *a = language->addAction(QString::fromUtf8(name));
        a->setCheckable(true);
        a->setChecked(current == QLatin1String(code));
        a->setData(QString::fromLatin1(code));
        group->addAction(a);
        const QString c = QString::fromLatin1(code);
        // Queued: the switch rebuilds the menus, this action's among them.
        connect(
            a, &QAction::triggered, this, [c] { setLanguage(c); }, Qt::QueuedConnection);
    }
    QMenu *help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&Keyboard..."), this, [this] {
        // The examples in this PLC's own words: "LD X0, OUT Y0", "LD 000.00, OUT 010.00".
        const model::Target &t = m_document->target();
        QStringList examples;
        for (const auto &[op, output] :
             {std::pair{model::Op::Load, false}, std::pair{model::Op::Out, true}})
            if (const model::InstructionSpec *spec = t.findInstruction(op))
                examples << spec->mnemonic + QLatin1Char(' ') + model::exampleDevice(t, output);
        messageBox(
            QMessageBox::Information, this, tr("Keyboard"),
            tr("F5 normally open contact, F6 normally closed contact, F7 coil, F8 instruction\n"
               "Shift+F5 / Shift+F6 the same contacts in parallel with the row above\n"
               "Shift+F7 / Shift+F8 rising / falling edge contact (Alt: in parallel)\n"
               "F9 horizontal wire, Shift+F9 vertical link, Ctrl+F9 / Ctrl+F10 delete them\n"
               "Type an instruction into the cell: %1\n"
               "Insert: insert a cell, Ctrl+Insert: insert a row, Shift+Insert: insert a rung\n"
               "Delete: clear, Ctrl+Delete: delete the row, Shift+Delete: delete the rung\n"
               "Ctrl+Z / Ctrl+Y: undo / redo, Ctrl+wheel: zoom, F4: check the program")
                    .arg(examples.join(QStringLiteral(", "))) +
                QLatin1Char('\n') +
                tr("Simulation: F10 run, F11 pause, Shift+F11 stop, F12 single scan, "
                   "Ctrl+Shift+F12 power cycle") +
                QLatin1Char('\n') +
                tr("Online: Ctrl+W go online / offline, Ctrl+1 STOP (PROGRAM), Ctrl+3 MONITOR, "
                   "Ctrl+4 RUN"));
    });
    QAction *about = help->addAction(tr("&About Rung Studio"), this, [this] {
        AboutDialog dialog(this);
        dialog.exec();
    });
    about->setObjectName(QStringLiteral("aboutAction"));
    about->setMenuRole(QAction::AboutRole);
}

} // namespace rung::app
