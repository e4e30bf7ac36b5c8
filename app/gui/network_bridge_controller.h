#pragma once

// The bridges of the network open in a network window, live (docs/network.md, "Bridges in the
// IDE"): it hands each session built from the document the window's bridge lines
// (network::BridgeLines: a pseudo-terminal keeps its path across Stop and edits), and shows in
// the Bridges dock and on the Network view where each bridge is reached (the pseudo-terminal's
// path, with a Copy button) or what, where and why it could not open. The lines are opened and
// read on the session's worker thread; this class only shows what the session reports.

#include "network/network_session_bridges.h"

#include <QObject>
#include <QPointer>

#include <memory>

class QDockWidget;
class QMainWindow;
class QVBoxLayout;
class QWidget;

namespace rung::network {
class NetworkSession;
}

namespace rung::app {

class NetworkDocument;
class NetworkView;

class NetworkBridgeController : public QObject {
    Q_OBJECT
public:
    NetworkBridgeController(NetworkDocument *document, NetworkView *view, QMainWindow *window);
    ~NetworkBridgeController() override;

    QDockWidget *dock() const { return m_dock; }
    // The session the window built from the document (null: none): its bridges start now.
    void setSession(network::NetworkSession *session);
    // Where a bridged port ("s5/CP2") is reached while its line is open; "" otherwise.
    QString reached(const QString &end) const;
    // Its error (what, where, why); "" when it is open or not built.
    QString error(const QString &end) const;
    // Copies where the port is reached to the clipboard; false when it is not open.
    bool copyReached(const QString &end);
    // The window's lines (tests: how many are open).
    const std::shared_ptr<network::BridgeLines> &lines() const { return m_lines; }

signals:
    void message(const QString &text);
    // The statuses changed (a bridge opened or failed), after the dock and the view show it.
    void bridgesChanged();

private:
    bool eventFilter(QObject *watched, QEvent *event) override;
    void refresh();
    const network::BridgeStatus *status(const QString &end) const;

    NetworkDocument *m_document;
    NetworkView *m_view;
    std::shared_ptr<network::BridgeLines> m_lines;
    QPointer<network::NetworkSession> m_session;
    QDockWidget *m_dock = nullptr;
    QWidget *m_panel = nullptr;
    QVBoxLayout *m_rows = nullptr;
    int m_shownFor = 0; // bridges the dock was last shown for (it opens when the first comes)
};

} // namespace rung::app
