#include "recovery.h"

#include "model/project/file_read.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLockFile>
#include <QSaveFile>
#include <QStandardPaths>

namespace rung::app {

namespace {

// The companion holds one path: a few hundred bytes; no file system has paths this long.
constexpr qint64 kMaxOriginBytes = 64 * 1024;

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

QString RecoveryFile::directory() {
    return recoveryDirectory();
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

bool RecoveryFile::write(const model::Project &project, const QString &origin, QString *error) {
    model::ProjectError projectError;
    if (!model::saveProject(project, path(), &projectError)) {
        if (error)
            *error = tr("The recovery file could not be written: %1").arg(projectError.message);
        return false;
    }
    QSaveFile file(originPath(m_base));
    const QByteArray bytes = origin.toUtf8();
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit()) {
        if (error)
            *error = tr("The recovery file could not be written: %1: %2")
                         .arg(QDir::toNativeSeparators(originPath(m_base)), file.errorString());
        return false;
    }
    return true;
}

std::optional<RecoveryFile::Recovered>
RecoveryFile::takeOrphan(const std::function<bool(const QString &origin)> &accept,
                         QStringList *unreadable) {
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
        // Work that cannot be read now may be read by a later version, or by hand: it stays.
        model::ProjectError error;
        auto project = model::loadProject(file.absoluteFilePath(), &error);
        if (!project) {
            if (unreadable)
                *unreadable << tr("%1 could not be read and is kept: %2")
                                   .arg(QDir::toNativeSeparators(file.absoluteFilePath()),
                                        error.message);
            continue;
        }
        // The path of a file: a companion larger than any path is no path, and the program comes
        // back untitled (Save asks where).
        QString origin;
        QByteArray bytes;
        if (model::readAtMost(originPath(base), kMaxOriginBytes, &bytes, nullptr) ==
            model::ReadStatus::Ok)
            origin = QString::fromUtf8(bytes).trimmed();
        const bool wanted = accept(origin);
        QFile::remove(file.absoluteFilePath());
        QFile::remove(originPath(base));
        if (wanted)
            return Recovered{std::move(*project), origin};
    }
    return std::nullopt;
}

} // namespace rung::app
