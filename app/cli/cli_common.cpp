#include "cli_common.h"

#include "model/convert.h"
#include "model/ladder_text.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>

namespace rung::app {

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(rung::app::Cli)
};

constexpr qint64 kMaxInputBytes = 64 * 1024 * 1024;

QString targetFromLadder(const QString &text) {
    static const QRegularExpression re(QStringLiteral("^\\s*LADDER\\s+(\\w+)"));
    const auto m = re.match(text);
    return m.hasMatch() ? m.captured(1) : QString();
}

model::Diagnostic syntaxError(int line, int column, const QString &message) {
    model::Diagnostic d;
    d.code = QStringLiteral("SYN001");
    d.location.line = line;
    d.location.column = column;
    d.message = message;
    return d;
}

} // namespace

bool parseCommonOptions(const QStringList &args, CommonOptions *options, QStringList *rest,
                        QString *error) {
    for (qsizetype i = 0; i < args.size(); ++i) {
        const QString &a = args[i];
        auto value = [&](QString *into) {
            if (i + 1 >= args.size()) {
                *error = Tr::tr("%1 needs a value").arg(a);
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
        *error = Tr::tr("no FILE given");
        return false;
    }
    return true;
}

bool loadInput(const CommonOptions &options, Input *input, QString *error) {
    input->file = options.file;
    const QString suffix = QFileInfo(options.file).suffix().toLower();
    QString from = options.from;
    if (from.isEmpty())
        from = suffix == QLatin1String(model::kProjectExtension) ? QStringLiteral("project")
               : suffix == QLatin1String("ladder")               ? QStringLiteral("ladder")
                                                                 : QStringLiteral("il");
    if (from == QLatin1String("il"))
        input->kind = InputKind::Listing;
    else if (from == QLatin1String("ladder"))
        input->kind = InputKind::Ladder;
    else if (from == QLatin1String("project"))
        input->kind = InputKind::Project;
    else {
        *error = Tr::tr("--from must be il, ladder or project, not %1").arg(from);
        return false;
    }

    if (input->kind == InputKind::Project) {
        model::ProjectError pe;
        auto project = model::loadProject(options.file, &pe);
        if (!project) {
            *error = pe.message;
            return false;
        }
        input->project = *project;
        input->target = project->target;
        if (!options.target.isEmpty() && model::Target::byId(options.target) != project->target) {
            *error = Tr::tr("%1 is a %2 project, not %3")
                         .arg(options.file, project->target->id, options.target);
            return false;
        }
        input->model =
            input->target->model(options.model.isEmpty() ? project->model : options.model);
        input->ladder = project->program;
    } else {
        QFile f(options.file);
        if (!f.open(QIODevice::ReadOnly)) {
            *error = Tr::tr("cannot read %1: %2").arg(options.file, f.errorString());
            return false;
        }
        if (f.size() > kMaxInputBytes) {
            *error = Tr::tr("%1 is %2 MB; the limit is %3 MB")
                         .arg(options.file)
                         .arg(f.size() / (1024 * 1024))
                         .arg(kMaxInputBytes / (1024 * 1024));
            return false;
        }
        const QString text = QString::fromUtf8(f.readAll());
        QString targetId = options.target;
        if (targetId.isEmpty())
            targetId = input->kind == InputKind::Ladder ? targetFromLadder(text)
                                                        : model::declaredTarget(text);
        if (targetId.isEmpty()) {
            *error =
                Tr::tr("%1: which PLC? Give --target vpc|vigor|cpm1|pl110 or a \"; target: NAME\" "
                       "first line")
                    .arg(options.file);
            return false;
        }
        input->target = model::Target::byId(targetId);
        if (!input->target) {
            *error = Tr::tr("unknown target %1 (vpc, vigor, cpm1, pl110)").arg(targetId);
            return false;
        }
        if (!options.model.isEmpty()) {
            input->model = input->target->model(options.model);
            if (!input->model) {
                *error =
                    Tr::tr("%1 has no model %2").arg(input->target->displayName, options.model);
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
        *error = Tr::tr("%1 has no model %2").arg(input->target->displayName, options.model);
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
    const QString severity = d.severity == model::Severity::Error     ? Tr::tr("error")
                             : d.severity == model::Severity::Warning ? Tr::tr("warning")
                                                                      : Tr::tr("note");
    QString where;
    if (d.location.onListing())
        where = QStringLiteral("%1:%2:%3")
                    .arg(file)
                    .arg(d.location.line)
                    .arg(std::max(1, d.location.column));
    else if (d.location.onLadder())
        where = QStringLiteral("%1:rung %2:%3:%4")
                    .arg(file)
                    .arg(d.location.rung + 1)
                    .arg(std::max(0, d.location.row) + 1)
                    .arg(std::max(0, d.location.cell) + 1);
    else
        where = file;
    return QStringLiteral("%1: %2: %3 [%4]").arg(where, severity, d.message, d.code);
}

} // namespace rung::app
