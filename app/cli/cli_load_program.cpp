#include "cli_load_program.h"

#include <QCoreApplication>

namespace rung::app {

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(rung::app::Cli)
};

} // namespace

LoadStatus loadProgram(const QString &file, const QString &target, const QString &model,
                       LoadedProgram *program, QStringList *errors) {
    errors->clear();
    CommonOptions options;
    options.file = file;
    options.target = target;
    options.model = model;
    Input input;
    QString error;
    if (!loadInput(options, &input, &error)) {
        errors->append(error);
        return LoadStatus::IoError;
    }
    program->file = file;
    program->kind = input.kind;
    program->target = input.target;
    program->model = input.model;
    program->list = input.list;
    program->ladder = input.ladder;
    if (input.kind != InputKind::Listing)
        program->origin = model::ladderToList(input.ladder).origin;
    // What does not read, or what a ladder holds that its listing cannot (a rung that would
    // then not run): the same lines `check` prints.
    for (const model::Diagnostic &d : input.problems)
        if (d.severity == model::Severity::Error)
            errors->append(formatDiagnostic(file, d));
    QString notice;
    std::vector<model::Diagnostic> typed;
    if (pendingListing(input, &notice, &typed)) {
        for (const model::Diagnostic &d : typed)
            errors->append(formatDiagnostic(pendingLocation(file), d));
        errors->append(notice);
    }
    if (!errors->isEmpty() || !input.listValid) {
        if (errors->isEmpty()) // nothing said why: say it plainly rather than run less
            errors->append(Tr::tr("%1: the program cannot be listed whole").arg(file));
        return LoadStatus::ProgramErrors;
    }
    return LoadStatus::Ok;
}

} // namespace rung::app
