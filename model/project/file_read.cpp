#include "model/project/file_read.h"

#include <QFile>

namespace rung::model {

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
