#include "editor/commands/document_commands.h"

#include "editor/document.h"

namespace rung::editor {

ReplaceRungsCommand::ReplaceRungsCommand(Document *doc, int first,
                                         std::vector<model::Rung> oldRungs,
                                         std::vector<model::Rung> newRungs, const QString &label)
    : QUndoCommand(label)
    , m_doc(doc)
    , m_first(first)
    , m_old(std::move(oldRungs))
    , m_new(std::move(newRungs)) {}

void ReplaceRungsCommand::redo() {
    m_doc->applyRungs(m_first, static_cast<int>(m_old.size()), m_new);
}

void ReplaceRungsCommand::undo() {
    m_doc->applyRungs(m_first, static_cast<int>(m_new.size()), m_old);
}

SymbolsCommand::SymbolsCommand(Document *doc, std::vector<model::Symbol> oldSymbols,
                               std::vector<model::Symbol> newSymbols)
    : QUndoCommand(Document::tr("Edit symbols"))
    , m_doc(doc)
    , m_old(std::move(oldSymbols))
    , m_new(std::move(newSymbols)) {}

void SymbolsCommand::redo() {
    m_doc->applySymbols(m_new);
}

void SymbolsCommand::undo() {
    m_doc->applySymbols(m_old);
}

WatchListsCommand::WatchListsCommand(Document *doc, std::vector<model::WatchList> oldLists,
                                     std::vector<model::WatchList> newLists, const QString &label)
    : QUndoCommand(label)
    , m_doc(doc)
    , m_old(std::move(oldLists))
    , m_new(std::move(newLists)) {}

void WatchListsCommand::redo() {
    m_doc->applyWatchLists(m_new);
}

void WatchListsCommand::undo() {
    m_doc->applyWatchLists(m_old);
}

PortsCommand::PortsCommand(Document *doc, QJsonObject oldPorts, QJsonObject newPorts,
                           const QString &label)
    : QUndoCommand(label)
    , m_doc(doc)
    , m_old(std::move(oldPorts))
    , m_new(std::move(newPorts)) {}

void PortsCommand::redo() {
    m_doc->applyPorts(m_new);
}

void PortsCommand::undo() {
    m_doc->applyPorts(m_old);
}

} // namespace rung::editor
