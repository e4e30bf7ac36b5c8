#include "editor/commands/listing_lines_command.h"

#include "editor/il_editor.h"

namespace rung::editor {

ListingLinesCommand::ListingLinesCommand(IlEditor *editor, int firstLine, QStringList before,
                                         QStringList after, std::function<void()> applied,
                                         const QString &label)
    : QUndoCommand(label)
    , m_editor(editor)
    , m_firstLine(firstLine)
    , m_before(std::move(before))
    , m_after(std::move(after))
    , m_applied(std::move(applied)) {}

void ListingLinesCommand::redo() {
    replace(m_before, m_after);
}

void ListingLinesCommand::undo() {
    replace(m_after, m_before);
}

void ListingLinesCommand::replace(const QStringList &from, const QStringList &to) {
    // The user may have typed over these lines since: then the step has nothing left to
    // undo, and it goes rather than overwrite what was typed.
    if (!m_editor || !m_editor->replaceLines(m_firstLine, from, to)) {
        setObsolete(true);
        return;
    }
    if (m_applied)
        m_applied();
}

} // namespace rung::editor
