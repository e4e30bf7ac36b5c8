#pragma once

// A delegate for tables of live values: a cell's editor is filled once, when it opens, so the
// snapshots that change the cell while the user types (dataChanged on the readers' beat) do
// not overwrite what is typed. The watch table and the network's watch table use it.

#include <QStyledItemDelegate>

namespace rung::editor {

class KeepTypedDelegate : public QStyledItemDelegate {
public:
    using QStyledItemDelegate::QStyledItemDelegate;

    void setEditorData(QWidget *editor, const QModelIndex &index) const override {
        static const char *const filled = "rungFilled";
        if (editor->property(filled).toBool())
            return;
        QStyledItemDelegate::setEditorData(editor, index);
        editor->setProperty(filled, true);
    }
};

} // namespace rung::editor
