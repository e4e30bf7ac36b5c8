#pragma once

// A program ready to run, from FILE as a listing (.il), a ladder text (.ladder) or a project
// (.rung): what a command that runs a program (serve, and simulate) does first. The file is
// read as every command reads it (cli_common.h: loadInput), then prepared as starting a
// simulation does (the PLC's checks, then the compiler). A ladder text or a project is
// checked as `check` checks it (model::checkLadder): a finding names its rung and cell.

#include "cli_common.h"

#include "model/convert/convert.h"
#include "simulator/program.h"

#include <QJsonObject>
#include <QString>
#include <QTextStream>

#include <memory>

namespace rung::app {

struct ProgramOptions {
    QString file;
    QString target; // --target; empty: from the file
    QString model;  // --model; empty: the file's or the family's default
};

struct LoadedProgram {
    std::shared_ptr<const simulator::Program> program;
    const model::Target *target = nullptr;
    InputKind kind = InputKind::Listing;
    // A ladder text or a project: the cell of each instruction the program runs (parallel to
    // its steps' instruction indices), so a runtime error can name its rung. Empty for a
    // listing, whose instructions carry their lines.
    std::vector<model::CellOrigin> origin;
    const model::ModelVariant *model = nullptr; // the model it runs on
    QJsonObject ports; // a project's port settings (docs/network-format.md); empty otherwise
};

// 0 with *loaded set; 1 when the program does not start (its errors, and why, are written to
// err as "FILE:LINE:COL: error: ...", or "FILE:rung R:ROW:COL: error: ..." for a ladder text or
// a project); 2 for a usage or I/O error (said on err).
int loadProgram(const ProgramOptions &options, LoadedProgram *loaded, QTextStream &err);

} // namespace rung::app
