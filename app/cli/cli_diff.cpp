#include "cli_diff.h"
#include "app/tr.h"

#include "cli_common.h"

#include "model/compare/compare.h"
#include "model/compare/project_text.h"
#include "model/ladder/ladder_text.h"

#include <QCoreApplication>
#include <QFileInfo>

namespace rung::app {

namespace {

const QString kNull = QStringLiteral("/dev/null");

// The target a file names itself (a project's, a ladder text's header, a listing's first
// line), or empty; read only to give a listing without one its partner's target.
QString namedTarget(const QString &path, const QString &from) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    const QString kind = !from.isEmpty() ? from
                         : suffix == QLatin1String(model::kProjectExtension)
                             ? QStringLiteral("project")
                         : suffix == QLatin1String("ladder") ? QStringLiteral("ladder")
                                                             : QStringLiteral("il");
    if (kind == QLatin1String("project")) {
        auto project = model::loadProject(path, nullptr);
        return project ? project->target->id : QString();
    }
    QByteArray bytes;
    QString error;
    if (!readInputFile(path, &bytes, &error))
        return {};
    const QString text = QString::fromUtf8(bytes);
    return kind == QLatin1String("ladder") ? model::ladderTextTarget(text)
                                           : model::declaredTarget(text);
}

// A side read for comparing: everything it holds must be there, or the comparison would
// report less than the files differ by.
bool loadSide(const CommonOptions &options, model::Project *project, QString *error) {
    Input input;
    if (!loadInput(options, &input, error))
        return false;
    QStringList problems;
    for (const model::Diagnostic &d : input.problems) {
        // A syntax error leaves a line out; a listing's rung that does not convert is not in
        // its ladder. A ladder's rung the list cannot hold is still compared (by its drawing).
        const bool lost =
            d.code == QLatin1String("SYN001") ||
            (input.kind == InputKind::Listing && d.severity == model::Severity::Error);
        if (lost)
            problems << formatDiagnostic(input.file, d);
    }
    if (!problems.isEmpty()) {
        *error = problems.join(QLatin1Char('\n')) + QLatin1Char('\n') +
                 DiffTr::tr("%1 does not read whole, so it is not compared").arg(input.file);
        return false;
    }
    *project = input.project;
    if (input.kind == InputKind::Listing)
        model::addInstructionComments(input.list, &project->program);
    return true;
}

} // namespace

QString diffUsage() {
    return DiffTr::tr(
        "  rungstudio-cli diff A B [--target T] [--model M] [--from il|ladder|project] "
        "[--format text|json]\n"
        "        (exit 0 the same, 1 different, 2 error)");
}

QString showUsage() {
    return DiffTr::tr("  rungstudio-cli show FILE   (a project as text to read and diff: git's "
                      "textconv)");
}

int runDiffCommand(const QStringList &args, QTextStream &out, QTextStream &err) {
    QStringList files;
    QString format = QStringLiteral("text");
    CommonOptions options;
    for (qsizetype i = 0; i < args.size(); ++i) {
        const QString &a = args[i];
        if (a == QLatin1String("--format") || a == QLatin1String("--target") ||
            a == QLatin1String("--model") || a == QLatin1String("--from")) {
            if (i + 1 >= args.size()) {
                err << DiffTr::tr("%1 needs a value").arg(a) << '\n' << diffUsage() << '\n';
                return 2;
            }
            const QString v = args[++i];
            if (a == QLatin1String("--format"))
                format = v;
            else if (a == QLatin1String("--target"))
                options.target = v;
            else if (a == QLatin1String("--model"))
                options.model = v;
            else
                options.from = v;
        } else if (a.startsWith(QLatin1String("--"))) {
            err << DiffTr::tr("unknown option %1").arg(a) << '\n' << diffUsage() << '\n';
            return 2;
        } else {
            files << a;
        }
    }
    if (files.size() != 2) {
        err << DiffTr::tr("diff takes two files, A and B") << '\n' << diffUsage() << '\n';
        return 2;
    }
    if (format != QLatin1String("text") && format != QLatin1String("json")) {
        err << DiffTr::tr("--format must be text or json, not %1").arg(format) << '\n';
        return 2;
    }
    // A listing that names no target takes --target, else its partner's.
    QString targets[2];
    for (int k = 0; k < 2; ++k)
        targets[k] = options.target.isEmpty() && files[k] != kNull
                         ? namedTarget(files[k], options.from)
                         : options.target;
    model::Project projects[2];
    bool empty[2] = {false, false};
    for (int k = 0; k < 2; ++k) {
        if (files[k] == kNull) {
            empty[k] = true;
            continue;
        }
        CommonOptions side = options;
        side.file = files[k];
        side.target = targets[k].isEmpty() ? targets[1 - k] : targets[k];
        QString error;
        if (!loadSide(side, &projects[k], &error)) {
            err << error << '\n';
            return 2;
        }
    }
    if (empty[0] && empty[1]) {
        err << DiffTr::tr("diff needs at least one file that is not /dev/null") << '\n';
        return 2;
    }
    for (int k = 0; k < 2; ++k) {
        if (!empty[k])
            continue;
        // git's /dev/null: a file added or deleted, compared with an empty program.
        const model::Project &other = projects[1 - k];
        projects[k].target = other.target;
        projects[k].model = other.model;
        projects[k].program.target = other.target;
    }
    if (projects[0].target != projects[1].target) {
        err << DiffTr::tr("%1 is a program for %2 and %3 one for %4: only programs of one PLC are "
                          "compared")
                   .arg(files[0], projects[0].target->displayName, files[1],
                        projects[1].target->displayName)
            << '\n';
        return 2;
    }
    const model::Comparison comparison = model::compareProjects(projects[0], projects[1]);
    if (format == QLatin1String("json"))
        out << QString::fromUtf8(model::comparisonJson(comparison, files[0], files[1]));
    else
        out << model::comparisonText(comparison, files[0], files[1]);
    return comparison.equal() ? 0 : 1;
}

int runShowCommand(const QStringList &args, QTextStream &out, QTextStream &err) {
    if (args.size() != 1 || args[0].startsWith(QLatin1String("--"))) {
        err << DiffTr::tr("usage:") << '\n' << showUsage() << '\n';
        return 2;
    }
    const QString &file = args[0];
    model::ProjectError error;
    const auto project = model::loadProject(file, &error);
    if (project) {
        out << model::projectText(*project);
        return 0;
    }
    // A textconv that fails stops git diff: a file that is no project (a merge left its
    // markers in it, a listing named .rung) is shown as it is, after why.
    QByteArray bytes;
    QString ioError;
    if (!readInputFile(file, &bytes, &ioError)) {
        err << ioError << '\n';
        return 2;
    }
    out << QStringLiteral("; ") << DiffTr::tr("not read as a project: %1").arg(error.message)
        << '\n'
        << QString::fromUtf8(bytes);
    return 0;
}

} // namespace rung::app
