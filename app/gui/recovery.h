#pragma once

// The recovery file of one window: the unsaved program written aside every minute, so a crash
// loses at most a minute of work. One file per window of each running instance (a lock beside
// it says the instance still runs), so instances never overwrite each other's; the files of an
// instance that is gone are orphans, offered on the next start.

#include "model/project/project.h"

#include <QCoreApplication>
#include <QString>
#include <QStringList>

#include <functional>
#include <memory>
#include <optional>

class QLockFile;

namespace rung::app {

class RecoveryFile {
    Q_DECLARE_TR_FUNCTIONS(rung::app::RecoveryFile)

public:
    RecoveryFile(); // claims a name no other instance or window holds
    ~RecoveryFile();
    RecoveryFile(const RecoveryFile &) = delete;
    RecoveryFile &operator=(const RecoveryFile &) = delete;

    QString path() const;
    // The program and the file it came from (empty: never saved), for Save to go back there.
    // False with the reason (translated) when either file cannot be written.
    bool write(const model::Project &project, const QString &origin, QString *error);
    void remove();

    struct Recovered {
        model::Project project;
        QString origin;
    };
    // Walks the orphaned recovery files, newest first: `accept` is asked for each that loads
    // (with the file its program came from); a file offered goes, whatever the answer, and the
    // first one accepted is returned. A file that does not load is never offered nor deleted:
    // it stays where it is, and *unreadable gets why, with its path.
    std::optional<Recovered> takeOrphan(const std::function<bool(const QString &origin)> &accept,
                                        QStringList *unreadable = nullptr);

    static void setDirectory(const QString &directory); // tests: a folder of their own
    static QString directory();                         // the folder in use

private:
    QString m_base;                    // recovery file path without its suffix
    std::unique_ptr<QLockFile> m_lock; // held while this window lives
};

} // namespace rung::app
