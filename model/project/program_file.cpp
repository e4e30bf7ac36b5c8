#include "model/project/program_file.h"

#include "model/ladder/ladder_text.h"
#include "model/listing/il.h"
#include "model/project/file_read.h"
#include "model/target/target_lists.h"
#include "model/tr.h"

#include <QCoreApplication>
#include <QFileInfo>

namespace rung::model {

ProgramFileKind programFileKind(const QString &path) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1String(kProjectExtension))
        return ProgramFileKind::Project;
    return suffix == QLatin1String("ladder") ? ProgramFileKind::LadderText
                                             : ProgramFileKind::Listing;
}

std::optional<ProgramFile> openProgramFile(const QString &path, ProgramFileKind kind,
                                           const ProgramFileOptions &options, QString *error) {
    ProgramFile file;
    file.kind = kind;
    // A target asked for is the user's word; one a file names is the file's.
    const auto unknown = [&](const QString &id) {
        const QString known = targetIds().join(QStringLiteral(", "));
        *error = id == options.target
                     ? ProjectTr::tr("unknown target %1 (%2)").arg(id, known)
                     : ProjectTr::tr("%1: unknown target %2 (%3)").arg(path, id, known);
        return std::nullopt;
    };
    if (kind == ProgramFileKind::Project) {
        ProjectError projectError;
        std::optional<Project> project = loadProject(path, &projectError);
        if (!project) {
            *error = projectError.message;
            return std::nullopt;
        }
        if (!options.target.isEmpty() && Target::byId(options.target) != project->target) {
            if (!Target::byId(options.target))
                return unknown(options.target);
            *error = ProjectTr::tr("%1 is a %2 project, not %3")
                         .arg(path, project->target->id, options.target);
            return std::nullopt;
        }
        file.target = project->target;
        file.project = std::move(*project);
        return file;
    }
    QByteArray bytes;
    QString ioError;
    if (const ReadStatus status = readAtMost(path, options.maxBytes, &bytes, &ioError);
        status != ReadStatus::Ok) {
        *error = readFailure(status, path, options.maxBytes, ioError);
        return std::nullopt;
    }
    file.text = QString::fromUtf8(bytes);
    QString id = options.target;
    if (id.isEmpty() && kind == ProgramFileKind::LadderText) {
        id = ladderTextTarget(file.text);
        if (id.isEmpty())
            id = options.fallbackTarget.isEmpty() ? Target::get(Target::families().front()).id
                                                  : options.fallbackTarget;
    } else if (id.isEmpty()) {
        id = declaredTarget(file.text);
        if (id.isEmpty() && !options.fallbackTarget.isEmpty())
            id = listingTarget(file.text, options.fallbackTarget);
        if (id.isEmpty())
            return file; // nothing names it: the caller asks
    }
    file.target = Target::byId(id);
    if (!file.target)
        return unknown(id);
    return file;
}

} // namespace rung::model
