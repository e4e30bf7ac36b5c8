#include "watch_panel.h"

#include "device_mime.h"
#include "watch_list_view.h"

#include <QEvent>
#include <QLineEdit>
#include <QVBoxLayout>

namespace rung::editor {

WatchPanel::WatchPanel(Document *document, QWidget *parent)
    : QWidget(parent)
    , m_view(new WatchListView(document))
    , m_add(new QLineEdit) {
    setObjectName(QStringLiteral("watchPanel"));
    m_add->setObjectName(QStringLiteral("watchAdd"));
    m_add->setClearButtonEnabled(true);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(m_add);
    layout->addWidget(m_view, 1);
    connect(m_add, &QLineEdit::returnPressed, this, &WatchPanel::addTyped);
    connect(m_view, &WatchListView::message, this, &WatchPanel::message);
    retranslate();
}

void WatchPanel::retranslate() {
    m_add->setPlaceholderText(tr("Add: a device or a range (D0..D15), then Enter"));
    m_add->setToolTip(tr("Several at once with commas: X0, Y0, D0..D15. Devices can also be "
                         "dragged here from the ladder or the cross reference"));
}

void WatchPanel::changeEvent(QEvent *event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void WatchPanel::addTyped() {
    QMimeData typed;
    typed.setText(m_add->text());
    const QStringList parts = devicesFromMime(&typed);
    if (!parts.isEmpty() && m_view->addDevices(parts))
        m_add->clear(); // what was refused stays, to be corrected
}

void WatchPanel::setMonitorSource(model::MonitorSource *source) {
    m_view->setMonitorSource(source);
}

} // namespace rung::editor
