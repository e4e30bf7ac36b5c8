#include "recovery.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLockFile>
#include <QSaveFile>
#include <QStandardPaths>

namespace rung::app {

namespace {

QString &directoryOverride() {
    static QString directory;
    return directory;
}

QString recoveryDirectory() {
    const QString dir = directoryOverride().isEmpty()
                            ? QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)
                            : directoryOverride();
    QDir().mkpath(dir);
    return dir;
}

// Beside each recovery file: the lock its instance holds while it runs, and the path of the
// file the recovered program came from (Save goes back there).
QString lockPath(const QString &base) {
    return base + QStringLiteral(".lock");
}
QString originPath(const QString &base) {
    return base + QStringLiteral(".path");
}

} // namespace

void RecoveryFile::setDirectory(const QString &directory) {
    directoryOverride() = directory;
}

RecoveryFile::RecoveryFile() {
    // Process ids repeat (containers start every program with a low one): a name whose lock is
    // taken, or whose recovery file waits to be offered, belongs to another instance. A
    // directory where no lock can be made ends the search after a few tries.
    static int windows = 0;
    for (int tries = 0; tries < 64; ++tries) {
        m_base = QStringLiteral("%1/recovery-%2-%3")
                     .arg(recoveryDirectory())
                     .arg(QCoreApplication::applicationPid())
                     .arg(++windows);
        m_lock = std::make_unique<QLockFile>(lockPath(m_base));
        m_lock->setStaleLockTime(0); // stale only when its process is gone
        if (!QFile::exists(m_base + QStringLiteral(".rung")) && m_lock->tryLock(0))
            return;
    }
}

RecoveryFile::~RecoveryFile() = default;

QString RecoveryFile::path() const {
    return m_base + QStringLiteral(".rung");
}

void RecoveryFile::remove() {
    QFile::remove(path());
    QFile::remove(originPath(m_base));
}

void RecoveryFile::write(const model::Project &project, const QString &origin) {
    model::ProjectError error;
    model::saveProject(project, path(), &error);
    QSaveFile file(originPath(m_base));
    if (file.open(QIODevice::WriteOnly)) {
        file.write(origin.toUtf8());
        file.commit();
    }
}

std::optional<RecoveryFile::Recovered>
RecoveryFile::takeOrphan(const std::function<bool(const QString &origin)> &accept) {
    const QFileInfoList files =
        QDir(recoveryDirectory())
            .entryInfoList({QStringLiteral("recovery*.rung")}, QDir::Files, QDir::Time);
    for (const QFileInfo &file : files) {
        const QString base = file.absoluteFilePath().chopped(5); // without ".rung"
        if (base == m_base)
            continue;
        // A lock that can be taken belongs to no running instance: its work is orphaned.
        QLockFile owner(lockPath(base));
        owner.setStaleLockTime(0);
        if (!owner.tryLock(0))
            continue;
        QString origin;
        QFile originFile(originPath(base));
        if (originFile.open(QIODevice::ReadOnly))
            origin = QString::fromUtf8(originFile.readAll()).trimmed();
        originFile.close();
        const bool wanted = accept(origin);
        model::ProjectError error;
        auto project = wanted ? model::loadProject(file.absoluteFilePath(), &error)
                              : std::optional<model::Project>();
        QFile::remove(file.absoluteFilePath());
        QFile::remove(originPath(base));
        if (project)
            return Recovered{std::move(*project), origin};
    }
    return std::nullopt;
}

} // namespace rung::app
