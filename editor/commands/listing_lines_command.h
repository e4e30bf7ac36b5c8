#pragma once

// A fix of the instruction list as typed (a fuzzy form rewritten) as a step of the project's
// undo: the step holds the lines before and after and replaces them in the list's editor; the
// program follows the text in place (applied), so that the fix stays one step.

#include <QPointer>
#include <QStringList>
#include <QUndoCommand>

#include <functional>

namespace rung::editor {

class IlEditor;

class ListingLinesCommand : public QUndoCommand {
public:
    // firstLine is 0-based; applied runs after each replacement (the views follow the text).
    ListingLinesCommand(IlEditor *editor, int firstLine, QStringList before, QStringList after,
                        std::function<void()> applied, const QString &label);

    void redo() override;
    void undo() override;

private:
    void replace(const QStringList &from, const QStringList &to);

    QPointer<IlEditor> m_editor;
    int m_firstLine;
    QStringList m_before;
    QStringList m_after;
    std::function<void()> m_applied;
};

} // namespace rung::editor
