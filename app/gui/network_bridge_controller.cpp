#include "app/gui/network_bridge_controller.h"

#include "app/gui/network_document.h"
#include "app/gui/network_view.h"

#include "network/network_session.h"

#include <QApplication>
#include <QClipboard>
#include <QDockWidget>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMainWindow>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>

namespace rung::app {

namespace {

using BridgeKind = network::BridgeDescription::Kind;

QString bridgeTitle(const network::BridgeDescription &b) {
    //: %1 a station's port ("s5/CP2"); the rest what its bridge goes to
    switch (b.kind) {
    case BridgeKind::Pty:
        return NetworkBridgeController::tr("%1: pseudo-terminal").arg(b.end);
    case BridgeKind::Serial:
        return NetworkBridgeController::tr("%1: serial port %2").arg(b.end, b.where);
    case BridgeKind::Tcp:
        return NetworkBridgeController::tr("%1: TCP to %2").arg(b.end, b.where);
    case BridgeKind::Listen:
        return NetworkBridgeController::tr("%1: listens on %2").arg(b.end, b.where);
    }
    return b.end;
}

} // namespace

NetworkBridgeController::NetworkBridgeController(NetworkDocument *document, NetworkView *view,
                                                 QMainWindow *window)
    : QObject(window)
    , m_document(document)
    , m_view(view)
    , m_lines(std::make_shared<network::BridgeLines>()) {
    m_dock = new QDockWidget(window);
    m_dock->setObjectName(QStringLiteral("networkBridgesDock"));
    auto *scroll = new QScrollArea(m_dock);
    scroll->setWidgetResizable(true);
    m_panel = new QWidget(scroll);
    m_panel->setObjectName(QStringLiteral("networkBridges"));
    m_rows = new QVBoxLayout(m_panel);
    scroll->setWidget(m_panel);
    m_dock->setWidget(scroll);
    m_dock->installEventFilter(this);
    connect(m_document, &NetworkDocument::changed, this, &NetworkBridgeController::refresh);
    refresh();
}

NetworkBridgeController::~NetworkBridgeController() = default;

bool NetworkBridgeController::eventFilter(QObject *watched, QEvent *event) {
    if (watched == m_dock && event->type() == QEvent::LanguageChange)
        refresh();
    return QObject::eventFilter(watched, event);
}

void NetworkBridgeController::setSession(network::NetworkSession *session) {
    if (m_session)
        disconnect(m_session, nullptr, this, nullptr);
    m_session = session;
    if (session) {
        connect(session, &network::NetworkSession::bridgesChanged, this, [this] {
            refresh();
            emit bridgesChanged();
        });
        // Also without bridges: the lines of those removed close.
        session->startBridges(m_lines);
    }
    refresh();
}

const network::BridgeStatus *NetworkBridgeController::status(const QString &end) const {
    if (!m_session)
        return nullptr;
    for (const network::BridgeStatus &s : m_session->bridgeStatus())
        if (s.bridge.end == end)
            return &s;
    return nullptr;
}

QString NetworkBridgeController::reached(const QString &end) const {
    const network::BridgeStatus *s = status(end);
    return s && s->open ? s->reached : QString();
}

QString NetworkBridgeController::error(const QString &end) const {
    const network::BridgeStatus *s = status(end);
    return s ? s->error : QString();
}

bool NetworkBridgeController::copyReached(const QString &end) {
    const QString where = reached(end);
    if (where.isEmpty())
        return false;
    QApplication::clipboard()->setText(where);
    emit message(tr("Copied %1: where %2 is reached").arg(where, end));
    return true;
}

void NetworkBridgeController::refresh() {
    m_dock->setWindowTitle(tr("Bridges"));
    // The rows again: a few bridges at most, each a title, where it is reached and its state.
    while (QLayoutItem *item = m_rows->takeAt(0)) {
        // Later: the button whose click brought us here may be one of them.
        if (QWidget *w = item->widget()) {
            w->setParent(nullptr);
            w->deleteLater();
        }
        delete item;
    }
    const auto &bridges = m_document->description().bridges;
    std::map<QString, NetworkView::LiveBridge> live;
    if (bridges.empty()) {
        auto *none = new QLabel(tr("No bridge: right-click a station's port in the Network view "
                                   "and choose Bridge To to put it on a pseudo-terminal, a "
                                   "serial port or TCP."),
                                m_panel);
        none->setWordWrap(true);
        m_rows->addWidget(none);
    }
    for (const network::BridgeDescription &b : bridges) {
        const network::BridgeStatus *s = status(b.end);
        // The session runs the bridges it was built with: an edit waits for Stop.
        const bool current = s && s->bridge.kind == b.kind && s->bridge.where == b.where;
        auto *row = new QWidget(m_panel);
        row->setObjectName(QStringLiteral("bridgeRow_") + b.end);
        auto *rowLayout = new QVBoxLayout(row);
        rowLayout->setContentsMargins(0, 0, 0, 6);
        auto *title = new QLabel(bridgeTitle(b), row);
        title->setStyleSheet(QStringLiteral("QLabel { font-weight: bold; }"));
        title->setWordWrap(true);
        rowLayout->addWidget(title);
        auto *line = new QHBoxLayout;
        auto *where = new QLineEdit(row);
        where->setObjectName(QStringLiteral("bridgeReached_") + b.end);
        where->setReadOnly(true);
        where->setText(current && s->open ? s->reached : QString());
        where->setPlaceholderText(tr("not open"));
        auto *copy = new QPushButton(tr("Copy"), row);
        copy->setObjectName(QStringLiteral("bridgeCopy_") + b.end);
        copy->setToolTip(tr("Copy where the bridge is reached to the clipboard"));
        copy->setEnabled(current && s->open);
        connect(copy, &QPushButton::clicked, this, [this, end = b.end] { copyReached(end); });
        auto *edit = new QPushButton(tr("Edit..."), row);
        edit->setObjectName(QStringLiteral("bridgeEdit_") + b.end);
        connect(edit, &QPushButton::clicked, m_view,
                [view = m_view, end = b.end] { view->editBridge(end); });
        auto *remove = new QPushButton(tr("Remove"), row);
        remove->setObjectName(QStringLiteral("bridgeRemove_") + b.end);
        connect(remove, &QPushButton::clicked, m_view,
                [view = m_view, end = b.end] { view->removeBridge(end); });
        line->addWidget(where, 1);
        line->addWidget(copy);
        rowLayout->addLayout(line);
        auto *buttons = new QHBoxLayout;
        buttons->addStretch();
        buttons->addWidget(edit);
        buttons->addWidget(remove);
        rowLayout->addLayout(buttons);
        auto *state = new QLabel(row);
        state->setObjectName(QStringLiteral("bridgeState_") + b.end);
        state->setWordWrap(true);
        state->setTextInteractionFlags(Qt::TextSelectableByMouse);
        QString text;
        bool bad = false;
        if (!m_session)
            text = tr("Not running: the network is not built (the status bar says why)");
        else if (!current)
            text = tr("Changed: Stop builds the network again with this bridge");
        else if (!s->error.isEmpty()) {
            text = s->error;
            bad = true;
        } else if (s->open)
            text = b.kind == BridgeKind::Pty
                       ? tr("Open: give this path to a master on this computer")
                       : tr("Open: %1").arg(s->reached);
        else
            text = tr("Opening...");
        state->setText(text);
        if (bad)
            state->setStyleSheet(QStringLiteral("QLabel { color: #b00020; }"));
        rowLayout->addWidget(state);
        m_rows->addWidget(row);
        if (current)
            live[b.end] = {s->open ? s->reached : QString(), s->error};
    }
    m_rows->addStretch();
    m_view->setLiveBridges(std::move(live));
    const int count = int(bridges.size());
    if (count > 0 && m_shownFor == 0) {
        m_dock->show();
        m_dock->raise();
    }
    m_shownFor = count;
}

} // namespace rung::app
