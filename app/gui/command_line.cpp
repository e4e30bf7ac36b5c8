#include "command_line.h"

#include "model/target/target.h"
#include "model/target/target_lists.h"

#include <QCoreApplication>

namespace rung::app {

namespace {

// The texts are marked with QT_TRANSLATE_NOOP for lupdate, in the context the GUI's other
// command-line texts use.
QString translated(const char *text) {
    return QCoreApplication::translate("rung::app::Gui", text);
}

} // namespace

void describeGuiArguments(QCommandLineParser &parser) {
    parser.setApplicationDescription(translated(
        QT_TRANSLATE_NOOP("rung::app::Gui", "Ladder and instruction-list IDE for small PLCs")));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(
        QStringLiteral("file"),
        translated(QT_TRANSLATE_NOOP("rung::app::Gui",
                                     "A project (.rung) or an instruction list to open")));
    parser.addOption(QCommandLineOption(
        QStringLiteral("target"),
        translated(QT_TRANSLATE_NOOP("rung::app::Gui", "Target of an instruction list: %1"))
            .arg(model::targetIds().join(QStringLiteral(", "))),
        QStringLiteral("T")));
    parser.addOption(QCommandLineOption(
        QStringLiteral("screenshot"),
        translated(QT_TRANSLATE_NOOP("rung::app::Gui", "Save a picture of the window and quit")),
        QStringLiteral("PNG")));
}

GuiArguments readGuiArguments(const QCommandLineParser &parser) {
    GuiArguments a;
    const QStringList files = parser.positionalArguments();
    a.file = files.value(0);
    a.target = parser.value(QStringLiteral("target")).trimmed().toLower();
    a.screenshot = parser.value(QStringLiteral("screenshot"));
    if (files.size() > 1)
        a.error = translated(QT_TRANSLATE_NOOP("rung::app::Gui", "Open one file at a time"));
    else if (!a.target.isEmpty() && !model::Target::byId(a.target))
        a.error = translated(QT_TRANSLATE_NOOP("rung::app::Gui", "Unknown target %1: use %2"))
                      .arg(a.target, model::targetIds().join(QStringLiteral(", ")));
    return a;
}

GuiArguments parseGuiArguments(const QStringList &arguments) {
    QCommandLineParser parser;
    describeGuiArguments(parser);
    if (!parser.parse(arguments)) {
        GuiArguments a;
        a.error = parser.errorText();
        return a;
    }
    return readGuiArguments(parser);
}

} // namespace rung::app
