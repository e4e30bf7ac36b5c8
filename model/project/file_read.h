#pragma once

// Reading a whole file the user named, with a limit: a project, a listing, a ladder text.

#include <QByteArray>
#include <QString>

namespace rung::model {

enum class ReadStatus { Ok, CannotOpen, TooLarge };

// Reads the file into `bytes` when it holds at most `limit` bytes. A device or a pipe has no
// size to ask first (/dev/zero never ends), so at most one byte past the limit is read to
// tell. `ioError` gets the system's reason when the file cannot be opened.
ReadStatus readAtMost(const QString &path, qint64 limit, QByteArray *bytes, QString *ioError);
// What the user reads when readAtMost did not read (translated): the path and the system's
// reason, or the limit in MB. Empty for Ok.
QString readFailure(ReadStatus status, const QString &path, qint64 limit, const QString &ioError);

} // namespace rung::model
