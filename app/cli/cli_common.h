#pragma once

// What every command does first: read FILE as a listing, a ladder text or a project, for the
// target named by --target, by the file itself, or by a "; target: NAME" first line.

#include "model/diagnostic.h"
#include "model/project.h"

#include <QStringList>
#include <QTextStream>

namespace rung::app {

enum class InputKind { Listing, Ladder, Project };

struct Input {
    QString file;
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

// "FILE:LINE:COL: error: message [CODE]" or "FILE:rung R:row:col: ..." (1-based).
QString formatDiagnostic(const QString &file, const model::Diagnostic &d);

} // namespace rung::app
