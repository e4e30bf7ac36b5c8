#pragma once

// The project's watch lists (devices the simulator and the online monitor show), in the
// project dock: each list with its devices and, while a MonitorSource is set, their live
// values. Adding and removing are undo steps of the document. The view does not know which
// origin (simulation or a PLC) feeds the source.

#include "model/image/monitor_source.h"

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
    explicit WatchListView(Document *document, QWidget *parent = nullptr);

    // Adds a device (as the target writes it) to the selected list, or to the first, which is
    // made when there is none; a device already there is not added twice.
    void addDevice(const QString &device);
    // Removes the selected device from its list.
    void removeSelected();

    // Shows the values of the source's snapshots in a second column (null: no column) and
    // tells the source which devices are watched.
    void setMonitorSource(model::MonitorSource *source);
    model::MonitorSource *monitorSource() const { return m_source; }

    // What the context menu offers for a device row while a source is set: a bit can be set,
    // reset, forced ON or OFF and released; a word, timer or counter takes a value typed in
    // the value column (Write Value..., F2 or a double-click); a timer or counter offers
    // nothing (the engine computes its current value). Empty for anything else.
    QList<QAction *> deviceActions(QTreeWidgetItem *item, QObject *parent);
    // Writes what the value column's text says to the row's device: ON/OFF or 1/0 for a
    // bit, a whole number for a word (decimal, or hexadecimal after 0x); false, with
    // message(), when the text is no value for the device.
    bool writeValue(QTreeWidgetItem *item, const QString &text);

signals:
    void message(const QString &text);

protected:
    void keyPressEvent(QKeyEvent *event) override;
    void changeEvent(QEvent *event) override; // LanguageChange: headers and values again
    void contextMenuEvent(QContextMenuEvent *event) override;

private:
    void refresh();
    void setTexts(); // the header and the accessible name, in the language installed
    void showValues();
    void tellWatched();
    QString valueText(const model::Snapshot &snapshot, const QString &device) const;
    int selectedList() const;
    std::optional<model::Address> addressOf(const QTreeWidgetItem *item) const;
    bool isBit(const model::Address &address) const;
    void editValue(QTreeWidgetItem *item); // a bit flips, a word opens the value cell
    // True, with message(), for a timer or counter (its current value cannot be written).
    bool refuseElement(const model::Address &address, const QString &device);

    Document *m_document;
    QPointer<model::MonitorSource> m_source;
    bool m_showing = false;               // the view writes the value column itself: not an edit
    QTreeWidgetItem *m_editing = nullptr; // whose value is being typed (editValue)
};

} // namespace rung::editor
