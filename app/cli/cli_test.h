#pragma once

#include <QStringList>
#include <QTextStream>

namespace rung::app {

// `rungstudio-cli test FILE|DIR... [--junit OUT.xml]`: runs scenario tests (.rungtest,
// docs/scenario-tests.md; a directory: every .rungtest under it). One line per failing
// expectation (FILE:LINE: when, what was expected, what was seen), then a summary. Exit 0 every
// scenario passed, 1 one failed or did not run, 2 usage or I/O error.
int runTestCommand(const QStringList &args, QTextStream &out, QTextStream &err);
QString testUsage();

} // namespace rung::app
