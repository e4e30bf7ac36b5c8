#include "model/project/file_read.h"
#include "model/tr.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>

namespace rung::model {

QString readFailure(ReadStatus status, const QString &path, qint64 limit, const QString &ioError) {
    switch (status) {
    case ReadStatus::CannotOpen:
        return ProjectTr::tr("%1: cannot open the file (%2)").arg(path, ioError);
    case ReadStatus::TooLarge:
        // A regular file says how large it is; a device or a pipe only that it goes on.
        if (const qint64 size = QFileInfo(path).size(); size > limit)
            return ProjectTr::tr("%1: the file is %2 MB; the most Rung Studio reads is %3 MB")
                .arg(path)
                .arg(size / (1024 * 1024))
                .arg(limit / (1024 * 1024));
        return ProjectTr::tr("%1: the file is larger than %2 MB, the most Rung Studio reads")
            .arg(path)
            .arg(limit / (1024 * 1024));
    case ReadStatus::Ok:
        break;
    }
    return QString();
}

ReadStatus readAtMost(const QString &path, qint64 limit, QByteArray *bytes, QString *ioError) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        if (ioError)
            *ioError = file.errorString();
        return ReadStatus::CannotOpen;
    }
    if (file.size() > limit) // a regular file says so before anything is read
        return ReadStatus::TooLarge;
    *bytes = file.read(limit + 1);
    if (bytes->size() > limit) {
        bytes->clear();
        return ReadStatus::TooLarge;
    }
    return ReadStatus::Ok;
}

} // namespace rung::model
