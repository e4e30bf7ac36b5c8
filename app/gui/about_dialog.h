#pragma once

// Help > About: the version, what the program is for, the user guide shipped with it, and the
// parts it is built from with their versions and licences (Qt, QScintilla, libserialport).

#include <QDialog>
#include <QIcon>

namespace rung::app {

// The program's icon (resources/icons), drawn apart for 16, 22 and 24 px so the rung stays
// legible at the taskbar's and the title bar's sizes.
QIcon applicationIcon();

class AboutDialog : public QDialog {
    Q_OBJECT

public:
    explicit AboutDialog(QWidget *parent = nullptr);

    // The user guide's link as the dialog shows it: a file URL, invalid when no guide is
    // installed beside the program.
    static QUrl userGuideUrl();
};

} // namespace rung::app
