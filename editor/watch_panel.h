#pragma once

// The Watch dock: a field to add devices by typing ("X0", "D0..D15", "X0..X17, Y0") above the
// watch table (watch_list_view.h), which also takes devices dropped from the ladder and the
// cross reference.

#include "model/image/monitor_source.h"

#include <QWidget>

class QLineEdit;

namespace rung::editor {

class Document;
class WatchListView;

class WatchPanel : public QWidget {
    Q_OBJECT

public:
    explicit WatchPanel(Document *document, QWidget *parent = nullptr);

    WatchListView *view() const { return m_view; }
    QLineEdit *addField() const { return m_add; }
    void setMonitorSource(model::MonitorSource *source);

signals:
    void message(const QString &text);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void addTyped();

    Document *m_document;
    const model::Target *m_hintsTarget = nullptr; // whose devices the hints show
    WatchListView *m_view;
    QLineEdit *m_add;
};

} // namespace rung::editor
