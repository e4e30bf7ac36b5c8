#include "cli_common.h"

#include "app/tr.h"
#include "model/checks/checks.h"
#include "model/convert/convert.h"
#include "model/ladder/ladder_text.h"
#include "model/project/file_read.h"
#include "model/project/program_file.h"
#include "model/target/target_lists.h"

#include <QCoreApplication>

namespace rung::app {

namespace {

// Checking takes about 0.7 s and 130 MB per MB of listing (8 MB: 6 s, 1 GB); a real program
// of 10,000 rungs is well under 1 MB. Read at most one byte more than this, so that a device or a
// pipe that never ends (/dev/zero) is refused too.
constexpr qint64 kMaxInputBytes = 8 * 1024 * 1024;

model::Diagnostic syntaxError(int line, int column, const QString &message) {
    model::Diagnostic d;
    d.code = QStringLiteral("SYN001");
    d.location.line = line;
    d.location.column = column;
    d.message = message;
    return d;
}

} // namespace

bool readInputFile(const QString &path, QByteArray *bytes, QString *error) {
    QString ioError;
    const model::ReadStatus status = model::readAtMost(path, kMaxInputBytes, bytes, &ioError);
    if (status != model::ReadStatus::Ok)
        *error = model::readFailure(status, path, kMaxInputBytes, ioError);
    return status == model::ReadStatus::Ok;
}

std::vector<model::Diagnostic> findings(const Input &input) {
    std::vector<model::Diagnostic> all;
    for (const model::Diagnostic &d : input.problems)
        if (d.code == QLatin1String("SYN001"))
            all.push_back(d);
    model::CheckOptions options;
    options.model = input.model;
    if (input.kind == InputKind::Listing)
        options.source = &input.text;
    // A text that parses is checked whole, even when it cannot be drawn (or listed): the checks
    // name those problems by their documented codes, next to every other finding. A listing
    // with lines that do not parse gets what the others show already (Document::setListing).
    if (all.empty()) {
        all = input.kind == InputKind::Listing ? model::checkList(input.list, options)
                                               : model::checkLadder(input.ladder, options);
    } else if (input.kind == InputKind::Listing) {
        options.parsedLinesOnly = true;
        for (model::Diagnostic &d : model::checkList(input.list, options))
            all.push_back(std::move(d));
    }
    model::sortDiagnostics(all);
    return all;
}

QString pendingLocation(const QString &file) {
    return file + QStringLiteral(":pendingListing");
}

bool pendingListing(const Input &input, QString *notice, std::vector<model::Diagnostic> *errors) {
    const QString &text = input.project.pendingListing;
    if (input.kind != InputKind::Project || text.isEmpty())
        return false;
    *notice = CliTr::tr("%1 holds an instruction list typed in Rung Studio that is not in its "
                        "program: the list had errors when the project was saved, and is kept as "
                        "typed under the key \"pendingListing\"; the rungs are the last valid "
                        "program. Open the project in Rung Studio and fix the list.")
                  .arg(input.file);
    errors->clear();
    const model::ParseResult parsed = model::parseInstructionList(*input.target, text, input.model);
    for (const model::ParseError &e : parsed.errors)
        errors->push_back(syntaxError(e.line, e.column, e.message));
    model::CheckOptions options;
    options.model = input.model;
    options.source = &text;
    options.parsedLinesOnly = !parsed.ok();
    for (const model::Diagnostic &d : model::checkList(parsed.list, options))
        if (d.severity == model::Severity::Error)
            errors->push_back(d);
    return true;
}

bool parseCommonOptions(const QStringList &args, CommonOptions *options, QStringList *rest,
                        QString *error) {
    for (qsizetype i = 0; i < args.size(); ++i) {
        const QString &a = args[i];
        auto value = [&](QString *into) {
            if (i + 1 >= args.size()) {
                *error = CliTr::tr("%1 needs a value").arg(a);
                return false;
            }
            *into = args[++i];
            return true;
        };
        if (a == QLatin1String("--target")) {
            if (!value(&options->target))
                return false;
        } else if (a == QLatin1String("--model")) {
            if (!value(&options->model))
                return false;
        } else if (a == QLatin1String("--from")) {
            if (!value(&options->from))
                return false;
        } else if (!a.startsWith(QLatin1String("--")) && a != QLatin1String("-o") &&
                   options->file.isEmpty()) {
            options->file = a;
        } else {
            rest->append(a);
            if ((a == QLatin1String("-o") || a == QLatin1String("--to")) && i + 1 < args.size())
                rest->append(args[++i]);
        }
    }
    if (options->file.isEmpty()) {
        *error = CliTr::tr("no FILE given");
        return false;
    }
    return true;
}

bool loadInput(const CommonOptions &options, Input *input, QString *error) {
    input->file = options.file;
    model::ProgramFileKind kind = model::programFileKind(options.file);
    if (options.from == QLatin1String("il"))
        kind = model::ProgramFileKind::Listing;
    else if (options.from == QLatin1String("ladder"))
        kind = model::ProgramFileKind::LadderText;
    else if (options.from == QLatin1String("project"))
        kind = model::ProgramFileKind::Project;
    else if (!options.from.isEmpty()) {
        *error = CliTr::tr("--from must be il, ladder or project, not %1").arg(options.from);
        return false;
    }
    input->kind = kind == model::ProgramFileKind::Project      ? InputKind::Project
                  : kind == model::ProgramFileKind::LadderText ? InputKind::Ladder
                                                               : InputKind::Listing;
    model::ProgramFileOptions open;
    open.target = options.target;
    open.maxBytes = kMaxInputBytes;
    std::optional<model::ProgramFile> file =
        model::openProgramFile(options.file, kind, open, error);
    if (!file)
        return false;
    if (!file->target) { // a listing that names no PLC: a script says which
        *error = CliTr::tr("%1: which PLC? Give --target %2 or a \"; target: NAME\" first line")
                     .arg(options.file, model::targetIds().join(QLatin1Char('|')));
        return false;
    }
    input->target = file->target;
    input->text = file->text;
    if (input->kind == InputKind::Project) {
        input->project = std::move(file->project);
        input->model =
            input->target->model(options.model.isEmpty() ? input->project.model : options.model);
        input->ladder = input->project.program;
    } else {
        const QString &text = input->text;
        if (!options.model.isEmpty()) {
            input->model = input->target->model(options.model);
            if (!input->model) {
                *error =
                    CliTr::tr("%1 has no model %2").arg(input->target->displayName, options.model);
                return false;
            }
        }
        if (input->kind == InputKind::Listing) {
            model::ParseResult parsed =
                model::parseInstructionList(*input->target, text, input->model);
            for (const model::ParseError &e : parsed.errors)
                input->problems.push_back(syntaxError(e.line, e.column, e.message));
            input->list = parsed.list;
            input->listValid = parsed.ok();
            model::ToLadderResult lad = model::listToLadder(parsed.list);
            input->ladder = lad.ladder;
            if (parsed.ok())
                for (const model::Diagnostic &d : lad.problems)
                    input->problems.push_back(d);
        } else {
            model::LadderTextResult lad =
                model::parseLadderText(*input->target, text, input->model);
            for (const model::ParseError &e : lad.errors)
                input->problems.push_back(syntaxError(e.line, e.column, e.message));
            input->ladder = lad.ladder;
        }
    }
    if (options.model.isEmpty() && !input->model)
        input->model = &input->target->defaultModel();
    if (input->model == nullptr) {
        *error = CliTr::tr("%1 has no model %2").arg(input->target->displayName, options.model);
        return false;
    }
    input->project.target = input->target;
    input->project.model = input->model->name;
    input->project.program = input->ladder;
    input->project.program.target = input->target;
    if (input->kind != InputKind::Listing) {
        model::ToListingResult il = model::ladderToList(input->ladder);
        input->list = il.list;
        input->listValid = il.ok() && !model::hasErrors(input->problems);
        for (const model::Diagnostic &d : il.problems)
            input->problems.push_back(d);
    }
    return true;
}

QString formatDiagnostic(const QString &file, const model::Diagnostic &d) {
    const QString severity = d.severity == model::Severity::Error     ? CliTr::tr("error")
                             : d.severity == model::Severity::Warning ? CliTr::tr("warning")
                                                                      : CliTr::tr("note");
    QString where;
    if (d.location.onListing())
        where = QStringLiteral("%1:%2:%3")
                    .arg(file)
                    .arg(d.location.line)
                    .arg(std::max(1, d.location.column));
    else if (d.location.onLadder())
        //: A finding's place on the ladder, after the file as a compiler writes file:line:column:
        //: %1 the file, %2 the rung's number, %3 the row, %4 the column. Keep the colons.
        where = CliTr::tr("%1:rung %2:%3:%4")
                    .arg(file)
                    .arg(d.location.rung + 1)
                    .arg(std::max(0, d.location.row) + 1)
                    .arg(std::max(0, d.location.cell) + 1);
    else // a finding about the whole file (none should be): its start
        where = QStringLiteral("%1:1:1").arg(file);
    return QStringLiteral("%1: %2: %3 [%4]").arg(where, severity, d.message, d.code);
}

} // namespace rung::app
