#pragma once

// The project's watch lists as an item model (the Watch dock draws it: watch_list_view.h).
// Each list is a top-level row with its devices under it; the columns are the device, its
// symbol, the value (a word in the row's format: decimal, signed, hexadecimal, binary or BCD,
// saved with the project), the format and whether a bit is forced. While a MonitorSource is
// set the values follow its snapshots: a snapshot changes the value and force columns
// (dataChanged), never the rows. The rows follow the document: an edit, an undo or a redo
// inserts and removes the rows that changed, and only another target resets the model.
// Adding, removing and changing a format are undo steps of the document; a value set in the
// value column is written through the source. The model does not know which origin
// (simulation or a PLC) feeds the source.

#include "model/image/monitor_source.h"
#include "model/image/value_format.h"
#include "model/listing/il.h"

#include <QAbstractItemModel>
#include <QPointer>
#include <QStringList>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace rung::model {
struct WatchList;
}

namespace rung::editor {

class Document;

class WatchListModel : public QAbstractItemModel {
    Q_OBJECT

public:
    enum Column { DeviceColumn, SymbolColumn, ValueColumn, FormatColumn, ForceColumn, Columns };
    enum Role {
        // bool: the row's device is forced (a view draws its value and force cells bold).
        ForcedRole = Qt::UserRole + 1,
    };

    explicit WatchListModel(Document *document, QObject *parent = nullptr);

    QModelIndex index(int row, int column, const QModelIndex &parent = {}) const override;
    QModelIndex parent(const QModelIndex &child) const override;
    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    // The value column writes what the text says (writeValue); the row keeps showing what the
    // source holds, never the text set.
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;
    // Device rows drag out as devices (editor/device_mime.h), in the table's order; devices
    // (or ranges) dropped on a list, or on one of its rows, are added to that list.
    QStringList mimeTypes() const override;
    QMimeData *mimeData(const QModelIndexList &indexes) const override;
    bool canDropMimeData(const QMimeData *data, Qt::DropAction action, int row, int column,
                         const QModelIndex &parent) const override;
    bool dropMimeData(const QMimeData *data, Qt::DropAction action, int row, int column,
                      const QModelIndex &parent) override;
    Qt::DropActions supportedDropActions() const override { return Qt::CopyAction; }
    Qt::DropActions supportedDragActions() const override { return Qt::CopyAction; }

    // Values from the source's snapshots (null: the value and force columns stay empty); the
    // source learns which devices are watched.
    void setMonitorSource(model::MonitorSource *source);
    model::MonitorSource *monitorSource() const { return m_source; }

    // What a row is: a list (the index of a top-level row), a device row of a list.
    bool isDevice(const QModelIndex &index) const;
    int listOf(const QModelIndex &index) const;     // -1 for an invalid index
    QString device(const QModelIndex &index) const; // as the target writes it; empty for a list
    std::optional<model::Address> address(const QModelIndex &index) const;
    bool isBit(const QModelIndex &index) const;
    // A timer's or counter's current value: the scan engine computes it, it cannot be written.
    bool isElement(const QModelIndex &index) const;

    // How a row's word value is shown (saved with the project; setFormat is one undo step).
    model::ValueFormat format(const QModelIndex &index) const;
    void setFormat(const QModelIndex &index, model::ValueFormat format);

    // Adds devices and ranges ("X0, D0..D15", "X0..X17") to list `list` (the first when out of
    // range; one named "Watch 1" is made when there is none) as one undo step; a device there
    // already is not added twice. False, with message() naming what is wrong and nothing
    // added, when a part is no device or range.
    bool addDevices(const QStringList &texts, int list = 0);
    // Removes these device rows (any column) from their lists, as one undo step.
    void removeDevices(const QModelIndexList &indexes);

    // True when a value can be written to the row's device now: a source is set and the row
    // is a device; false, with message() saying why, for a timer or counter.
    bool checkWritable(const QModelIndex &index);
    // Writes what the text says to the row's device: ON/OFF or 1/0 for a bit, a value in the
    // row's format for a word; false, with message(), when the text is no value for it.
    bool writeValue(const QModelIndex &index, const QString &text);
    // Writes the opposite of what the latest snapshot holds to a bit row's device.
    bool flipBit(const QModelIndex &index);

    // The headers and the texts in the language now installed.
    void retranslate();

signals:
    void message(const QString &text);

private:
    struct Row {
        QString device;
        std::optional<model::Address> address;
        // Derived from the project: the symbol, the format shown, the program's timer or
        // counter box of the device (its constant preset).
        QString symbol;
        QString comment;
        model::ValueFormat format = model::ValueFormat::Decimal;
        const model::Instruction *box = nullptr;
    };
    struct List {
        QString name;
        std::vector<Row> rows;
    };

    void follow(); // the document changed
    void followRows(int list, const model::WatchList &now);
    // Turns the rows under `parent`, named `before`, into the rows named `after`: the rows of
    // a longest common subsequence stay (a view keeps their selection and expansion), the
    // others are removed in runs from the end, then the new ones inserted in runs from the
    // start, each run with its signals; remove(first, last) and insert(first, last) change
    // the rows themselves.
    void patch(const QModelIndex &parent, const QStringList &before, const QStringList &after,
               const std::function<void(int, int)> &remove,
               const std::function<void(int, int)> &insert);
    Row makeRow(const QString &device) const;
    void derive(Row &row, const model::WatchList &list) const;
    void tellWatched(bool always = false);
    void valuesChanged(); // the value and force columns of every device row
    const Row *rowAt(const QModelIndex &index) const;
    std::shared_ptr<const model::Snapshot> snapshot() const; // the source's, of our target
    QString valueText(const Row &row, const model::Snapshot &snapshot) const;
    bool isBit(const model::Address &address) const;
    bool isElement(const model::Address &address) const;
    int bitsOf(const model::Address &address) const;
    bool refuseElement(const Row &row);

    Document *m_document;
    const model::Target *m_target = nullptr;
    QPointer<model::MonitorSource> m_source;
    std::vector<List> m_lists;
    // The instructions the rows' boxes point into, kept alive here.
    std::shared_ptr<const std::vector<model::Instruction>> m_program;
    std::vector<model::Address> m_told; // what the source was told is watched
};

} // namespace rung::editor
