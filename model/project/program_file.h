#pragma once

// Opening a file the user names as a program: a project (.rung), a ladder text (.ladder) or
// an instruction list (any other name), and choosing the PLC it is for. The IDE's File > Open
// and every command of rungstudio-cli read a program file here, so that both choose alike.

#include "model/project/project.h"

#include <cstdint>
#include <optional>

namespace rung::model {

enum class ProgramFileKind : std::uint8_t { Listing, LadderText, Project };

// What a file is by its name: ".rung" a project, ".ladder" a ladder text, else a listing.
ProgramFileKind programFileKind(const QString &path);

struct ProgramFileOptions {
    QString target; // as the user asked (--target, the IDE's command line); empty: the file says
    // The target the caller has in hand (the IDE's open project) for a text that names none.
    // Empty: none, and a listing that names no target opens with none (the caller asks).
    QString fallbackTarget;
    qint64 maxBytes = 8 * 1024 * 1024; // the most a listing or ladder text may hold
};

struct ProgramFile {
    ProgramFileKind kind = ProgramFileKind::Listing;
    const Target *target = nullptr;
    QString text;    // the listing or ladder text as read; empty for a project
    Project project; // the project as loaded (kind Project)
};

// Reads `path` as `kind` and chooses its target:
// - a project's is its own; another one asked for is an error;
// - a ladder text's: as asked, else its LADDER line, else the fallback, else the first family
//   (its reader then says the text has no LADDER line);
// - a listing's: as asked, else its "; target:" line (declaredTarget), else with a fallback
//   the family whose syntax reads it, the fallback first (listingTarget); without a fallback
//   none: the file opens with target == nullptr and the caller says how to name it.
// Empty with *error (translated, naming the file) when it cannot be read or loaded, or a
// target named is unknown.
std::optional<ProgramFile> openProgramFile(const QString &path, ProgramFileKind kind,
                                           const ProgramFileOptions &options, QString *error);

} // namespace rung::model
