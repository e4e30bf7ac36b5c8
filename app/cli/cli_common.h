#pragma once

// What every command does first: read FILE as a listing, a ladder text or a project, for the
// target named by --target, by the file itself, or by a "; target: NAME" first line.

#include "model/checks/diagnostic.h"
#include "model/project/project.h"

#include <QStringList>
#include <QTextStream>

namespace rung::app {

enum class InputKind { Listing, Ladder, Project };

struct Input {
    QString file;
    QString text; // the listing or ladder text as read (empty for a project)
    InputKind kind = InputKind::Listing;
    const model::Target *target = nullptr;
    const model::ModelVariant *model = nullptr;
    model::InstructionList list;             // the listing (converted from the ladder if need be)
    model::LadderProgram ladder;             // the ladder (converted from the listing if need be)
    model::Project project;                  // symbols, set values, watch lists (projects only)
    std::vector<model::Diagnostic> problems; // syntax errors and conversion problems
    bool listValid = false;
};

struct CommonOptions {
    QString file;
    QString target;
    QString model;
    QString from;
};

// Reads --target/--model/--from and the FILE argument; the rest stays in *rest.
bool parseCommonOptions(const QStringList &args, CommonOptions *options, QStringList *rest,
                        QString *error);
// Loads the input; false with *error set (translated) for usage and I/O errors.
bool loadInput(const CommonOptions &options, Input *input, QString *error);

// Reads at most the size limit (and one byte more to tell it is over), so that a pipe or a
// device that never ends is refused too; false with *error set (translated).
bool readInputFile(const QString &path, QByteArray *bytes, QString *error);
// What `check` prints: the syntax errors, or when the text parses every check's findings.
std::vector<model::Diagnostic> findings(const Input &input);

// A project saved while the instruction list as typed in the IDE had errors keeps that text
// (pendingListing) beside its rungs, the last valid program: the text is the user's newest
// work and not in the rungs. False when the input holds no such text; else *notice says so
// plainly and *errors holds the errors of the text, located in it (see pendingLocation).
bool pendingListing(const Input &input, QString *notice, std::vector<model::Diagnostic> *errors);
// Where pendingListing's errors are: "FILE:pendingListing", for formatDiagnostic.
QString pendingLocation(const QString &file);

// "FILE:LINE:COL: error: message [CODE]" or "FILE:rung R:row:col: ..." (1-based).
QString formatDiagnostic(const QString &file, const model::Diagnostic &d);

} // namespace rung::app
