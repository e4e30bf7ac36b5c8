// The main window's side of networks: a .rungnet opens in a NetworkWindow of its own, and a
// station's program asked for there opens here for editing.

#include "app/gui/file_controller.h"
#include "app/gui/main_window.h"
#include "app/gui/network_window.h"

namespace rung::app {

NetworkWindow *MainWindow::openNetwork(const QString &path, QString *error) {
    // A window of its own (not a child widget), closed with this one.
    auto *window = new NetworkWindow(this);
    window->setWindowFlag(Qt::Window);
    if (path.isEmpty() ? !window->newNetwork(error) : !window->open(path, error)) {
        delete window;
        return nullptr;
    }
    connect(window, &NetworkWindow::openProgramRequested, this, [this](const QString &program) {
        if (program.isEmpty() || !m_files->maybeSave())
            return;
        if (openFile(program)) {
            raise();
            activateWindow();
        }
    });
    window->show();
    return window;
}

} // namespace rung::app
