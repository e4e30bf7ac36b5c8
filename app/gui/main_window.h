#pragma once

// The main window: the ladder and the instruction list of one program (tabs or side by side),
// the problems panel, the project dock (target, model, symbols), menus, toolbar and status
// bar. File handling (open, save, recovery, export) lives in main_window_files.cpp.

#include "editor/document.h"

#include <QMainWindow>
#include <QTimer>

#include <memory>

class QLabel;
class QLockFile;
class QSplitter;
class QTabWidget;
class QTableWidget;
class QTreeWidget;
class QLineEdit;
class QMenu;

class QPrinter;

namespace rung::editor {
class CrossReferenceView;
class IlEditor;
class LadderView;
class ProblemsView;
class WatchListView;
} // namespace rung::editor

namespace rung::app {

class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget *parent = nullptr);
    ~MainWindow() override;

    editor::Document *document() { return m_document; }
    editor::LadderView *ladderView() { return m_ladder; }
    editor::IlEditor *ilEditor() { return m_il; }
    editor::ProblemsView *problemsView() { return m_problems; }

    // Opens a project (.rung) or a listing (.il, with the given target); false after telling
    // the user why when the file cannot be read.
    bool openFile(const QString &path, const QString &targetId = QString(), bool quiet = false);
    bool saveTo(const QString &path);
    void newProject(const model::Target &target, const QString &modelName);
    void setSideBySide(bool sideBySide);
    void editRungComment(); // asks for the comment of the rung under the cursor
    // The ladder as PNG, SVG or PDF (by the file's suffix; the PDF is the printout, with
    // the page header); false with the reason when it cannot be written.
    bool exportLadder(const QString &path, QString *error);
    bool printLadder(QPrinter *printer);
    // Applies the IL editor's text now (the editor also does it after a short pause).
    void applyListing();
    // This window's recovery file (one per window of each running instance, so instances
    // never overwrite each other's) and the folder all of them live in.
    QString recoveryPath() const;
    static void setRecoveryDirectory(const QString &directory); // tests: a folder of their own
    // Tools over the whole program (main_window_tools.cpp).
    void copyRung(bool cut);
    void pasteRungs();
    int replaceDeviceEverywhere(const QString &from, const QString &to,
                                QString *error); // -1: error
    // Moves the ladder's cursor to the next (previous) use of a device, remembered for F3;
    // false with a message in the status bar when the text is no device or nothing uses it.
    bool findDevice(const QString &device, bool backwards);
    bool importSymbols(const QString &path, QString *error);
    bool exportSymbolsTo(const QString &path, QString *error);
    editor::WatchListView *watchListView() const { return m_watch; }
    QLineEdit *crossReferenceDevice() { return m_crossDevice; }
    QTreeWidget *crossReference() { return m_crossTree; }
    void writeRecovery();
    // Offers the recovery file of an instance that is gone (crashed), newest first; true when
    // one was recovered: it is then the open program, modified, with its original file.
    bool offerRecovery(bool ask = true);
    // What the application shows first: work orphaned by a crash when the user recovers it,
    // else the file of the command line (if any).
    void start(const QString &file, const QString &targetId, bool askToRecover = true);

protected:
    void closeEvent(QCloseEvent *event) override;

private:
    // applyListing(), as a step of its own or into the undo step already under way (a fix).
    void applyListingAs(editor::Document::ListingStep step);
    // An instruction list or a symbol table opened, imported: read no further than this.
    static constexpr qint64 kMaxTextFileBytes = 64 * 1024 * 1024;
    void buildActions();
    void buildDocks();
    void updateTitle();
    void updateStatus();
    void refreshFromDocument();
    void showProject(const model::Project &project, const QString &path);
    void refreshSymbols();
    void symbolsEdited(int row);
    void locate(const model::Diagnostic &diagnostic);
    void applyFix(const model::Diagnostic &diagnostic);
    QAction *undoAction(bool redo);
    bool maybeSave();
    void addRecent(const QString &path);
    void rebuildRecentMenu();
    void rebuildExamplesMenu();
    void claimRecoveryFile();
    void removeRecovery();

    // File actions (main_window_files.cpp).
    void fileNew();
    void fileOpen();
    bool fileSave();
    bool fileSaveAs();
    void importListing();
    void exportListing();
    void exportImage(const QString &format);
    void printPreview();
    void replaceDevice();
    void findDeviceDialog();
    void exportSymbols();
    void buildCrossReference();

    editor::Document *m_document;
    editor::LadderView *m_ladder;
    editor::IlEditor *m_il;
    editor::ProblemsView *m_problems;
    editor::WatchListView *m_watch = nullptr;
    QTabWidget *m_tabs;
    QSplitter *m_split;
    QTableWidget *m_symbols = nullptr;
    editor::CrossReferenceView *m_crossReference = nullptr;
    QLineEdit *m_crossDevice = nullptr;
    QTreeWidget *m_crossTree = nullptr;
    QLabel *m_projectInfo = nullptr;
    QLabel *m_statusTarget;
    QLabel *m_statusSteps;
    QLabel *m_statusCursor;
    QMenu *m_recentMenu = nullptr;
    QMenu *m_examplesMenu = nullptr;
    QTimer m_ilTimer;
    QTimer m_recoveryTimer;
    QString m_recoveryBase;                    // recovery file path without its suffix
    std::unique_ptr<QLockFile> m_recoveryLock; // held while this window lives
    std::vector<model::Diagnostic> m_listingErrors;
    struct TypedSteps { // the step of each line of the text as typed, for the text it was read from
        const model::ModelVariant *model = nullptr;
        QString text;
        std::vector<int> steps;
    } m_typedSteps;
    bool m_editingListing = false;
    // A status message about the list's errors ("... has errors"): it goes once the list
    // applies without them, not when its time is up.
    QString m_errorsMessage;
    QString m_findText; // the device of the last Find, for F3 / Shift+F3
    bool m_sideBySide = false;
    bool m_updatingSymbols = false;
    // Symbol table rows being typed that are no symbol yet (no device, or one the target does
    // not have): they stay in the table, after the symbols, until complete or cleared.
    struct PendingSymbol {
        QString device, name, comment;
    };
    std::vector<PendingSymbol> m_pendingSymbols;
};

} // namespace rung::app
