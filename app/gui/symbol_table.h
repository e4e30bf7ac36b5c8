#pragma once

// The project's symbol table, edited in place: device, name and comment per row. Rows being
// typed that are no symbol yet (no device, or one the target does not have) stay in the table,
// after the symbols, marked, until complete or cleared. CSV import and export.

#include "model/project/project.h"

#include <QTableWidget>

#include <vector>

namespace rung::editor {
class Document;
}

namespace rung::app {

class SymbolTable : public QTableWidget {
    Q_OBJECT

public:
    explicit SymbolTable(editor::Document *document, QWidget *parent = nullptr);

    void refresh(); // from the document's symbols and the rows being typed
    // The rows typed that are no symbol yet (marked in the table): a project keeps them.
    const std::vector<model::PendingSymbol> &pending() const { return m_pending; }
    void setPending(const std::vector<model::PendingSymbol> &rows); // those of another project
    bool importCsv(const QString &path, QString *error);
    bool exportCsv(const QString &path, QString *error) const;

signals:
    void message(const QString &text); // why a typed device is no device
    void pendingChanged();             // the rows that are no symbol yet, unsaved work

protected:
    void changeEvent(QEvent *event) override;

private:
    void edited(int row);
    void setHeaders();

    editor::Document *m_document;
    bool m_updating = false;
    std::vector<model::PendingSymbol> m_pending;
};

} // namespace rung::app
