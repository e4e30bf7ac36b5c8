#pragma once

// The project's symbol table, edited in place: a view over editor::SymbolTableModel (device,
// name and comment per row; the rows being typed that are no symbol yet stay after the
// symbols, marked, until complete or cleared). CSV import and export.

#include "model/project/project.h"

#include <QTableView>

#include <vector>

namespace rung::editor {
class Document;
class SymbolTableModel;
} // namespace rung::editor

namespace rung::app {

class SymbolTable : public QTableView {
    Q_OBJECT

public:
    explicit SymbolTable(editor::Document *document, QWidget *parent = nullptr);

    editor::SymbolTableModel *symbols() const { return m_model; }
    void refresh(); // from the document's symbols and the rows being typed
    // The rows typed that are no symbol yet (marked in the table): a project keeps them.
    const std::vector<model::PendingSymbol> &pending() const;
    void setPending(const std::vector<model::PendingSymbol> &rows); // those of another project
    bool importCsv(const QString &path, QString *error);
    bool exportCsv(const QString &path, QString *error) const;

signals:
    void message(const QString &text); // why a typed device is no device
    void pendingChanged();             // the rows that are no symbol yet, unsaved work

protected:
    void changeEvent(QEvent *event) override;

private:
    void setHeaders();

    editor::Document *m_document;
    editor::SymbolTableModel *m_model;
};

} // namespace rung::app
