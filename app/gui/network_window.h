#pragma once

// The window of a network (.rungnet): its stations simulated together on one clock
// (network::NetworkSession), a station selector that chooses which station the ladder and
// the inputs and outputs show, a watch table of devices of any station ("s5/D10"), the faults
// a user makes while it runs (cut a wire, silence a station, corrupt the next frame) and the
// usual simulation controls with the main window's keys. A station's program is edited in the
// main window (double-click the station): the network reads its files again at Stop.

#include <QMainWindow>
#include <QPointer>

#include <memory>
#include <vector>

class QAction;
class QComboBox;
class QWidgetAction;
class QLabel;
class QListWidget;
class QMenu;
class QStackedWidget;
class QTableView;
class QLineEdit;

namespace rung::editor {
class Document;
class FrontPanel;
class IoPanel;
class LadderView;
} // namespace rung::editor
namespace rung::network {
class NetworkSession;
class StationSource;
} // namespace rung::network

namespace rung::app {

class NetworkBridgeController;
class NetworkChart;
class NetworkDebugController;
class NetworkDocument;
class NetworkHistoryController;
class NetworkView;
class NetworkTrafficView;
class NetworkWatchModel;

class NetworkWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit NetworkWindow(QWidget *parent = nullptr);
    ~NetworkWindow() override;

    // Reads the file into the Network view, loads every station's program and builds the
    // network, Stopped at time 0; false with what, where and why when the file does not read.
    // A network that reads but does not build (a program missing) opens in the view, with why
    // in the status bar, to be mended there.
    bool open(const QString &path, QString *error);
    // An empty network in the view: add stations there (its context menu), then simulate.
    bool newNetwork(QString *error);
    NetworkDocument *networkDocument() const { return m_doc; }
    NetworkView *networkView() const { return m_view; }
    // Saves the network (asks where when it has no file yet); false when it was not written.
    bool save(bool askWhere = false);
    QString path() const { return m_path; }
    network::NetworkSession *session() const { return m_session.get(); }

    // The station the ladder, the inputs and outputs and the front panel show.
    QString currentStation() const;
    bool selectStation(const QString &name);
    QComboBox *stationSelector() const { return m_selector; }
    editor::LadderView *ladderView(const QString &station) const;
    editor::Document *document(const QString &station) const;
    NetworkWatchModel *watchModel() const { return m_watch; }
    NetworkChart *chart() const { return m_chart; }
    NetworkTrafficView *traffic() const { return m_traffic; }
    NetworkHistoryController *history() const { return m_history; }
    editor::FrontPanel *frontPanel() const { return m_panel; }
    NetworkBridgeController *bridges() const { return m_bridges; }
    // The selected station's list, the Scan Debugger, breakpoints and stepping.
    NetworkDebugController *debugger() const { return m_debug; }
    // Adds "STATION/DEVICE" to the watch table; false with the reason in the status bar.
    bool watch(const QString &device);
    // The status line: run state and virtual time.
    QString statusText() const;

signals:
    // The user asked to edit a station's program (the main window opens it).
    void openProgramRequested(const QString &path);
    // The station the views show changed.
    void stationChanged(const QString &name);

protected:
    void closeEvent(QCloseEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    struct StationView {
        QString name;
        network::StationSource *source = nullptr;
        editor::Document *document = nullptr;
        editor::LadderView *ladder = nullptr;
        editor::IoPanel *io = nullptr;
    };
    void buildWindow();
    void buildMenus();
    void buildFaultsMenu();
    void retranslate();
    void updateStatus();
    void updateActions();
    bool loadStationDocument(StationView &view, QString *error);
    // The session and the stations' views built again from the document (its edits taken);
    // the watch table's and the chart's devices kept where the stations still have them.
    bool buildSession(QString *error);
    void dropSession();
    void documentChanged();
    void updateTitle();
    void addWatchedFromLine();

    QString m_path;
    NetworkDocument *m_doc = nullptr;
    NetworkView *m_view = nullptr;
    class QTabWidget *m_tabs = nullptr;
    bool m_stale = false; // the document was edited since the session was built
    QAction *m_save = nullptr;
    QAction *m_saveAs = nullptr;
    QAction *m_undo = nullptr;
    QAction *m_redo = nullptr;
    std::unique_ptr<network::NetworkSession> m_session;
    std::vector<StationView> m_views;
    QComboBox *m_selector = nullptr;
    QWidgetAction *m_selectorAction = nullptr; // the selector on the toolbar (buildMenus)
    QStackedWidget *m_ladders = nullptr;
    QStackedWidget *m_ioPanels = nullptr;
    QListWidget *m_stationList = nullptr;
    QTableView *m_watchView = nullptr;
    QLineEdit *m_watchLine = nullptr;
    NetworkWatchModel *m_watch = nullptr;
    NetworkChart *m_chart = nullptr;
    NetworkTrafficView *m_traffic = nullptr;
    editor::FrontPanel *m_panel = nullptr;
    NetworkHistoryController *m_history = nullptr;
    QAction *m_chartWatched = nullptr;
    QLabel *m_status = nullptr;
    QLabel *m_selectorLabel = nullptr;
    QMenu *m_simulationMenu = nullptr;
    QMenu *m_faultsMenu = nullptr;
    QMenu *m_speedMenu = nullptr;
    QAction *m_run = nullptr;
    QAction *m_pause = nullptr;
    QAction *m_stop = nullptr;
    QAction *m_scan = nullptr;
    QAction *m_powerCycle = nullptr;
    QAction *m_close = nullptr;
    QAction *m_editProgram = nullptr;
    QAction *m_removeWatch = nullptr;
    class QDockWidget *m_stationsDock = nullptr;
    class QDockWidget *m_watchDock = nullptr;
    class QDockWidget *m_ioDock = nullptr;
    class QDockWidget *m_chartDock = nullptr;
    class QDockWidget *m_trafficDock = nullptr;
    class QDockWidget *m_panelDock = nullptr;
    NetworkBridgeController *m_bridges = nullptr; // the Bridges dock, live bridges
    NetworkDebugController *m_debug = nullptr;
};

} // namespace rung::app
