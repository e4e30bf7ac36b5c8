#pragma once

// The main window: the ladder and the instruction list of one program (tabs or side by side),
// the problems panel, the project dock (target, model, symbols), menus, toolbar and status
// bar. File handling (open, save) lives in main_window_files.cpp; the recovery file, the
// exports and the symbol table are parts of their own (recovery.h, ladder_export.h,
// symbol_table.h).

#include "editor/document.h"
#include "model/image/monitor_source.h"

#include <QMainWindow>
#include <QPointer>
#include <QTimer>

#include <memory>

class QLabel;
class QSplitter;
class QTabWidget;
class QLineEdit;
class QMenu;
class QToolBar;

namespace rung::model {
class MonitorSource;
}
namespace rung::comms {
class OnlineSession;
}
namespace rung::editor {
class CrossReferenceView;
class IlEditor;
class IoPanel;
class TimingChart;
class WatchPanel;
class LadderView;
class ProblemsView;
class WatchListView;
} // namespace rung::editor

namespace rung::model {
class MonitorSource;
}

namespace rung::app {

class ConnectionPanel;
class DebugController;
class ElidingLabel;
class FileController;
class FrontPanelController;
class LayoutController;
class ListingController;
class NetworkWindow;
class OnlineController;
class RecoveryFile;
class ScanDebuggerView;
class SimulationController;
class SimulationMenu;
class SimulationPanel;
class SymbolTable;

class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget *parent = nullptr);
    ~MainWindow() override;

    editor::Document *document() { return m_document; }
    editor::LadderView *ladderView() { return m_ladder; }
    editor::IlEditor *ilEditor() { return m_il; }
    editor::ProblemsView *problemsView() { return m_problems; }

    // The window's files (file_controller.h): open, save, the recovery file. The window's
    // own entry points are its controller's.
    FileController *files() const { return m_files; }
    LayoutController *layoutController() const { return m_layout; }
    bool openFile(const QString &path, const QString &targetId = QString(), bool quiet = false);
    bool saveTo(const QString &path);
    QString completeSavePath(const QString &chosen, const QStringList &suffixes);
    bool isModified() const;
    void newProject(const model::Target &target, const QString &modelName);
    void setSideBySide(bool sideBySide);
    void editRungComment(); // asks for the comment of the rung under the cursor
    // Edit > Communication Ports...: the project's port settings (the Vigor's "2nd COM Port
    // Setting", CPU Link, the PL110's COM1 / EXP1 / COM2 protocols), one undo step.
    void editCommunicationPorts();
    // Applies the IL editor's text now (the editor also does it after a short pause).
    void applyListing();
    QString recoveryPath() const;
    // Tools over the whole program (main_window_tools.cpp).
    void copyRung(bool cut);
    void pasteRungs();
    // Edit > Replace Device without its dialogs: the number of places changed (one undo
    // step), -1 with the reason when either text is no device.
    int replaceDeviceEverywhere(const QString &from, const QString &to, QString *error);
    // Moves the ladder's cursor to the next (previous) use of a device, remembered for F3;
    // false with a message in the status bar when the text is no device or nothing uses it.
    bool findDevice(const QString &device, bool backwards);
    SymbolTable *symbolTable() const { return m_symbols; }
    editor::WatchListView *watchListView() const { return m_watch; }
    editor::WatchPanel *watchPanel() const { return m_watchPanel; }
    editor::IoPanel *ioPanel() const { return m_ioPanel; }
    // The Front Panel dock; showSource points it at any source (a network station's).
    FrontPanelController *frontPanel() const { return m_frontPanel; }
    editor::TimingChart *timingChart() const { return m_chart; }
    SimulationController *simulation() const { return m_simulation; }
    // The simulation's docks, breakpoints and stepping (debug_controller.h).
    DebugController *debugging() const { return m_debug; }
    SimulationPanel *simulationPanel() const;
    ScanDebuggerView *scanDebugger() const;
    ConnectionPanel *connectionPanel() const;
    OnlineController *online() const { return m_online; }
    QLineEdit *crossReferenceDevice() { return m_crossDevice; }
    editor::CrossReferenceView *crossReference() const { return m_crossReference; }
    void writeRecovery();
    bool offerRecovery(bool ask = true);
    void start(const QString &file, const QString &targetId, bool askToRecover = true);

    // A network (.rungnet) in a window of its own beside this one (main_window_network.cpp);
    // null with why. Its stations' programs open here for editing.
    NetworkWindow *openNetwork(const QString &path, QString *error);

    // Where the live values come from (main_window_monitor.cpp).
    enum class MonitorOrigin { Simulation, Online, History };
    // The one place that hands the active source to every monitoring view (the ladder's
    // overlay, the instruction list's values, the watch lists; null: none) and says in the
    // title and the status bar which origin the window shows.
    void setMonitorSource(model::MonitorSource *source,
                          MonitorOrigin origin = MonitorOrigin::Simulation);
    model::MonitorSource *monitorSource() const { return m_monitorSource; }
    // The name of an origin as the window shows it ("Simulation"): its one place.
    static QString originText(MonitorOrigin origin);

protected:
    void closeEvent(QCloseEvent *event) override;
    void changeEvent(QEvent *event) override; // LanguageChange: retranslate()

private:
    void buildActions();
    // Every text of the window in the language now installed: menus and toolbar built again,
    // docks, tabs, status bar, and the problems found again (their messages are translated
    // when found). The list as typed stays as it is.
    void retranslate();
    void buildDocks();
    void updateTitle();
    void updateStatus();
    void refreshProjectInfo();
    void locate(const model::Diagnostic &diagnostic);
    void replaceDevice();
    void findDeviceDialog();
    void exportSymbols();
    void buildCrossReference();
    // The monitoring docks: watch table, inputs and outputs, timing chart
    // (main_window_panels.cpp).
    void buildMonitorDocks();
    void retranslatePanels();
    void addPanelActions(QMenu *menu);
    void setPanelsSource(model::MonitorSource *source);
    // The simulation (main_window_simulation.cpp).
    void setupSimulation();
    // The online controller and what its session changes in the window (main_window_monitor.cpp).
    void setupOnline();
    // The origin's label in the status bar and the title (main_window_monitor.cpp).
    void updateMonitorLabel();

    editor::Document *m_document;
    editor::LadderView *m_ladder;
    editor::IlEditor *m_il;
    editor::ProblemsView *m_problems;
    editor::WatchListView *m_watch = nullptr;
    editor::WatchPanel *m_watchPanel = nullptr;
    editor::IoPanel *m_ioPanel = nullptr;
    FrontPanelController *m_frontPanel = nullptr;
    editor::TimingChart *m_chart = nullptr;
    bool m_panelsShown = false; // the first simulation showed the inputs and outputs
    SymbolTable *m_symbols = nullptr;
    editor::CrossReferenceView *m_crossReference = nullptr;
    QLineEdit *m_crossDevice = nullptr;
    QLabel *m_projectInfo = nullptr;
    QLabel *m_symbolsLabel = nullptr;
    QToolBar *m_toolBar = nullptr;
    QLabel *m_statusTarget;
    QLabel *m_statusSteps;
    ElidingLabel *m_statusCursor;
    SimulationController *m_simulation = nullptr;
    SimulationMenu *m_simulationMenu = nullptr; // the Simulation menu and status
    DebugController *m_debug = nullptr;
    OnlineController *m_online = nullptr; // the connection dock, the Online menu
    QPointer<model::MonitorSource> m_monitorSource;
    MonitorOrigin m_monitorOrigin = MonitorOrigin::Simulation;
    QLabel *m_statusOrigin = nullptr;
    ListingController *m_listing = nullptr; // the list as typed, in step with the program
    FileController *m_files = nullptr;
    LayoutController *m_layout = nullptr; // tabs or side by side, the docks' places
    QString m_findText;                   // the device of the last Find, for F3 / Shift+F3
};

} // namespace rung::app
