#include "watch_panel.h"

#include "device_mime.h"
#include "document.h"
#include "watch_list_view.h"

#include "model/target/target_lists.h"

#include <QEvent>
#include <QLineEdit>
#include <QVBoxLayout>

namespace rung::editor {

WatchPanel::WatchPanel(Document *document, QWidget *parent)
    : QWidget(parent)
    , m_document(document)
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
    connect(document, &Document::programChanged, this, [this] {
        if (&m_document->target() != m_hintsTarget)
            retranslate(); // another family: the hints' examples are its devices
    });
    retranslate();
}

void WatchPanel::retranslate() {
    const model::Target &target = m_document->target();
    m_hintsTarget = &target;
    const QString range = model::exampleWordRange(target, 16);
    m_add->setPlaceholderText(tr("Add: a device or a range (%1), then Enter").arg(range));
    m_add->setToolTip(
        tr("Several at once with commas: %1, %2, %3. Devices can also be "
           "dragged here from the ladder or the cross reference")
            .arg(model::exampleDevice(target), model::exampleDevice(target, true), range));
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
