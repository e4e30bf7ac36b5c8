#pragma once

// The Network view (issue 30): the open network drawn as boxes, one per station (its name,
// target, model and program, then each port with its application, station number, rate and
// format, and its bridge to a real line) and per simulated device, with the wires as buses
// beneath them joining the ports. Zoomable (Ctrl+wheel, Ctrl++ / Ctrl+- / Ctrl+0); a click
// selects a station, a port or a wire; a drag from one port to another wires them; Delete
// removes what is selected (a station after saying what goes with it); the context menu holds
// every edit of NetworkDocument. Double-click on a station asks for its program. The drawing and
// the mouse are the canvas's (network_canvas.h), the edits the view's.

#include "network/network_file.h"

#include <QScrollArea>

#include <map>
#include <optional>
#include <vector>

namespace rung::app {

class NetworkDocument;
class NetworkCanvas;

class NetworkView : public QScrollArea {
    Q_OBJECT
public:
    explicit NetworkView(NetworkDocument *document, QWidget *parent = nullptr);

    NetworkDocument *document() const { return m_document; }
    QWidget *canvas() const;

    double zoom() const { return m_zoom; }
    // The width the drawing may take without scrolling sideways, unzoomed: the view's, less a
    // vertical scroll bar's whether shown or not (so that showing one never wraps anew).
    double textWidth() const;
    void setZoom(double zoom); // 0.5 .. 3
    void zoomIn();
    void zoomOut();

    // What is selected: a station or device ("master"), a port ("master/CP2") or a wire
    // ("wire:w1"); "" for nothing.
    QString selection() const { return m_selection; }
    void select(const QString &item);
    // The selected station's name (also when one of its ports is selected).
    QString selectedStation() const;

    // Where things are drawn, in the canvas's coordinates at the current zoom (for tests and
    // for the lead's integration: scrolling to a station).
    QRect itemRect(const QString &item) const; // a station or a device box
    QPoint endPoint(const QString &end) const; // a port's row or a device's connector
    QString itemAt(const QPoint &canvasPoint) const;

    // The edits the menus run (each says why when refused). Remove asks before it removes
    // anything else; `confirm` false skips the question (tests, scripts).
    void removeSelected(bool confirm = true);
    void editPort(const QString &end);
    void addStationFromProgram();
    void addNewProjectStation();
    void editPeriod();
    // A port's bridge (network_bridge_dialog.h): made, or changed when the port has one; the
    // dialog opens on `kind` when given. removeBridge takes it away. Each is one undo step.
    void editBridge(const QString &end,
                    std::optional<network::BridgeDescription::Kind> kind = std::nullopt);
    void removeBridge(const QString &end);

    // The bridges of the running network (network_bridge_controller.h): where each port's line
    // is reached, or why it failed; drawn on the port.
    struct LiveBridge {
        QString reached;
        QString error;
    };
    void setLiveBridges(std::map<QString, LiveBridge> live);
    const std::map<QString, LiveBridge> &liveBridges() const { return m_live; }
    // The text the view draws for a port's bridge ("bridge: pseudo-terminal /dev/pts/5"); ""
    // when it has none.
    QString bridgeText(const QString &end) const;

    // Quiet: a refused edit is only signalled (editRefused), no message box (tests, scripts).
    void setQuiet(bool quiet) { m_quiet = quiet; }

protected:
    void resizeEvent(QResizeEvent *event) override;

signals:
    void stationActivated(const QString &name);
    void stationSelected(const QString &name);
    void selectionChanged(const QString &item);
    // An edit was refused; the view has said why in a message box unless quiet.
    void editRefused(const QString &why);

protected:
    void changeEvent(QEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;

private:
    friend class NetworkCanvas;
    void refuse(const QString &why);
    void contextMenuAt(const QPoint &canvasPoint, const QPoint &global);
    void addBridgeMenu(class QMenu *menu, const QString &end);

    NetworkDocument *m_document;
    NetworkCanvas *m_canvas;
    double m_zoom = 1.0;
    QString m_selection;
    bool m_quiet = false;
    std::map<QString, LiveBridge> m_live;
};

// File > Save / Save As of a network: writes `document` to `file` (empty: where it came from);
// when the file could not hold everything the user has, says what and asks before writing
// anything; an error is shown. True when the file was written.
bool saveNetwork(QWidget *parent, NetworkDocument *document, const QString &file = {});

} // namespace rung::app
