#pragma once

// The symbol table as a table model: device, name and comment per row. The rows are the
// document's symbols, then the rows being typed that are no symbol yet (no device, or one the
// target does not have: PendingSymbol, kept with the project), then a free row for the next
// symbol. An edit of a cell reads the rows again: the complete ones are the document's new
// symbols (one undo step, "Edit symbols", when they changed), the others wait, marked
// (PendingRole; the device's tooltip says why); a typed row cleared of everything goes. The
// rows follow the document (undo, redo, another project) with the model's signals: a row that
// changed is a dataChanged, rows that come or go are inserted or removed at the end, so the
// cell being edited keeps its place.

#include "model/project/project.h"

#include <QAbstractTableModel>

#include <vector>

namespace rung::editor {

class Document;

class SymbolTableModel : public QAbstractTableModel {
    Q_OBJECT

public:
    enum Column { DeviceColumn, NameColumn, CommentColumn, ColumnCount };
    enum Role {
        PendingRole = Qt::UserRole + 1, // true on every cell of a row that is no symbol yet
    };

    explicit SymbolTableModel(Document *document, QObject *parent = nullptr);

    // The rows typed that are no symbol yet: a project keeps them.
    const std::vector<model::PendingSymbol> &pending() const { return m_pending; }
    // Those of another project (no pendingChanged: they are what it holds).
    void setPending(const std::vector<model::PendingSymbol> &rows);
    void refresh(); // the rows again from the document (its signals bring them too)
    // The headers and the reasons in the language now installed.
    void retranslate();

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

signals:
    void message(const QString &text); // why a device just typed is no device
    void pendingChanged();             // the rows that are no symbol yet, unsaved work

private:
    struct Row {
        QString cells[ColumnCount];
        bool pending = false;
        QString why; // a pending row's reason
        friend bool operator==(const Row &, const Row &) = default;
    };
    std::vector<Row> rows() const; // as the document and the pending rows have them now
    QString whyPending(const model::PendingSymbol &row) const;
    void sync(); // m_rows to rows(), with the model's signals
    void changed(int first, int last, const std::vector<Row> &now);

    Document *m_document;
    std::vector<model::PendingSymbol> m_pending;
    std::vector<Row> m_rows; // shown: the symbols, the pending rows, the free row
};

} // namespace rung::editor
