#pragma once

// The open project as both views see it: the ladder is the program, the listing is derived
// from it (canonical form), every change goes through the undo stack as one step.

#include "model/checks/checks.h"
#include "model/convert/convert.h"
#include "model/convert/typed_listing.h"
#include "model/project/project.h"

#include <QObject>
#include <QUndoStack>

#include <functional>
#include <map>
#include <memory>
#include <tuple>

namespace rung::editor {

class Document : public QObject {
    Q_OBJECT

public:
    explicit Document(QObject *parent = nullptr);

    // A new empty program for a target and model.
    void reset(const model::Target &target, const QString &modelName);
    void setProject(const model::Project &project, const QString &path);

    const model::Project &project() const { return m_project; }
    const model::Target &target() const { return *m_project.target; }
    const model::ModelVariant *modelVariant() const;
    const model::LadderProgram &ladder() const { return m_project.program; }
    QUndoStack *undoStack() { return &m_undo; }

    QString path() const { return m_path; }
    void setPath(const QString &path);
    // A program with no project file yet may still have a name: the listing it was imported
    // from ("traffic.il"), the example it copies ("Traffic light"). The title and the printed
    // header show it, and Save As offers `suggestedPath` (the folder and name it came from,
    // as a project). Until the next setProject or reset; a path, once saved, names it.
    void setUntitledName(const QString &name, const QString &suggestedPath);
    // The file's name, else the untitled name, else "Untitled".
    QString name() const;
    // Where Save As starts: the file itself, else the suggestion, else empty.
    QString suggestedPath() const { return m_path.isEmpty() ? m_suggestedPath : m_path; }
    bool isModified() const { return !m_undo.isClean(); }
    void markSaved() { m_undo.setClean(); }
    // The program holds work that no file has (recovered after a crash): no undo step is
    // clean, so it stays modified, whatever undo does, until it is saved.
    void markUnsaved() { m_undo.resetClean(); }

    // The canonical listing of the ladder and where each rung starts in it.
    const model::ToListingResult &listing() const { return *m_listing; }
    // The listing's instructions, kept alive for a reader that holds them past the next
    // refresh (the list pane's values), without a copy.
    std::shared_ptr<const std::vector<model::Instruction>> sharedInstructions() const {
        return {m_listing, &m_listing->list.instructions};
    }
    // The listing as the list pane shows it: a rung the list cannot express (a bridge, an
    // element the target lacks) has a placeholder comment in its place, "; [[3:9f2c41]] Rung
    // 3 is not in the list: ...", that names it and why; setListing puts that rung back
    // where the line stands, so editing the list never drops it.
    QString listingText() const { return m_listingText; }
    // Its line map: the line of each instruction, the instruction of each line.
    const model::PrintedListing &printedListing() const { return m_printed; }
    // The rungs that have a placeholder line in the list, with the reason the line gives: the
    // list (and a file written from it) holds less than the ladder while there is one.
    struct Unlisted {
        int rung;
        QString reason;
    };
    const std::vector<Unlisted> &unlistedRungs() const { return m_unlisted; }
    // A contact of a listed rung that is on no path to an output (LD002) is not in the list
    // either: a marked line before its rung's instructions names it, "; [[3:9f2c41@2,1]] Rung
    // 3: X5 (row 2, column 1) ...", and setListing keeps the contact in the rebuilt rung while
    // that line stays (deleting the line lets it go).
    // model/convert/typed_listing.h reads such lines back (model::placeholderKey).
    int rungOfLine(int line) const; // 1-based line of the listing text -> rung, -1 if none
    int firstLineOfRung(int rung) const;
    // The line of the list a finding on the ladder belongs to: a left-out contact's marked
    // line, the line of the instruction written from the cell, else its rung's first line.
    int lineOf(const model::Location &location) const;
    int stepCount() const;

    const std::vector<model::Diagnostic> &diagnostics() const { return m_diagnostics; }

    // Devices worth offering when an operand is typed: those the program uses and those the
    // symbol table names, in address order, as the target writes them; withNames adds the
    // symbol's name after two spaces ("X0  Start").
    QStringList knownDevices(bool withNames = false) const;

    // Asked before each edit of the rungs that does not come from the list (the ladder's, a
    // fix's), with the rungs it replaces: false leaves the program as it is and pushes no step.
    // The main window asks the user there before an edit replaces a list typed with errors, and
    // takes a list typed just now first.
    void setRungEditGuard(std::function<bool(int first, int count)> guard) {
        m_rungEditGuard = std::move(guard);
    }
    // Whether the undo stack's step at this index changes the rungs (a symbol's does not).
    bool stepChangesRungs(int index) const;

    // Edits, each one undo step with its label.
    void replaceRungs(int first, int count, const std::vector<model::Rung> &rungs,
                      const QString &label);
    void setRung(int index, const model::Rung &rung, const QString &label);
    void insertRung(int index, const model::Rung &rung);
    void removeRungs(int first, int count);
    void setSymbols(const std::vector<model::Symbol> &symbols);
    void setWatchLists(const std::vector<model::WatchList> &lists, const QString &label);
    // The project's communication ports (model::Project::ports), as a whole; no step when
    // they are the same.
    void setPorts(const QJsonObject &ports, const QString &label);
    // How setListing changes the program: as an undo step of its own, or in place for an undo
    // step that holds the change itself (a fix of the typed list, ListingLinesCommand), or not
    // at all: Check only says whether the text would be taken (and its errors).
    enum class ListingStep { Own, InPlace, Check };
    // Rebuilds the ladder from listing text; false (nothing changed) when the text has errors,
    // which land in *errors: the syntax errors, or when the text parses but cannot be drawn
    // every finding of the listing checks by its documented code (as `rungstudio-cli check`).
    // On success *errors holds the fuzzy forms of the text as typed (FZ*, with the canonical
    // rewrite as a fix); the program's other findings come from the ladder (diagnostics()).
    bool setListing(const QString &text, std::vector<model::Diagnostic> *errors,
                    ListingStep step = ListingStep::Own);

    // Converts and checks the program again, as it is (the findings in the language now
    // installed): programChanged, with rungsRevision() as it was.
    void recheck() { refresh(); }
    // Counts the changes of the rungs (an edit, an undo, another project): the list pane takes
    // the canonical listing again only when this moved, so a change of the symbols or the
    // watch lists never replaces the list as typed.
    quint64 rungsRevision() const { return m_rungsRevision; }

    // Used by the undo commands only.
    void applyRungs(int first, int count, const std::vector<model::Rung> &rungs);
    void applySymbols(const std::vector<model::Symbol> &symbols);
    void applyWatchLists(const std::vector<model::WatchList> &lists);
    void applyPorts(const QJsonObject &ports);

signals:
    void programChanged();
    void pathChanged(const QString &path);
    void nameChanged(); // name() changed: a new path or untitled name
    // Another project (setProject, reset): after its programChanged. What a view said of the
    // project before is not this one's.
    void projectReplaced();

private:
    void refresh();
    void pushRungs(int first, int count, const std::vector<model::Rung> &rungs,
                   const QString &label);
    // Keeps rung `index` for the placeholder line that stands for it; returns the line's key.
    QString heldRung(int index);

    model::Project m_project;
    QString m_path;
    QString m_untitledName;
    QString m_suggestedPath;
    QUndoStack m_undo;
    std::shared_ptr<const model::ToListingResult> m_listing =
        std::make_shared<const model::ToListingResult>();
    QString m_listingText;
    model::PrintedListing m_printed;
    std::vector<Unlisted> m_unlisted;
    quint64 m_rungsRevision = 0;
    std::vector<int> m_rungLine; // first line of each rung in m_listingText (1-based)
    // The marked line of each left-out contact, by rung, row and column.
    std::map<std::tuple<int, int, int>, int> m_leftOutLine;
    // Every rung a placeholder line has stood for since the project was opened, by the key the
    // line carries: text typed from an older list still finds its rung.
    model::HeldRungs m_held;
    std::vector<model::Diagnostic> m_diagnostics;
    std::function<bool(int first, int count)> m_rungEditGuard;
};

} // namespace rung::editor
