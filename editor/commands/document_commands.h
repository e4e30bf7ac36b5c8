#pragma once

// The document's own undo steps: the rungs, the symbols and the watch lists replaced as a
// whole. Each step stores the state before and after as values, never pointers into the
// document, and hands it back through Document's apply* functions.

#include "model/ladder/ladder.h"
#include "model/project/project.h"

#include <QUndoCommand>

#include <vector>

namespace rung::editor {

class Document;

// Replaces rungs [first, first + oldRungs.size()) by newRungs; stores both as values (the
// serialized state of the rungs), never pointers into the document.
class ReplaceRungsCommand : public QUndoCommand {
public:
    ReplaceRungsCommand(Document *doc, int first, std::vector<model::Rung> oldRungs,
                        std::vector<model::Rung> newRungs, const QString &label);

    void redo() override;
    void undo() override;

private:
    Document *m_doc;
    int m_first;
    std::vector<model::Rung> m_old;
    std::vector<model::Rung> m_new;
};

class SymbolsCommand : public QUndoCommand {
public:
    SymbolsCommand(Document *doc, std::vector<model::Symbol> oldSymbols,
                   std::vector<model::Symbol> newSymbols);
    void redo() override;
    void undo() override;

private:
    Document *m_doc;
    std::vector<model::Symbol> m_old;
    std::vector<model::Symbol> m_new;
};

class WatchListsCommand : public QUndoCommand {
public:
    WatchListsCommand(Document *doc, std::vector<model::WatchList> oldLists,
                      std::vector<model::WatchList> newLists, const QString &label);
    void redo() override;
    void undo() override;

private:
    Document *m_doc;
    std::vector<model::WatchList> m_old;
    std::vector<model::WatchList> m_new;
};

// The project's communication ports ("ports": the 2nd COM Port Setting and the like) replaced
// as a whole.
class PortsCommand : public QUndoCommand {
public:
    PortsCommand(Document *doc, QJsonObject oldPorts, QJsonObject newPorts, const QString &label);
    void redo() override;
    void undo() override;

private:
    Document *m_doc;
    QJsonObject m_old;
    QJsonObject m_new;
};

} // namespace rung::editor
