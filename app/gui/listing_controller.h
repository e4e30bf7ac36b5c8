#pragma once

// The instruction list pane in step with the program: what is typed becomes the program after
// a short pause (or at once, applyListing); a list with errors stays as typed, its errors in
// the list and the problems, while the ladder keeps the last valid program; an edit of the
// rungs that would print over such a list asks first (mayReplaceTypedList); the undo actions
// take what was just typed first. The window's other controllers ask it for the list as typed
// (pendingListing, hasErrors) and to take a pending edit first (flush). It needs the document,
// the two views and the problems panel, not the window.

#include "editor/document.h"

#include <QObject>
#include <QPointer>
#include <QTimer>

#include <vector>

class QAction;
class QStatusBar;
class QWidget;

namespace rung::editor {
class IlEditor;
class LadderView;
class ProblemsView;
} // namespace rung::editor

namespace rung::app {

class ListingController : public QObject {
    Q_OBJECT

public:
    // `window`: the parent of its question and where the problems' dock is found; `status`:
    // where its messages go.
    ListingController(editor::Document *document, editor::LadderView *ladder, editor::IlEditor *il,
                      editor::ProblemsView *problems, QStatusBar *status, QWidget *window,
                      QObject *parent = nullptr);
    ~ListingController() override;

    // Applies the IL editor's text now (the editor also does it after a short pause).
    void applyListing();
    // applyListing(), as a step of its own or into the undo step already under way (a fix).
    void applyListingAs(editor::Document::ListingStep step);
    // What was typed and not yet applied becomes the program first (before a save, a run).
    void flush() {
        if (m_ilTimer.isActive())
            applyListing();
    }
    // Typed within the pause, not yet applied.
    bool editPending() const { return m_ilTimer.isActive(); }
    // The list as typed has errors the program could not take.
    bool hasErrors() const { return model::hasErrors(m_listingErrors); }
    // The findings of the list as typed (errors, or the fuzzy forms of a text that applied).
    const std::vector<model::Diagnostic> &listingErrors() const { return m_listingErrors; }
    // The list as typed when it has errors the program could not take; empty when it agrees.
    QString pendingListing() const;
    // Another program comes: the findings of the list that showed the last one go.
    void forget() { m_listingErrors.clear(); }
    // A status message about the list's errors ("... has errors"): it goes once the list
    // applies without them, not when its time is up.
    void sayErrors(const QString &message);

    // The list pane, the problems and the step numbers from the document (refreshed()).
    void refreshFromDocument();
    // Before an edit of the rungs replaces the list as typed with errors (the list would show
    // the ladder's program): asks the user, naming the list's first error; false to keep the
    // list and leave the program as it is. True at once when there is nothing typed to lose.
    // A list typed within the pause without errors is taken first, as its own step; false
    // (with a word in the status bar) when it changed the rungs [first, first + count) the
    // edit was made on, so that the edit never lands on a rung it was not made for.
    bool mayReplaceTypedList(int first = 0, int count = 0);
    void applyFix(const model::Diagnostic &diagnostic);
    // Edit > Undo / Redo: QUndoStack's, with the list's pending edit taken first.
    QAction *undoAction(bool redo, QObject *owner);
    // The findings found again in the language installed; the list as typed stays as it is.
    void recheck();

signals:
    // After refreshFromDocument: the window's symbols, project, status and title follow.
    void refreshed();

private:
    QStatusBar *statusBar() const { return m_status; }
    // Which instruction of the program each line of the list shows, for its live values.
    void updateMonitorLines(bool typed);

    editor::Document *m_document;
    editor::LadderView *m_ladder;
    editor::IlEditor *m_il;
    editor::ProblemsView *m_problems;
    QStatusBar *m_status;
    QPointer<QWidget> m_window;
    QTimer m_ilTimer;
    std::vector<model::Diagnostic> m_listingErrors;
    struct TypedSteps { // the step of each line of the text as typed, for the text it was read from
        const model::ModelVariant *model = nullptr;
        QString text;
        std::vector<int> steps;
        // The instruction of the program on each line (0-based), when the text as typed holds
        // the program's instructions one for one; empty when it does not.
        std::vector<int> instructionOfLine;
    } m_typedSteps;
    bool m_editingListing = false;
    // The rungs revision and the listing the list pane last took from the document.
    quint64 m_shownRevision = 0;
    QString m_shownListing;
    QString m_errorsMessage;
};

} // namespace rung::app
