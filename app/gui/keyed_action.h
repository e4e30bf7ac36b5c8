#pragma once

// A menu entry with its key: the action named for tests and for the window's key map, its
// tooltip "Step Instruction (Ctrl+F12)" as the toolbars show it. One place for the debug,
// network debug and online menus.

#include <QAction>
#include <QKeySequence>
#include <QMenu>
#include <QString>

namespace rung::app {

template <typename Slot>
QAction *addKeyedAction(QMenu *menu, const QObject *receiver, const char *name, const QString &text,
                        const QKeySequence &key, Slot slot) {
    QAction *a = menu->addAction(text, receiver, slot);
    a->setObjectName(QString::fromLatin1(name));
    if (!key.isEmpty()) {
        a->setShortcut(key);
        a->setToolTip(QStringLiteral("%1 (%2)").arg(QString(text).remove(QLatin1Char('&')),
                                                    key.toString(QKeySequence::NativeText)));
    }
    return a;
}

} // namespace rung::app
