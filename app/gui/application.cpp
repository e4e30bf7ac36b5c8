#include "application.h"

#include <QApplication>
#include <QMainWindow>

namespace rung::app {

int runGui(int argc, char **argv)
{
    QApplication app(argc, argv);
    QMainWindow window;
    window.setWindowTitle(QStringLiteral("Rung Studio"));
    window.show();
    return app.exec();
}

} // namespace rung::app
