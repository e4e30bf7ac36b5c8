#pragma once

// The window's files: File > New, Open, Open Recent, Examples, Save, Save As, Import and
// Export of the instruction list, Export Ladder, Print Preview; what was saved (a project keeps
// the list as typed and the symbol rows that are no symbol yet), the question before unsaved
// work goes, and the recovery file written every minute and offered after a crash. It needs
// the document, the two views, the list as typed and the symbol table, not the window: a
// test hands it a plain widget as the parent of its dialogs.

#include "model/project/project.h"

#include <QObject>
#include <QPointer>
#include <QStringList>
#include <QTimer>

#include <functional>
#include <memory>
#include <vector>

class QMenu;
class QStatusBar;
class QToolBar;
class QWidget;

namespace rung::editor {
class Document;
class IlEditor;
class LadderView;
} // namespace rung::editor

namespace rung::app {

class ListingController;
class RecoveryFile;
class SymbolTable;

class FileController : public QObject {
    Q_OBJECT

public:
    // `window`: the parent of its dialogs (and what Quit closes); `status`: its messages.
    FileController(editor::Document *document, editor::LadderView *ladder, editor::IlEditor *il,
                   ListingController *listing, SymbolTable *symbols, QStatusBar *status,
                   QWidget *window, QObject *parent = nullptr);
    ~FileController() override;

    // The File menu's entries and the toolbar's New, Open and Save (built again with the
    // menus when the language changes).
    void addActions(QMenu *file, QToolBar *bar);

    // Opens a project (.rung) or a listing (.il, with the given target); false after telling
    // the user why when the file cannot be read.
    bool openFile(const QString &path, const QString &targetId = QString(), bool quiet = false);
    bool saveTo(const QString &path);
    void newProject(const model::Target &target, const QString &modelName);
    // A file name chosen in a save dialog, with the first of `suffixes` added when it has none
    // of them (typing "latch" for a PDF writes latch.pdf); when that names a file that exists,
    // asks before it is replaced (the dialog asked about the name as typed). Empty: cancelled.
    QString completeSavePath(const QString &chosen, const QStringList &suffixes);
    // A save dialog in the program's folder, then completeSavePath.
    QString askSavePath(const QString &title, const QString &filter, const QStringList &suffixes);
    // Unsaved work: the program, or a list as typed (with errors) or symbol rows that are no
    // symbol yet that the last save or open did not hold.
    bool isModified() const;
    // Asks to save unsaved work; false when the user cancelled.
    bool maybeSave();
    // The window closes for good: its recovery file goes.
    void closing();

    QString recoveryPath() const; // this window's (recovery.h)

    // Opens a network (.rungnet; an empty path: a new network) in a window of its own; false
    // with why. The main window sets it (network_window.h); without one a network is refused
    // with a reason.
    using NetworkOpener = std::function<bool(const QString &path, QString *error)>;
    void setNetworkOpener(NetworkOpener opener) { m_networkOpener = std::move(opener); }
    void writeRecovery();
    // Offers the recovery file of an instance that is gone (crashed), newest first; true when
    // one was recovered: it is then the open program, modified, with its original file.
    bool offerRecovery(bool ask = true);
    // What the application shows first: work orphaned by a crash when the user recovers it,
    // else the file of the command line (if any).
    void start(const QString &file, const QString &targetId, bool askToRecover = true);

    // An instruction list or a symbol table opened, imported: read no further than this.
    static constexpr qint64 kMaxTextFileBytes = 64 * 1024 * 1024;

signals:
    // Saved: the project's name and the title follow.
    void saved();

private:
    QStatusBar *statusBar() const { return m_status; }
    void showProject(const model::Project &project, const QString &path);
    // Names a program opened from a listing or ladder text after its file
    // (Document::setUntitledName).
    void nameImported(const QString &path);
    // A program read from a listing or ladder text: a new project of the target's default
    // model, named after the file.
    void showImported(const model::Target &target, const model::LadderProgram &program,
                      const QString &path);
    // The project as Save and recovery keep it: the program and the list as typed.
    model::Project projectToKeep() const;
    void addRecent(const QString &path);
    void rebuildRecentMenu();
    void rebuildExamplesMenu();
    void fileNew();
    void fileOpen();
    bool fileSave();
    bool fileSaveAs();
    void importListing();
    void exportListing();
    void exportImage(const QString &format);
    void printPreview();

    editor::Document *m_document;
    editor::LadderView *m_ladder;
    editor::IlEditor *m_il;
    ListingController *m_listing;
    SymbolTable *m_symbols;
    QStatusBar *m_status;
    QPointer<QWidget> m_window;
    QPointer<QMenu> m_recentMenu;
    QPointer<QMenu> m_examplesMenu;
    NetworkOpener m_networkOpener;
    QTimer m_recoveryTimer;
    std::unique_ptr<RecoveryFile> m_recovery;
    QString m_savedPending; // the list as typed that the file holds (pendingListing)
    std::vector<model::PendingSymbol> m_savedPendingSymbols; // and the symbol rows it holds
};

} // namespace rung::app
