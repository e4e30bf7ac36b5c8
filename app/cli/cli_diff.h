#pragma once

#include <QStringList>
#include <QTextStream>

namespace rung::app {

// `rungstudio-cli diff A B [--target T] [--format text|json]`: two projects, listings or ladder
// texts of one target compared rung by rung (model/compare/compare.h). Exit 0 equal, 1
// different, 2 usage or I/O error, as diff. A side given as /dev/null (git's new or deleted
// file) is an empty program of the other side's target.
int runDiffCommand(const QStringList &args, QTextStream &out, QTextStream &err);
QString diffUsage();

// `rungstudio-cli show FILE`: the file as a text to read and diff (git's textconv for *.rung):
// the canonical listing, a blank line between rungs, then the symbols, set values and watch
// lists as comment lines. Never refuses: a file that is no project is shown as it is, after a
// line that says why. Exit 0, or 2 when the file cannot be read.
int runShowCommand(const QStringList &args, QTextStream &out, QTextStream &err);
QString showUsage();

} // namespace rung::app
