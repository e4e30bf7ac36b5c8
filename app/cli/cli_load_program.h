#pragma once

// A program to run, from what the IDE saves and draws: a listing (.il, any other extension),
// a ladder text (.ladder) or a project (.rung), read as `check` reads them (cli_common.h).
// The `simulate` command runs what this loads; the virtual PLC (`serve`) can load the same.

#include "cli_common.h"

#include "model/convert/convert.h"
#include "model/listing/il.h"

#include <QString>
#include <QStringList>

namespace rung::app {

struct LoadedProgram {
    QString file;
    InputKind kind = InputKind::Listing;
    const model::Target *target = nullptr;
    const model::ModelVariant *model = nullptr;
    model::InstructionList list; // the listing (a ladder or a project: its canonical listing)
    model::LadderProgram ladder; // a ladder text's or project's rungs (a listing: drawn from it)
    // A ladder or a project: the cell of each instruction of `list`, so a finding about an
    // instruction can say its rung (the file has no listing lines).
    std::vector<model::CellOrigin> origin;
};

enum class LoadStatus {
    Ok,
    ProgramErrors, // the file reads, but what it holds cannot run: exit 1
    IoError,       // usage or I/O: exit 2
};

// Loads FILE for the target (`--target`, else the file's own: a "; target:" line, the
// LADDER line, the project's) and model. On ProgramErrors `errors` holds one line per
// problem as `check` prints them (FILE:LINE:COL or FILE:rung R:row:col, the code): the
// syntax errors of a listing or a ladder text, the rungs a ladder cannot list (they would
// not run), and a project's list typed with errors (pendingListing: its newest work is not in
// its program). On IoError `errors` holds the one reason.
LoadStatus loadProgram(const QString &file, const QString &target, const QString &model,
                       LoadedProgram *program, QStringList *errors);

} // namespace rung::app
