# Precompiled headers: the standard library and Qt headers every file of a room reads are
# parsed once a target instead of once a file (on the two-core CI machine they were a third
# of the build's time). Off with -DRUNG_PCH=OFF, e.g. for a ccache build; a file must still
# include what it uses, which the PCH-free builds check.
option(RUNG_PCH "Precompile the standard and Qt headers each target reads" ON)

set(RUNG_PCH_CORE
    <algorithm> <array> <cstdint> <functional> <map> <memory> <optional> <set> <string>
    <utility> <variant> <vector>
    <QByteArray> <QCoreApplication> <QFile> <QFileInfo> <QHash> <QList> <QMap> <QObject>
    <QRegularExpression> <QString> <QStringList> <QTextStream>)
set(RUNG_PCH_WIDGETS ${RUNG_PCH_CORE}
    <QAction> <QApplication> <QComboBox> <QDialog> <QDockWidget> <QEvent> <QHBoxLayout>
    <QHeaderView> <QKeyEvent> <QLabel> <QLineEdit> <QMainWindow> <QMenu> <QMessageBox>
    <QPainter> <QPointer> <QPushButton> <QScrollBar> <QSettings> <QSpinBox> <QStatusBar>
    <QStyle> <QTimer> <QToolBar> <QTreeWidget> <QVBoxLayout> <QWidget>)

# rung_precompile(TARGET core|widgets [test] [qttest])
function(rung_precompile target kind)
    if(NOT RUNG_PCH)
        return()
    endif()
    if(kind STREQUAL "widgets")
        set(headers ${RUNG_PCH_WIDGETS})
    else()
        set(headers ${RUNG_PCH_CORE})
    endif()
    if("test" IN_LIST ARGN)
        list(APPEND headers <gtest/gtest.h> <QDir> <QTemporaryDir>)
    endif()
    if("qttest" IN_LIST ARGN)
        list(APPEND headers <QSignalSpy> <QTest>)
    endif()
    target_precompile_headers(${target} PRIVATE ${headers})
endfunction()
