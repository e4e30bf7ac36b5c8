#pragma once

// The Watch dock's table: a view over the project's watch lists (watch_list_model.h), each
// list with its devices, their symbols, the value in the row's format and whether a bit is
// forced. The view is the interaction: a double-click or F2 writes a value (a bit flips), the
// format and force columns open their choices, the context menu sets, forces and releases,
// Delete removes, devices are dropped in (from the ladder, the cross reference) and rows
// dragged out (to the timing chart). Devices also come in by typing (WatchPanel). The view
// does not know which origin (simulation or a PLC) feeds the source.

#include "watch_list_model.h"

#include <QTreeView>

class QAction;

namespace rung::editor {

class Document;

class WatchListView : public QTreeView {
    Q_OBJECT

public:
    using Column = WatchListModel::Column;
    using enum WatchListModel::Column;

    explicit WatchListView(Document *document, QWidget *parent = nullptr);

    WatchListModel *watchModel() const { return m_model; }

    // Adds a device (as the target writes it) to the selected list, or to the first, which is
    // made when there is none; a device already there is not added twice.
    void addDevice(const QString &device);
    // Adds devices and ranges ("X0, D0..D15", "X0..X17") to the selected list as one undo
    // step; false, with message() naming what is wrong and nothing added, when a part is no
    // device or range.
    bool addDevices(const QStringList &texts);
    // Removes the selected devices (else the current one) from their lists.
    void removeSelected();
    // How a row's word value is shown (saved with the project, one undo step).
    void setFormat(const QModelIndex &index, model::ValueFormat format);
    model::ValueFormat format(const QModelIndex &index) const;

    // Shows the values of the source's snapshots (null: the value column stays empty) and
    // tells the source which devices are watched.
    void setMonitorSource(model::MonitorSource *source);
    model::MonitorSource *monitorSource() const { return m_model->monitorSource(); }

    // What the context menu offers for a device row while a source is set: a bit can be set,
    // reset, forced ON or OFF and released; a word takes a value typed in the value column
    // (Write Value..., F2 or a double-click); a timer or counter offers nothing (the engine
    // computes its current value). Empty for anything else.
    QList<QAction *> deviceActions(const QModelIndex &index, QObject *parent);
    // Writes what the text says to the row's device (WatchListModel::writeValue).
    bool writeValue(const QModelIndex &index, const QString &text);
    // The devices of the selected rows, as the target writes them, in the table's order.
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
    void rowsInserted(const QModelIndex &parent, int first, int last) override;
    void reset() override;

private:
    void showLists(int first, int last); // spanned and expanded
    int selectedList() const;
    void editValue(const QModelIndex &index); // a bit flips, a word opens the value cell
    void chooseFormat(const QModelIndex &index);
    void chooseForce(const QModelIndex &index);
    void addFormats(QMenu *menu, const QModelIndex &index);

    WatchListModel *m_model;
};

} // namespace rung::editor
