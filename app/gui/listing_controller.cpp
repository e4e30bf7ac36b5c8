#include "listing_controller.h"

#include "editor/commands/listing_lines_command.h"
#include "editor/il_editor.h"
#include "editor/ladder_view.h"
#include "editor/problems_view.h"

#include <QAction>
#include <QDockWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QStatusBar>
#include <QUndoStack>

#include <algorithm>

namespace rung::app {

ListingController::ListingController(editor::Document *document, editor::LadderView *ladder,
                                     editor::IlEditor *il, editor::ProblemsView *problems,
                                     QStatusBar *status, QWidget *window, QObject *parent)
    : QObject(parent)
    , m_document(document)
    , m_ladder(ladder)
    , m_il(il)
    , m_problems(problems)
    , m_status(status)
    , m_window(window) {
    m_ilTimer.setSingleShot(true);
    m_ilTimer.setInterval(500);
    connect(&m_ilTimer, &QTimer::timeout, this, &ListingController::applyListing);
    connect(m_il, &editor::IlEditor::listingEdited, this, [this] { m_ilTimer.start(); });
    connect(m_document, &editor::Document::programChanged, this,
            &ListingController::refreshFromDocument);
    m_document->setRungEditGuard(
        [this](int first, int count) { return mayReplaceTypedList(first, count); });
    connect(m_problems, &editor::ProblemsView::applyFix, this, &ListingController::applyFix);
}

ListingController::~ListingController() {
    m_ilTimer.stop();
    m_document->setRungEditGuard({});
}

void ListingController::sayErrors(const QString &message) {
    m_errorsMessage = message;
    statusBar()->showMessage(m_errorsMessage, 10000);
}

void ListingController::recheck() {
    const bool typed = !m_listingErrors.empty();
    m_editingListing = typed;
    m_document->recheck();
    m_editingListing = false;
    if (typed)
        applyListing();
}

void ListingController::refreshFromDocument() {
    // The list pane takes the ladder's listing when the rungs changed, or when it shows the
    // listing it was given (in another language, say); a change of the symbols or the watch
    // lists leaves the list as typed as it is.
    const bool rungsChanged = m_document->rungsRevision() != m_shownRevision;
    if (!m_editingListing && (rungsChanged || m_il->text() == m_shownListing)) {
        if (model::hasErrors(m_listingErrors))
            statusBar()->showMessage(tr("The list as typed had errors and now shows the "
                                        "ladder's program; Ctrl+Z in the list brings it back"),
                                     10000);
        m_il->setListing(m_document->listingText());
        m_shownListing = m_document->listingText();
        m_listingErrors.clear();
        m_ladder->setNotice(QString()); // it spoke of the errors of a list no longer shown
    }
    m_shownRevision = m_document->rungsRevision();
    // The list pane shows the text as typed (with errors or forms of its own), or the listing.
    const bool typed =
        m_editingListing || !m_listingErrors.empty() || m_il->text() != m_document->listingText();
    std::vector<model::Diagnostic> all = m_document->diagnostics();
    all.insert(all.end(), m_listingErrors.begin(), m_listingErrors.end());
    m_problems->setDiagnostics(all);
    if (auto *dock =
            m_window ? m_window->findChild<QDockWidget *>(QStringLiteral("problemsDock")) : nullptr)
        dock->setWindowTitle(m_problems->summary());
    if (!typed) {
        // Listing findings of the canonical text: map each rung's findings to its lines.
        std::vector<model::Diagnostic> onLines;
        for (model::Diagnostic d : m_document->diagnostics()) {
            if (d.location.rung < 0)
                continue;
            d.location.line = m_document->lineOf(d.location);
            if (d.location.line > 0)
                onLines.push_back(d);
        }
        m_il->showDiagnostics(onLines);
    } else {
        m_il->showDiagnostics(m_listingErrors);
    }
    std::vector<int> stepOfLine;
    if (typed) {
        // The text as typed (with errors, or in a form of its own): its lines that parse
        // keep their step numbers, as the parser counts them. A typing pause refreshes twice
        // (the document's change, then the apply): the text is parsed for this once.
        const QString typed = m_il->text();
        if (typed != m_typedSteps.text || m_document->modelVariant() != m_typedSteps.model) {
            const model::ParseResult parsed = model::parseInstructionList(
                m_document->target(), typed, m_document->modelVariant());
            std::vector<int> steps(static_cast<std::size_t>(std::max(0, m_il->lines())), -1);
            for (const model::Instruction &ins : parsed.list.instructions)
                if (ins.line >= 1 && ins.line <= static_cast<int>(steps.size()))
                    steps[static_cast<std::size_t>(ins.line - 1)] = ins.step;
            // A text of the program's own instructions, written its own way (spacing,
            // comments, aliases): its lines can show the running program's values.
            std::vector<int> lineOf;
            const auto &program = m_document->listing().list.instructions;
            const auto &read = parsed.list.instructions;
            if (parsed.ok() && read.size() == program.size() &&
                std::equal(read.begin(), read.end(), program.begin(),
                           [](const model::Instruction &a, const model::Instruction &b) {
                               return a.sameAs(b);
                           })) {
                lineOf.assign(steps.size(), -1);
                for (std::size_t i = 0; i < read.size(); ++i)
                    if (read[i].line >= 1 && read[i].line <= static_cast<int>(lineOf.size()))
                        lineOf[static_cast<std::size_t>(read[i].line - 1)] = static_cast<int>(i);
            }
            m_typedSteps = {m_document->modelVariant(), typed, std::move(steps), std::move(lineOf)};
        }
        stepOfLine = m_typedSteps.steps;
    } else {
        // The printer's line map: comment lines have no step.
        const auto &list = m_document->listing().list;
        for (const int i : m_document->printedListing().instructionOfLine)
            stepOfLine.push_back(i < 0 ? -1 : list.instructions[static_cast<std::size_t>(i)].step);
    }
    m_il->setStepNumbers(stepOfLine);
    updateMonitorLines(typed);
    emit refreshed(); // the list as typed counts as unsaved work: the title says so
}

bool ListingController::mayReplaceTypedList(int first, int count) {
    if (m_editingListing)
        return true; // the list's own change
    if (m_ilTimer.isActive()) {
        // Typed just now, not yet checked. Text with errors is taken as such (the program
        // stays), so that the question below knows of it. A valid text becomes the program
        // now, its own undo step, so the edit adds to it instead of printing over it.
        std::vector<model::Diagnostic> errors;
        const bool valid =
            m_document->setListing(m_il->text(), &errors, editor::Document::ListingStep::Check);
        const std::vector<model::Rung> before =
            valid ? m_document->ladder().rungs : std::vector<model::Rung>{};
        applyListing();
        if (valid) {
            const std::vector<model::Rung> &after = m_document->ladder().rungs;
            const auto [b, a] =
                std::mismatch(before.begin(), before.end(), after.begin(), after.end());
            const auto unchanged = static_cast<int>(b - before.begin());
            if (unchanged < first + std::max(count, 0)) {
                statusBar()->showMessage(
                    tr("The list as typed was taken first and changed rung %1, so the ladder "
                       "edit was not made: make it again on the rung as it is now.")
                        .arg(unchanged + 1),
                    10000);
                return false;
            }
        }
    }
    const auto firstError = std::find_if(
        m_listingErrors.begin(), m_listingErrors.end(),
        [](const model::Diagnostic &d) { return d.severity == model::Severity::Error; });
    if (firstError == m_listingErrors.end())
        return true;
    QMessageBox box(QMessageBox::Question, tr("Replace the Instruction List?"),
                    tr("The instruction list as typed has errors (line %1: %2).")
                        .arg(firstError->location.line)
                        .arg(firstError->message),
                    QMessageBox::NoButton, m_window);
    box.setInformativeText(
        tr("This change to the ladder replaces the list with the ladder's program; Ctrl+Z in "
           "the list brings the typed text back. Cancel keeps the list as typed and leaves the "
           "ladder as it is."));
    QPushButton *replace = box.addButton(tr("Replace the List"), QMessageBox::AcceptRole);
    QPushButton *cancel = box.addButton(QMessageBox::Cancel);
    box.setDefaultButton(cancel);
    box.setEscapeButton(cancel);
    box.exec();
    return box.clickedButton() == replace;
}

void ListingController::applyListing() {
    applyListingAs(editor::Document::ListingStep::Own);
}

void ListingController::applyListingAs(editor::Document::ListingStep step) {
    m_ilTimer.stop(); // what is typed is applied now
    std::vector<model::Diagnostic> errors;
    m_editingListing = true;
    const bool ok = m_document->setListing(m_il->text(), &errors, step);
    m_listingErrors = errors; // when ok: the fuzzy forms of the text as typed
    if (ok || errors.empty()) {
        m_ladder->setNotice(QString());
        if (ok && !m_errorsMessage.isEmpty() && statusBar()->currentMessage() == m_errorsMessage)
            statusBar()->clearMessage();
    } else {
        const model::Diagnostic &first = errors.front();
        m_ladder->setNotice(
            tr("The instruction list has %1: line %2: %3. The ladder shows the last valid "
               "program.")
                .arg(errors.size() == 1 ? tr("an error") : tr("%1 errors").arg(errors.size()))
                .arg(first.location.line)
                .arg(first.message));
    }
    // While the text is invalid the ladder keeps the last valid program; the errors show in
    // the listing and in the problems panel.
    refreshFromDocument();
    m_editingListing = false;
}

QString ListingController::pendingListing() const {
    return model::hasErrors(m_listingErrors) ? m_il->text() : QString();
}

void ListingController::applyFix(const model::Diagnostic &d) {
    if (!d.fix)
        return;
    if (d.fix->firstRung >= 0) {
        m_document->replaceRungs(d.fix->firstRung, d.fix->lastRung - d.fix->firstRung + 1,
                                 d.fix->rungs, d.fix->label);
        return;
    }
    // A listing fix rewrites the lines of the text as typed, the rest of it untouched, as one
    // step of the project's undo (Edit > Undo) and of the list's own (Ctrl+Z there). FZ001/FZ002
    // keep the program, FZ004-FZ006 reorder it: the step's redo and undo bring the program along
    // with the text in place, so that no second step ("Edit instruction list") is pushed.
    if (m_ilTimer.isActive())
        applyListing(); // what was typed before the fix is a step of its own
    const int first = d.fix->firstLine - 1;
    const int last = d.fix->lastLine - 1;
    if (first < 0 || last >= m_il->lines() || first > last)
        return;
    QStringList before;
    for (int line = first; line <= last; ++line)
        before << m_il->lineText(line);
    QStringList after = d.fix->listing.split(QLatin1Char('\n'));
    if (after.size() > 1 && after.back().isEmpty())
        after.removeLast();
    // The replaced lines count as typed: they are applied into the fix's own undo step.
    const auto follow = [this] { applyListingAs(editor::Document::ListingStep::InPlace); };
    m_document->undoStack()->push(
        new editor::ListingLinesCommand(m_il, first, before, after, follow, d.fix->label));
}

QAction *ListingController::undoAction(bool redo, QObject *owner) {
    // As QUndoStack's own actions, but the list's pending edit (typed, not yet applied)
    // becomes a step first: Undo then takes back what was just typed, and no step of the
    // stack runs on a text the program has not caught up with.
    QUndoStack *stack = m_document->undoStack();
    auto *action = new QAction(owner);
    const auto label = [redo, stack] {
        const QString what = redo ? stack->redoText() : stack->undoText();
        if (what.isEmpty())
            return redo ? tr("&Redo") : tr("&Undo");
        //: %1 is the step's label, e.g. "Insert rung"
        return redo ? tr("&Redo %1").arg(what) : tr("&Undo %1").arg(what);
    };
    const auto update = [this, action, label, redo, stack] {
        action->setText(label());
        action->setEnabled((redo ? stack->canRedo() : stack->canUndo()) ||
                           (!redo && (m_ilTimer.isActive() || model::hasErrors(m_listingErrors))));
    };
    update();
    // The action as the context: they go with it (a new language builds new ones), and
    // ~MainWindow disconnects the stack and the list from every action before they go.
    connect(stack, &QUndoStack::indexChanged, action, update);
    connect(stack, &QUndoStack::cleanChanged, action, update);
    connect(m_il, &editor::IlEditor::listingEdited, action, update);
    connect(action, &QAction::triggered, this, [this, redo, stack] {
        if (m_ilTimer.isActive())
            applyListing();
        // Text the program cannot follow (it has errors) is the list's own business: the
        // stack's step would overwrite it with the last valid program's listing.
        if (!redo && model::hasErrors(m_listingErrors) && m_il->isUndoAvailable()) {
            m_il->undo();
            applyListing();
            return;
        }
        // A step of the rungs would replace the list as typed: asked first.
        const int step = redo ? stack->index() : stack->index() - 1;
        if (m_document->stepChangesRungs(step) && !mayReplaceTypedList())
            return;
        redo ? stack->redo() : stack->undo();
    });
    return action;
}

void ListingController::updateMonitorLines(bool typed) {
    const auto instructions = m_document->sharedInstructions();
    if (!typed) {
        m_il->setMonitorLines(m_document->printedListing().instructionOfLine, instructions);
        return;
    }
    // The text as typed: its own lines when it holds the program's instructions one for one,
    // else no values (they would stand on the wrong lines).
    if (m_typedSteps.text == m_il->text() && !m_typedSteps.instructionOfLine.empty())
        m_il->setMonitorLines(m_typedSteps.instructionOfLine, instructions);
    else
        m_il->setMonitorLines({}, nullptr);
}

} // namespace rung::app
