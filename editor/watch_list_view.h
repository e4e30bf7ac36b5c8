#pragma once

// The project's watch lists (devices the simulator and the online monitor show), in the
// project dock: each list with its devices and, while a MonitorSource is set, their live
// values. Adding and removing are undo steps of the document. The view does not know which
// origin (simulation or a PLC) feeds the source.

#include "model/image/monitor_source.h"

#include <QPointer>
#include <QTreeWidget>

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

protected:
    void keyPressEvent(QKeyEvent *event) override;
    void changeEvent(QEvent *event) override; // LanguageChange: headers and values again

private:
    void refresh();
    void setTexts(); // the header and the accessible name, in the language installed
    void showValues();
    void tellWatched();
    QString valueText(const model::Snapshot &snapshot, const QString &device) const;
    int selectedList() const;

    Document *m_document;
    QPointer<model::MonitorSource> m_source;
};

} // namespace rung::editor
