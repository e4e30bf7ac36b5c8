#pragma once

// The GUI's command line: rungstudio [FILE] [--target T] [--screenshot PNG].

#include <QCommandLineParser>
#include <QStringList>

namespace rung::app {

struct GuiArguments {
    QString file;       // a project (.rung) or an instruction list; empty: none
    QString target;     // for an instruction list: vpc, vigor, cpm1, pl110; empty: the default
    QString screenshot; // save a picture of the window there and quit
    QString error;      // why the arguments cannot be used; empty: they can
    bool ok() const { return error.isEmpty(); }
};

// The options and the positional argument, for --help and for parsing.
void describeGuiArguments(QCommandLineParser &parser);
// Reads what the parser found (after parse() or process()) and checks the target.
GuiArguments readGuiArguments(const QCommandLineParser &parser);
// Parses a whole command line (arguments[0] is the program), without exiting on errors.
GuiArguments parseGuiArguments(const QStringList &arguments);

} // namespace rung::app
