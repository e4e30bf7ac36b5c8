#pragma once

// A program ready to run, from FILE as a listing (.il), a ladder text (.ladder) or a project
// (.rung): what a command that runs a program (serve, and simulate) does first. The file is
// read as every command reads it (cli_common.h: loadInput), then prepared as starting a
// simulation does (simulator::prepareProgram: the PLC's checks, then the compiler).

#include "simulator/program.h"

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
};

// 0 with *loaded set; 1 when the program does not start (its errors, and why, are written to
// err as "FILE:LINE:COL: error: ..."); 2 for a usage or I/O error (said on err).
int loadProgram(const ProgramOptions &options, LoadedProgram *loaded, QTextStream &err);

} // namespace rung::app
