#include "cli.h"

#include "cli_common.h"
#include "cli_diff.h"
#include "cli_network.h"
#include "cli_online.h"
#include "cli_plcopen.h"
#include "cli_record.h"
#include "cli_serve.h"
#include "cli_simulate.h"
#include "cli_terminal.h"
#include "cli_test.h"

#include "app/tr.h"
#include "model/checks/checks.h"
#include "model/convert/convert.h"
#include "model/ladder/ladder_text.h"
#include "model/target/target_lists.h"

#include <QCoreApplication>
#include <QSaveFile>

#include <algorithm>
#include <iterator>

namespace rung::app {

namespace {

QString usage() {
    return CliTr::tr("usage:\n"
                     "  rungstudio-cli check FILE [--target %1] [--model M]\n"
                     "  rungstudio-cli convert FILE [--target T] [--model M] [--from "
                     "il|ladder|project|plcopen] --to il|ladder|project|plcopen "
                     "[-o OUT] [--force] [--map FILE]\n"
                     "  rungstudio-cli simulate FILE [--target T] [--model M] --scans N [--period "
                     "MS] [--set DEV=VALUE@SCAN]... "
                     "--trace DEV[,DEV...]\n"
                     "  rungstudio-cli serve FILE [--target T] [--model M] --protocol "
                     "vigor|modbus|modbus-tcp|hostlink (--pty | --port NAME | --tcp HOST:PORT) "
                     "[--station N] [--baud B] [--frame 8N1] [--period MS] [--fault KIND]\n"
                     "FILE is a listing (.il), a ladder text (.ladder) or a project (.rung).\n"
                     "--lang en|hu|it: the language of the messages (else the locale's, LANG).\n"
                     "Exit status: 0 no error, 1 the program has errors, 2 usage or I/O error.")
               .arg(model::targetIds().join(QLatin1Char('|'))) +
           QLatin1Char('\n') + networkUsage() + QLatin1Char('\n') + diffUsage() +
           QLatin1Char('\n') + showUsage() + QLatin1Char('\n') + testUsage() + QLatin1Char('\n') +
           onlineUsage() + QLatin1Char('\n') + recordUsage() + QLatin1Char('\n') + terminalUsage() +
           QLatin1Char('\n') + QStringLiteral("  rungstudio-cli --help | --version");
}

int check(const QStringList &args, QTextStream &out, QTextStream &err) {
    // A network (docs/network.md): every station's program, then the wiring.
    for (qsizetype i = 0; i < args.size(); ++i)
        if (!args[i].startsWith(QLatin1String("--")) && isNetworkFile(args[i]))
            return runNetworkCheck(args[i], args.mid(0, i) + args.mid(i + 1), out, err);
    CommonOptions options;
    QStringList rest;
    QString error;
    if (!parseCommonOptions(args, &options, &rest, &error) || !rest.isEmpty()) {
        err << (error.isEmpty() ? CliTr::tr("unexpected argument %1").arg(rest.value(0)) : error)
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
    // The rungs may check clean while the user's newest work, a list with errors, waits beside
    // them: that is no success.
    QString notice;
    std::vector<model::Diagnostic> typed;
    if (pendingListing(input, &notice, &typed)) {
        for (const model::Diagnostic &d : typed)
            out << formatDiagnostic(pendingLocation(input.file), d) << '\n';
        err << notice << '\n';
        return 1;
    }
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
    QString mapFile;
    bool force = false;
    for (qsizetype i = 0; i < rest.size(); ++i) {
        if (rest[i] == QLatin1String("--to") && i + 1 < rest.size())
            to = rest[++i];
        else if (rest[i] == QLatin1String("--map") && i + 1 < rest.size())
            mapFile = rest[++i];
        else if (rest[i] == QLatin1String("--force"))
            force = true;
        else if (rest[i] == QLatin1String("-o") && i + 1 < rest.size())
            output = rest[++i];
        else {
            err << CliTr::tr("unexpected argument %1").arg(rest[i]) << '\n' << usage() << '\n';
            return 2;
        }
    }
    if (to != QLatin1String("il") && to != QLatin1String("ladder") &&
        to != QLatin1String("project") && to != QLatin1String("plcopen")) {
        err << CliTr::tr("--to must be il, ladder, project or plcopen") << '\n' << usage() << '\n';
        return 2;
    }
    Input input;
    // Imported with --force although parts could not be: the exit status says so.
    int importStatus = 0;
    if (options.from == QLatin1String("plcopen")) {
        if (const int status =
                loadPlcopenInput(options, mapFile, force, &input, &importStatus, err);
            status != 0)
            return status;
    } else if (!mapFile.isEmpty()) {
        err << CliTr::tr("--map is for --from plcopen") << '\n';
        return 2;
    } else if (!loadInput(options, &input, &error)) {
        err << error << '\n';
        return 2;
    }
    // A project that holds a list as typed with errors (pendingListing): converted to a list or
    // a ladder, the file would hold the last valid program without the user's newest work. A
    // project keeps the text, so --to project may go on.
    QString notice;
    std::vector<model::Diagnostic> typed;
    if (to != QLatin1String("project") && pendingListing(input, &notice, &typed)) {
        for (const model::Diagnostic &d : typed)
            err << formatDiagnostic(pendingLocation(input.file), d) << '\n';
        err << notice << '\n'
            << CliTr::tr("nothing written: the list as typed would be lost") << '\n';
        return 1;
    }
    // What `check` rejects is not written (docs/cli.md): the same findings decide, so that a
    // converted file never holds a program the tool itself calls wrong. The reasons are the
    // documented codes of `check`, not the conversion's own.
    // --force overrides the checks only: a text that does not parse, or does not convert,
    // would be written with parts missing, so it is never written.
    const std::vector<model::Diagnostic> all = findings(input);
    const bool incomplete = model::hasErrors(input.problems);
    // A contact on no path to an output is left out of a listing (LD002): written as a list,
    // the program would be shorter than the drawing, so it is never written, as the IDE's
    // Export Instruction List refuses it.
    std::vector<model::Diagnostic> leftOut;
    if (to == QLatin1String("il"))
        std::copy_if(all.begin(), all.end(), std::back_inserter(leftOut),
                     [](const model::Diagnostic &d) { return d.code == QLatin1String("LD002"); });
    if (!leftOut.empty() && !incomplete) {
        for (const model::Diagnostic &d : all)
            if (d.severity == model::Severity::Error || d.code == QLatin1String("LD002"))
                err << formatDiagnostic(input.file, d) << '\n';
        err << CliTr::tr("nothing written: the listing would leave out the contacts above") << '\n';
        return 1;
    }
    const bool hasErrors = incomplete || model::hasErrors(all);
    if (hasErrors) {
        for (const model::Diagnostic &d : all)
            if (d.severity == model::Severity::Error)
                err << formatDiagnostic(input.file, d) << '\n';
        if (incomplete) {
            err << CliTr::tr("nothing written: the input does not parse or convert whole") << '\n';
            return 1;
        }
        if (!force) {
            err << CliTr::tr("nothing written: the input has errors (--force writes it anyway)")
                << '\n';
            return 1;
        }
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
    } else if (to == QLatin1String("plcopen")) {
        bytes = plcopenOutput(input, err);
    } else {
        bytes = model::projectToJson(input.project);
    }
    // Written with --force, the program still has errors: exit 1 says so, as `check` would.
    const int status = hasErrors || importStatus != 0 ? 1 : 0;
    if (output.isEmpty()) {
        out << QString::fromUtf8(bytes);
        return status;
    }
    QSaveFile file(output);
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit()) {
        err << CliTr::tr("cannot write %1: %2").arg(output, file.errorString()) << '\n';
        return 2;
    }
    return status;
}

} // namespace

int runCli(const QStringList &arguments, QTextStream &out, QTextStream &err) {
    const QString command = arguments.value(1);
    const QStringList args = arguments.mid(2);
    // `rungstudio-cli serve --help` is how most users ask; no command takes it as a value.
    if (args.contains(QLatin1String("--help")) || args.contains(QLatin1String("-h"))) {
        out << usage() << '\n';
        return 0;
    }
    if (command == QLatin1String("check"))
        return check(args, out, err);
    if (command == QLatin1String("convert"))
        return convert(args, out, err);
    if (command == QLatin1String("simulate"))
        return runSimulateCommand(args, out, err);
    if (command == QLatin1String("diff"))
        return runDiffCommand(args, out, err);
    if (command == QLatin1String("show"))
        return runShowCommand(args, out, err);
    if (command == QLatin1String("test"))
        return runTestCommand(args, out, err);
    if (command == QLatin1String("serve"))
        return runServeCommand(args, out, err);
    if (command == QLatin1String("record"))
        return runRecordCommand(args, out, err);
    if (command == QLatin1String("terminal")) {
        QTextStream in(stdin);
        return runTerminalCommand(args, in, out, err);
    }
    if (command == QLatin1String("read"))
        return runReadCommand(args, out, err);
    if (command == QLatin1String("write"))
        return runWriteCommand(args, out, err);
    if (command == QLatin1String("--help") || command == QLatin1String("-h") ||
        command == QLatin1String("help")) {
        out << usage() << '\n';
        return 0;
    }
    if (command == QLatin1String("--version")) {
        out << QStringLiteral("rungstudio-cli %1\n").arg(QStringLiteral(RUNG_VERSION));
        return 0;
    }
    err << (command.isEmpty() ? CliTr::tr("no command given")
                              : CliTr::tr("unknown command %1").arg(command))
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
