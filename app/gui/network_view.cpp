#include "app/gui/network_view.h"

#include "app/gui/network_bridge_dialog.h"
#include "app/gui/network_canvas.h"
#include "app/gui/network_document.h"
#include "app/gui/network_port_dialog.h"
#include "app/gui/network_station_dialog.h"

#include "model/comm/port_config.h"
#include "model/target/target.h"

#include <QApplication>
#include <QClipboard>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMenu>
#include <QMessageBox>
#include <QResizeEvent>
#include <QScrollBar>
#include <QWheelEvent>

#include <algorithm>

namespace rung::app {

NetworkView::NetworkView(NetworkDocument *document, QWidget *parent)
    : QScrollArea(parent)
    , m_document(document)
    , m_canvas(new NetworkCanvas(this)) {
    setWidget(m_canvas);
    setWidgetResizable(false);
    setFocusPolicy(Qt::StrongFocus);
    setBackgroundRole(QPalette::Base);
    connect(document, &NetworkDocument::changed, this, [this] {
        // What was selected may be gone (undo of an add, a removed station).
        if (!m_selection.isEmpty() && !m_selection.startsWith(QLatin1String("wire:")) &&
            !m_document->station(m_selection.section(QLatin1Char('/'), 0, 0))) {
            bool device = false;
            for (const auto &v : m_document->description().devices)
                device = device || v.name == m_selection;
            if (!device)
                select({});
        }
        m_canvas->relayout();
    });
    connect(document, &NetworkDocument::filePathChanged, this, [this] { m_canvas->relayout(); });
    m_canvas->relayout();
}

double NetworkView::textWidth() const {
    const int bar = verticalScrollBar()->sizeHint().width();
    return std::max(0, width() - 2 * frameWidth() - bar) / m_zoom;
}

void NetworkView::resizeEvent(QResizeEvent *event) {
    QScrollArea::resizeEvent(event);
    if (event->oldSize().width() != event->size().width())
        m_canvas->relayout(); // the description wraps to the new width
}

QWidget *NetworkView::canvas() const {
    return m_canvas;
}

void NetworkView::setZoom(double zoom) {
    m_zoom = std::clamp(zoom, 0.5, 3.0);
    m_canvas->relayout();
}

void NetworkView::zoomIn() {
    setZoom(m_zoom * 1.25);
}
void NetworkView::zoomOut() {
    setZoom(m_zoom / 1.25);
}

void NetworkView::select(const QString &item) {
    if (item == m_selection)
        return;
    m_selection = item;
    m_canvas->update();
    emit selectionChanged(item);
    const QString station = selectedStation();
    if (!station.isEmpty() || item.isEmpty())
        emit stationSelected(station);
}

QString NetworkView::selectedStation() const {
    const QString name = m_selection.section(QLatin1Char('/'), 0, 0);
    return !m_selection.startsWith(QLatin1String("wire:")) && m_document->station(name) ? name
                                                                                        : QString();
}

QRect NetworkView::itemRect(const QString &item) const {
    for (const auto &box : m_canvas->layout().boxes)
        if (box.name == item)
            return QRectF(box.rect.topLeft() * m_zoom, box.rect.size() * m_zoom).toRect();
    return {};
}

QPoint NetworkView::endPoint(const QString &end) const {
    for (const auto &box : m_canvas->layout().boxes)
        for (const auto &row : box.rows)
            if (row.end == end)
                return (row.rect.center() * m_zoom).toPoint();
    return {-1, -1};
}

QString NetworkView::itemAt(const QPoint &canvasPoint) const {
    return m_canvas->itemAt(QPointF(canvasPoint) / m_zoom);
}

void NetworkView::refuse(const QString &why) {
    emit editRefused(why);
    if (!m_quiet)
        QMessageBox::warning(this, tr("Network"), why);
}

void NetworkView::removeSelected(bool confirm) {
    QString why;
    if (m_selection.startsWith(QLatin1String("wire:"))) {
        if (!m_document->removeWire(m_selection.mid(5), &why))
            refuse(why);
        return;
    }
    if (m_selection.contains(QLatin1Char('/'))) {
        if (!m_document->disconnectEnd(m_selection, &why))
            refuse(why);
        return;
    }
    if (!m_document->station(m_selection)) {
        if (!m_selection.isEmpty())
            refuse(tr("%1 is a simulated device: edit it in the network file").arg(m_selection));
        return;
    }
    const QStringList also = m_document->removalConsequences(m_selection);
    if (confirm && !also.isEmpty() &&
        QMessageBox::question(
            this, tr("Remove Station"),
            tr("Remove station %1? With it:\n%2\n(Edit > Undo brings it back.)")
                .arg(m_selection, QStringLiteral("- ") + also.join(QStringLiteral("\n- "))),
            QMessageBox::Yes | QMessageBox::Cancel) != QMessageBox::Yes)
        return;
    if (!m_document->removeStation(m_selection, &why))
        refuse(why);
}

void NetworkView::editPort(const QString &end) {
    const QString station = end.section(QLatin1Char('/'), 0, 0);
    const QString port = end.section(QLatin1Char('/'), 1);
    const auto *s = m_document->station(station);
    if (!s)
        return;
    const NetworkStationInfo info = m_document->stationInfo(station);
    const auto edited =
        editPortSettings(this, *info.target, info.model, port, s->ports.value(port).toObject(),
                         info.projectPorts.value(port).toObject(), end);
    QString why;
    if (edited && !m_document->setPortSettings(station, port, *edited, &why))
        refuse(why);
}

void NetworkView::addStationFromProgram() {
    const QString file = QFileDialog::getOpenFileName(
        this, tr("Add Station from Program"), QFileInfo(m_document->filePath()).absolutePath(),
        tr("Programs (*.rung *.il *.ladder);;All files (*)"));
    if (file.isEmpty())
        return;
    QString why;
    const QString name = m_document->freeName(QFileInfo(file).completeBaseName());
    if (!m_document->addExistingProgram(name, file, QString(), QString(), &why))
        refuse(why);
    else
        select(name);
}

void NetworkView::addNewProjectStation() {
    NetworkStationDialog dialog(m_document, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    QString why;
    if (!m_document->addNewProject(dialog.name(), dialog.file(), dialog.target(), dialog.model(),
                                   &why))
        refuse(why);
    else
        select(dialog.name());
}

void NetworkView::editPeriod() {
    bool ok = false;
    const int ms = QInputDialog::getInt(
        this, tr("Network Period"), tr("Scan period of the stations that give none (ms):"),
        int(m_document->description().periodMs), 1, 1000000, 1, &ok);
    QString why;
    if (ok && !m_document->setPeriod(ms, &why))
        refuse(why);
}

QString NetworkView::bridgeText(const QString &end) const {
    const network::BridgeDescription *b = m_document->bridgeOf(end);
    if (!b)
        return {};
    using K = network::BridgeDescription::Kind;
    const auto live = m_live.find(end);
    const QString reached = live == m_live.end() ? QString() : live->second.reached;
    if (live != m_live.end() && !live->second.error.isEmpty())
        //: a bridge whose line did not open; the tooltip says why
        return tr("bridge: failed (%1)").arg(b->kind == K::Pty ? tr("pseudo-terminal") : b->where);
    switch (b->kind) {
    case K::Pty:
        //: %1 the pseudo-terminal's path while the network runs
        return reached.isEmpty() ? tr("bridge: pseudo-terminal")
                                 : tr("bridge: pseudo-terminal %1").arg(reached);
    case K::Serial:
        return tr("bridge: serial %1").arg(b->where);
    case K::Tcp:
        return tr("bridge: TCP to %1").arg(b->where);
    case K::Listen:
        return tr("bridge: listens on %1").arg(reached.isEmpty() ? b->where : reached);
    }
    return {};
}

void NetworkView::setLiveBridges(std::map<QString, LiveBridge> live) {
    if (live.size() == m_live.size() &&
        std::equal(live.begin(), live.end(), m_live.begin(), [](const auto &a, const auto &b) {
            return a.first == b.first && a.second.reached == b.second.reached &&
                   a.second.error == b.second.error;
        }))
        return;
    m_live = std::move(live);
    m_canvas->relayout();
}

void NetworkView::editBridge(const QString &end,
                             std::optional<network::BridgeDescription::Kind> kind) {
    const QString station = end.section(QLatin1Char('/'), 0, 0);
    const QString port = end.section(QLatin1Char('/'), 1);
    const auto *s = m_document->station(station);
    if (!s)
        return;
    const NetworkStationInfo info = m_document->stationInfo(station);
    model::PortConfig config;
    QString why;
    if (!model::readPortConfig(*info.target, info.target->model(info.model), port,
                               {{m_document->effectivePortSettings(station, port), end}}, &config,
                               &why)) {
        refuse(why);
        return;
    }
    network::BridgeDescription bridge;
    bridge.end = end;
    if (const network::BridgeDescription *b = m_document->bridgeOf(end))
        bridge = *b;
    NetworkBridgeDialog dialog(bridge, *config.application, config.line,
                               s->ports.value(port).toObject(), this);
    if (kind)
        dialog.setKind(*kind);
    if (dialog.exec() != QDialog::Accepted)
        return;
    if (!m_document->setBridge(dialog.bridge(), dialog.portSettings(), &why))
        refuse(why);
}

void NetworkView::removeBridge(const QString &end) {
    QString why;
    if (!m_document->removeBridge(end, &why))
        refuse(why);
}

void NetworkView::addBridgeMenu(QMenu *menu, const QString &end) {
    using K = network::BridgeDescription::Kind;
    QMenu *bridges = menu->addMenu(tr("&Bridge To"));
    bridges->setObjectName(QStringLiteral("networkBridgeTo"));
    // A pseudo-terminal needs nothing more; the others ask where (network_bridge_dialog.h).
    bridges->addAction(tr("&Pseudo-terminal"), this, [this, end] {
        network::BridgeDescription b;
        b.end = end;
        QString why;
        if (!m_document->addBridge(b, &why))
            refuse(why);
    });
    bridges->addAction(tr("&Serial Port..."), this, [this, end] { editBridge(end, K::Serial); });
    bridges->addAction(tr("&TCP Device Server..."), this, [this, end] { editBridge(end, K::Tcp); });
    bridges->addAction(tr("TCP &Listen..."), this, [this, end] { editBridge(end, K::Listen); });
}

void NetworkView::contextMenuAt(const QPoint &canvasPoint, const QPoint &global) {
    const QString item = m_canvas->itemAt(canvasPoint);
    select(item);
    QMenu menu(this);
    const QString station = selectedStation();
    QString why;
    if (item.contains(QLatin1Char('/'))) {
        menu.addAction(tr("Port &Settings..."), this, [this, item] { editPort(item); });
        if (m_document->wireOf(item))
            menu.addAction(tr("&Disconnect"), this, [this, item] {
                QString why;
                if (!m_document->disconnectEnd(item, &why))
                    refuse(why);
            });
        bool bridged = false;
        for (const auto &b : m_document->description().bridges)
            bridged = bridged || b.end == item;
        if (bridged) {
            menu.addAction(tr("Edit &Bridge..."), this, [this, item] { editBridge(item); });
            if (const auto live = m_live.find(item);
                live != m_live.end() && !live->second.reached.isEmpty())
                menu.addAction(tr("&Copy %1").arg(live->second.reached), this,
                               [reached = live->second.reached] {
                                   QApplication::clipboard()->setText(reached);
                               });
            menu.addAction(tr("Remove Brid&ge"), this, [this, item] { removeBridge(item); });
        } else {
            addBridgeMenu(&menu, item);
        }
        menu.addSeparator();
    }
    if (item.startsWith(QLatin1String("wire:")))
        menu.addAction(tr("Remove &Wire"), this, [this] { removeSelected(); });
    if (!station.isEmpty()) {
        menu.addAction(tr("&Open Program"), this,
                       [this, station] { emit stationActivated(station); });
        menu.addAction(tr("&Remove Station %1...").arg(station), this, [this, station] {
            select(station);
            removeSelected();
        });
        menu.addSeparator();
    }
    menu.addAction(tr("Add Station from &Program..."), this, &NetworkView::addStationFromProgram);
    menu.addAction(tr("Add New Pro&ject Station..."), this, &NetworkView::addNewProjectStation);
    menu.addAction(tr("&Network Period..."), this, &NetworkView::editPeriod);
    menu.addSeparator();
    menu.addAction(tr("Zoom &In"), this, &NetworkView::zoomIn);
    menu.addAction(tr("Zoom O&ut"), this, &NetworkView::zoomOut);
    menu.exec(global);
}

void NetworkView::changeEvent(QEvent *event) {
    if (event->type() == QEvent::LanguageChange)
        m_canvas->relayout();
    QScrollArea::changeEvent(event);
}

void NetworkView::keyPressEvent(QKeyEvent *event) {
    const bool ctrl = event->modifiers() & Qt::ControlModifier;
    if (event->key() == Qt::Key_Delete || event->key() == Qt::Key_Backspace) {
        removeSelected();
    } else if ((event->key() == Qt::Key_Return || event->key() == Qt::Key_Enter) &&
               !selectedStation().isEmpty()) {
        emit stationActivated(selectedStation());
    } else if (ctrl && (event->key() == Qt::Key_Plus || event->key() == Qt::Key_Equal)) {
        zoomIn();
    } else if (ctrl && event->key() == Qt::Key_Minus) {
        zoomOut();
    } else if (ctrl && event->key() == Qt::Key_0) {
        setZoom(1.0);
    } else {
        QScrollArea::keyPressEvent(event);
        return;
    }
    event->accept();
}

void NetworkView::wheelEvent(QWheelEvent *event) {
    if (event->modifiers() & Qt::ControlModifier) {
        if (event->angleDelta().y() > 0)
            zoomIn();
        else if (event->angleDelta().y() < 0)
            zoomOut();
        event->accept();
        return;
    }
    QScrollArea::wheelEvent(event);
}

bool saveNetwork(QWidget *parent, NetworkDocument *document, const QString &file) {
    const QString to = file.isEmpty() ? document->filePath() : file;
    QStringList notKept;
    QString why;
    if (file.isEmpty() ? document->save(&notKept, &why) : document->saveAs(to, &notKept, &why))
        return true;
    if (!notKept.isEmpty()) {
        // Never write less than the user has without saying so and letting them choose.
        const auto answer = QMessageBox::warning(
            parent, NetworkView::tr("Save Network"),
            NetworkView::tr("%1 cannot hold everything in this network:\n%2\n\nSave anyway, "
                            "leaving this out of the file?")
                .arg(to, QStringLiteral("- ") + notKept.join(QStringLiteral("\n- "))),
            QMessageBox::Save | QMessageBox::Cancel, QMessageBox::Cancel);
        if (answer != QMessageBox::Save)
            return false;
        if (document->saveAs(to, &notKept, &why, true))
            return true;
    }
    QMessageBox::critical(parent, NetworkView::tr("Save Network"), why);
    return false;
}

} // namespace rung::app
