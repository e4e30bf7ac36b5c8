#pragma once

// The window's file dialogs. They open in the project's folder (a new project: the folder a
// file was last opened from or saved to, remembered across starts), not in whatever folder the
// program happened to be started from; and where Qt draws the dialog itself (no desktop file
// dialog), it opens wide enough for its Size and Date columns in every language: at its own
// size the Hungarian and Italian column titles and dates were cut ("Dimension", "26 Nov...").

#include <QString>

class QWidget;

namespace rung::app {

// The folder a file dialog starts in: the project's, else the last one used, else the user's
// documents folder.
QString fileDialogFolder(const QString &projectPath);
// Remembers the folder of a file the user chose, for the next dialog of a new project.
void rememberFileDialogFolder(const QString &chosenPath);

// An existing file to open; empty when cancelled.
QString askOpenFile(QWidget *parent, const QString &title, const QString &projectPath,
                    const QString &filter);
// A file to write, starting at `start` (a folder or a file name to propose); empty when
// cancelled. The caller adds the format's extension and asks before replacing.
QString askSaveFile(QWidget *parent, const QString &title, const QString &start,
                    const QString &filter);

} // namespace rung::app
