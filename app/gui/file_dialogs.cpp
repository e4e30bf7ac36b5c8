#include "file_dialogs.h"

#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHeaderView>
#include <QLocale>
#include <QScreen>
#include <QSettings>
#include <QStandardPaths>
#include <QTreeView>

#include <algorithm>

namespace rung::app {

namespace {

const auto kFolderKey = QStringLiteral("files/lastFolder");

QString exec(QFileDialog &dialog) {
    // About 860 x 500 px at a 9 pt font: the name, size, type and date columns whole. A
    // desktop's own dialog ignores the size.
    const QScreen *screen = dialog.parentWidget() ? dialog.parentWidget()->screen() : nullptr;
    const QRect room = screen ? screen->availableGeometry() : QRect(0, 0, 1024, 600);
    const int unit = dialog.fontMetrics().averageCharWidth();
    dialog.resize(std::min(room.width() * 9 / 10, unit * 130),
                  std::min(room.height() * 8 / 10, dialog.fontMetrics().height() * 30));
    // Qt sizes the detail columns for English samples ("128.88 GB", "10/29/81 02:02PM"):
    // every column gets room for its title and the sort arrow, the date column for a date as
    // the file system model writes it.
    if (auto *details = dialog.findChild<QTreeView *>(QStringLiteral("treeView"))) {
        QHeaderView *header = details->header();
        const QFontMetrics fm = header->fontMetrics();
        const QString longDate = QLocale::system().toString(
            QDateTime(QDate(2026, 12, 28), QTime(23, 58, 58)), QLocale::ShortFormat);
        for (int i = 0; i < header->count(); ++i) {
            const QString title = header->model()->headerData(i, Qt::Horizontal).toString();
            int needs = fm.horizontalAdvance(title) + 2 * fm.height();
            if (i == 2) // the type: a file type's name, not only "Folder"
                needs = std::max(needs, 18 * fm.averageCharWidth());
            if (i == header->count() - 1)
                needs = std::max(needs, fm.horizontalAdvance(longDate) + fm.height());
            if (header->sectionSize(i) < needs)
                header->resizeSection(i, needs);
        }
    }
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty())
        return {};
    const QString path = dialog.selectedFiles().front();
    rememberFileDialogFolder(path);
    return path;
}

} // namespace

QString fileDialogFolder(const QString &projectPath) {
    if (!projectPath.isEmpty()) {
        const QFileInfo info(projectPath);
        if (info.absoluteDir().exists())
            return info.absolutePath();
    }
    const QString last = QSettings().value(kFolderKey).toString();
    if (!last.isEmpty() && QFileInfo(last).isDir())
        return last;
    const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    return QFileInfo(documents).isDir() ? documents : QDir::homePath();
}

void rememberFileDialogFolder(const QString &chosenPath) {
    if (!chosenPath.isEmpty())
        QSettings().setValue(kFolderKey, QFileInfo(chosenPath).absolutePath());
}

QString askOpenFile(QWidget *parent, const QString &title, const QString &projectPath,
                    const QString &filter) {
    QFileDialog dialog(parent, title, fileDialogFolder(projectPath), filter);
    dialog.setAcceptMode(QFileDialog::AcceptOpen);
    dialog.setFileMode(QFileDialog::ExistingFile);
    return exec(dialog);
}

QString askSaveFile(QWidget *parent, const QString &title, const QString &start,
                    const QString &filter) {
    QFileDialog dialog(parent, title, start, filter);
    dialog.setAcceptMode(QFileDialog::AcceptSave);
    dialog.setFileMode(QFileDialog::AnyFile);
    return exec(dialog);
}

} // namespace rung::app
