#pragma once

// The project's watch lists (devices the simulator and the online monitor will show), in the
// project dock: each list with its devices. Adding and removing are undo steps of the
// document.

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

protected:
    void keyPressEvent(QKeyEvent *event) override;

private:
    void refresh();
    int selectedList() const;

    Document *m_document;
};

} // namespace rung::editor
