#pragma once

// The project's symbol table, edited in place: device, name and comment per row. Rows being
// typed that are no symbol yet (no device, or one the target does not have) stay in the table,
// after the symbols, marked, until complete or cleared. CSV import and export.

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

    void refresh();     // from the document's symbols and the rows being typed
    void dropPending(); // the half-typed rows belong to a program that goes
    bool importCsv(const QString &path, QString *error);
    bool exportCsv(const QString &path, QString *error) const;

signals:
    void message(const QString &text); // why a typed device is no device

protected:
    void changeEvent(QEvent *event) override;

private:
    void edited(int row);
    void setHeaders();

    editor::Document *m_document;
    bool m_updating = false;
    struct PendingSymbol {
        QString device, name, comment;
    };
    std::vector<PendingSymbol> m_pending;
};

} // namespace rung::app
