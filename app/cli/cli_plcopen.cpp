#include "cli_plcopen.h"
#include "app/tr.h"

#include "model/convert/convert.h"
#include "model/exchange/plcopen.h"

#include <QCoreApplication>
#include <QFileInfo>

namespace rung::app {

int loadPlcopenInput(const CommonOptions &options, const QString &mapFile, bool force, Input *input,
                     int *status, QTextStream &err) {
    *status = 0;
    if (options.target.isEmpty()) {
        err << CliTr::tr("--from plcopen needs --target: which PLC the program is for") << '\n';
        return 2;
    }
    const model::Target *target = model::Target::byId(options.target);
    if (!target) {
        err << CliTr::tr("unknown target %1").arg(options.target) << '\n';
        return 2;
    }
    const model::ModelVariant *model = nullptr;
    if (!options.model.isEmpty()) {
        model = target->model(options.model);
        if (!model) {
            err << CliTr::tr("%1 has no model %2").arg(target->displayName, options.model) << '\n';
            return 2;
        }
    }
    model::DeviceMapping mapping;
    if (!mapFile.isEmpty()) {
        QByteArray bytes;
        QString error;
        if (!readInputFile(mapFile, &bytes, &error)) {
            err << error << '\n';
            return 2;
        }
        const auto read = model::readDeviceMapping(QString::fromUtf8(bytes), &error);
        if (!read) {
            err << mapFile << ": " << error << '\n';
            return 2;
        }
        mapping = *read;
    }
    QByteArray bytes;
    QString error;
    if (!readInputFile(options.file, &bytes, &error)) {
        err << error << '\n';
        return 2;
    }
    const model::PlcopenImport imported = model::importPlcopen(bytes, *target, model, mapping);
    if (!imported.fileTarget.isEmpty() && imported.fileTarget != target->id)
        err << CliTr::tr("%1: note: the file was written by Rung Studio for %2; it is read for %3")
                   .arg(options.file, imported.fileTarget, target->id)
            << '\n';
    for (const QString &note : imported.notes)
        err << options.file << ": " << CliTr::tr("note") << ": " << note << '\n';
    for (const model::ImportIssue &i : imported.issues)
        err << QStringLiteral("%1:%2: %3: %4: %5")
                   .arg(options.file)
                   .arg(i.line)
                   .arg(CliTr::tr("error"), i.element, i.message)
            << '\n';
    for (const model::UnmappedVariable &u : imported.unmapped)
        err << QStringLiteral("%1:%2: %3: ").arg(options.file).arg(u.line).arg(CliTr::tr("error"))
            << (u.proposed.isEmpty()
                    ? CliTr::tr("variable %1 (%2) names no device of %3, and none is free for it")
                          .arg(u.name, u.type, target->displayName)
                    : CliTr::tr("variable %1 (%2) names no device of %3; proposed: %4")
                          .arg(u.name, u.type, target->displayName, u.proposed))
            << '\n';
    if (!imported.unmapped.empty()) {
        err << CliTr::tr("A mapping file with the devices proposed (check them, then give it with "
                         "--map FILE):")
            << '\n';
        for (const model::UnmappedVariable &u : imported.unmapped)
            err << u.name << " = " << (u.proposed.isEmpty() ? QStringLiteral("?") : u.proposed)
                << '\n';
    }
    if (!imported.project) {
        err << CliTr::tr("nothing written: the file holds no ladder to import") << '\n';
        return 1;
    }
    if (!imported.complete()) {
        *status = 1;
        if (!force) {
            err << CliTr::tr("nothing written: the file holds what %1 cannot take, listed above "
                             "(--force writes the rest)")
                       .arg(target->displayName)
                << '\n';
            return 1;
        }
        err << CliTr::tr("written without what is listed above (--force)") << '\n';
    }
    input->file = options.file;
    input->kind = InputKind::Project;
    input->project = *imported.project;
    input->target = target;
    input->model = target->model(input->project.model);
    if (!input->model)
        input->model = &target->defaultModel();
    input->ladder = input->project.program;
    const model::ToListingResult il = model::ladderToList(input->ladder);
    input->list = il.list;
    input->listValid = il.ok();
    for (const model::Diagnostic &d : il.problems)
        input->problems.push_back(d);
    return 0;
}

QByteArray plcopenOutput(const Input &input, QTextStream &err) {
    const model::PlcopenExport out =
        model::exportPlcopen(input.project, QFileInfo(input.file).completeBaseName());
    for (const QString &note : out.notes)
        err << input.file << ": " << CliTr::tr("note") << ": " << note << '\n';
    return out.xml;
}

} // namespace rung::app
