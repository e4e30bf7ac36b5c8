#pragma once

// The project's watch lists as a live table (the Watch dock): each list with its devices,
// their symbols, the value (a word in the row's format: decimal, signed, hexadecimal, binary
// or BCD, saved with the project), and whether a bit is forced. While a MonitorSource is set
// the values follow its snapshots; a value typed in the value column is written, the force
// column forces and releases. Devices come in by typing (WatchPanel), by a drop of devices
// (from the ladder, the cross reference) or a range ("D0..D15"). Adding, removing and
// changing a format are undo steps of the document. The view does not know which origin
// (simulation or a PLC) feeds the source.

#include "model/image/monitor_source.h"
#include "model/image/value_format.h"
#include "model/listing/il.h"

#include <QHash>
#include <QList>
#include <QPointer>
#include <QTreeWidget>

#include <optional>

class QAction;

namespace rung::editor {

class Document;

class WatchListView : public QTreeWidget {
    Q_OBJECT

public:
    enum Column { DeviceColumn, SymbolColumn, ValueColumn, FormatColumn, ForceColumn, Columns };

    explicit WatchListView(Document *document, QWidget *parent = nullptr);

    // Adds a device (as the target writes it) to the selected list, or to the first, which is
    // made when there is none; a device already there is not added twice.
    void addDevice(const QString &device);
    // Adds devices and ranges ("X0, D0..D15", "X0..X17") as one undo step; false, with
    // message() naming what is wrong and nothing added, when a part is no device or range.
    bool addDevices(const QStringList &texts);
    // Removes the selected devices from their lists.
    void removeSelected();
    // How a row's word value is shown (saved with the project, one undo step).
    void setFormat(QTreeWidgetItem *item, model::ValueFormat format);
    model::ValueFormat format(const QTreeWidgetItem *item) const;

    // Shows the values of the source's snapshots (null: the value column stays empty) and
    // tells the source which devices are watched.
    void setMonitorSource(model::MonitorSource *source);
    model::MonitorSource *monitorSource() const { return m_source; }

    // What the context menu offers for a device row while a source is set: a bit can be set,
    // reset, forced ON or OFF and released; a word takes a value typed in the value column
    // (Write Value..., F2 or a double-click); a timer or counter offers nothing (the engine
    // computes its current value). Empty for anything else.
    QList<QAction *> deviceActions(QTreeWidgetItem *item, QObject *parent);
    // Writes what the value column's text says to the row's device: ON/OFF or 1/0 for a
    // bit, a value in the row's format for a word; false, with message(), when the text is
    // no value for the device.
    bool writeValue(QTreeWidgetItem *item, const QString &text);
    // The devices of the selected rows, as the target writes them.
    QStringList selectedDevices() const;
    // What a drop at this viewport position does: the devices (or ranges) the data carries
    // go into the list under it (or the selected one); false when it carries none or one is
    // no device.
    bool dropDevices(const QMimeData *data, const QPoint &at);

signals:
    void message(const QString &text);

protected:
    void keyPressEvent(QKeyEvent *event) override;
    void changeEvent(QEvent *event) override; // LanguageChange: headers and values again
    void contextMenuEvent(QContextMenuEvent *event) override;
    void dragEnterEvent(QDragEnterEvent *event) override;
    void dragMoveEvent(QDragMoveEvent *event) override;
    void dropEvent(QDropEvent *event) override;
    QMimeData *mimeData(const QList<QTreeWidgetItem *> &items) const override;
    QStringList mimeTypes() const override;

private:
    void refresh();
    void setTexts(); // the header and the accessible name, in the language installed
    void showValues();
    void tellWatched();
    void showRow(QTreeWidgetItem *item, const model::Snapshot *snapshot);
    int selectedList() const;
    std::optional<model::Address> addressOf(const QTreeWidgetItem *item) const;
    bool isBit(const model::Address &address) const;
    int bitsOf(const model::Address &address) const;
    void editValue(QTreeWidgetItem *item); // a bit flips, a word opens the value cell
    void chooseFormat(QTreeWidgetItem *item);
    void chooseForce(QTreeWidgetItem *item);
    // True, with message(), for a timer or counter (its current value cannot be written).
    bool refuseElement(const model::Address &address, const QString &device);

    Document *m_document;
    QPointer<model::MonitorSource> m_source;
    bool m_showing = false;               // the view writes the value column itself: not an edit
    QTreeWidgetItem *m_editing = nullptr; // whose value is being typed (editValue)
    // The program's timer and counter boxes of the rows (their constant presets), from the
    // instructions held here.
    std::shared_ptr<const std::vector<model::Instruction>> m_program;
    QHash<const QTreeWidgetItem *, const model::Instruction *> m_boxes;
};

} // namespace rung::editor
