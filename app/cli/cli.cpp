#include "cli.h"

#include "cli_common.h"
#include "cli_simulate.h"

#include "model/checks/checks.h"
#include "model/convert/convert.h"
#include "model/ladder/ladder_text.h"

#include <QCoreApplication>
#include <QSaveFile>

namespace rung::app {

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(rung::app::Cli)
};

QString usage() {
    return Tr::tr("usage:\n"
                  "  rungstudio-cli check FILE [--target vpc|vigor|cpm1|pl110] [--model M]\n"
                  "  rungstudio-cli convert FILE [--target T] [--from il|ladder|project] --to "
                  "il|ladder|project "
                  "[-o OUT]\n"
                  "  rungstudio-cli simulate FILE [--target T] --scans N [--period MS] [--set "
                  "DEV=VALUE@SCAN]... "
                  "--trace DEV[,DEV...]\n"
                  "FILE is a listing (.il), a ladder text (.ladder) or a project (.rung).\n"
                  "--lang en|hu|it: the language of the messages (else the locale's, LANG).\n"
                  "Exit status: 0 no error, 1 the program has errors, 2 usage or I/O error.");
}

int check(const QStringList &args, QTextStream &out, QTextStream &err) {
    CommonOptions options;
    QStringList rest;
    QString error;
    if (!parseCommonOptions(args, &options, &rest, &error) || !rest.isEmpty()) {
        err << (error.isEmpty() ? Tr::tr("unexpected argument %1").arg(rest.value(0)) : error)
            << '\n'
            << usage() << '\n';
        return 2;
    }
    Input input;
    if (!loadInput(options, &input, &error)) {
        err << error << '\n';
        return 2;
    }
    const std::vector<model::Diagnostic> all = findings(input);
    for (const model::Diagnostic &d : all)
        out << formatDiagnostic(input.file, d) << '\n';
    return model::hasErrors(all) ? 1 : 0;
}

int convert(const QStringList &args, QTextStream &out, QTextStream &err) {
    CommonOptions options;
    QStringList rest;
    QString error;
    if (!parseCommonOptions(args, &options, &rest, &error)) {
        err << error << '\n' << usage() << '\n';
        return 2;
    }
    QString to;
    QString output;
    for (qsizetype i = 0; i < rest.size(); ++i) {
        if (rest[i] == QLatin1String("--to") && i + 1 < rest.size())
            to = rest[++i];
        else if (rest[i] == QLatin1String("-o") && i + 1 < rest.size())
            output = rest[++i];
        else {
            err << Tr::tr("unexpected argument %1").arg(rest[i]) << '\n' << usage() << '\n';
            return 2;
        }
    }
    if (to != QLatin1String("il") && to != QLatin1String("ladder") &&
        to != QLatin1String("project")) {
        err << Tr::tr("--to must be il, ladder or project") << '\n' << usage() << '\n';
        return 2;
    }
    Input input;
    if (!loadInput(options, &input, &error)) {
        err << error << '\n';
        return 2;
    }
    if (model::hasErrors(input.problems)) {
        // The reasons by the documented codes of `check`, not the conversion's own.
        for (const model::Diagnostic &d : findings(input))
            if (d.severity == model::Severity::Error)
                err << formatDiagnostic(input.file, d) << '\n';
        err << Tr::tr("nothing written: the input has errors") << '\n';
        return 1;
    }
    QByteArray bytes;
    if (to == QLatin1String("il")) {
        // A listing is written in the canonical form, through its ladder, as the IDE writes it.
        const model::InstructionList canonical =
            input.kind == InputKind::Listing ? model::ladderToList(input.ladder).list : input.list;
        bytes = model::printInstructionList(canonical).toUtf8();
    } else if (to == QLatin1String("ladder")) {
        input.ladder.target = input.target;
        bytes = model::printLadderText(input.ladder).toUtf8();
    } else {
        bytes = model::projectToJson(input.project);
    }
    if (output.isEmpty()) {
        out << QString::fromUtf8(bytes);
        return 0;
    }
    QSaveFile file(output);
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit()) {
        err << Tr::tr("cannot write %1: %2").arg(output, file.errorString()) << '\n';
        return 2;
    }
    return 0;
}

} // namespace

int runCli(const QStringList &arguments, QTextStream &out, QTextStream &err) {
    const QString command = arguments.value(1);
    const QStringList args = arguments.mid(2);
    if (command == QLatin1String("check"))
        return check(args, out, err);
    if (command == QLatin1String("convert"))
        return convert(args, out, err);
    if (command == QLatin1String("simulate"))
        return runSimulateCommand(args, out, err);
    if (command == QLatin1String("--help") || command == QLatin1String("-h") ||
        command == QLatin1String("help")) {
        out << usage() << '\n';
        return 0;
    }
    if (command == QLatin1String("--version")) {
        out << QStringLiteral("rungstudio-cli %1\n").arg(QStringLiteral(RUNG_VERSION));
        return 0;
    }
    err << (command.isEmpty() ? Tr::tr("no command given")
                              : Tr::tr("unknown command %1").arg(command))
        << '\n'
        << usage() << '\n';
    return 2;
}

int runCli(const QStringList &arguments) {
    QTextStream out(stdout);
    QTextStream err(stderr);
    return runCli(arguments, out, err);
}

} // namespace rung::app
