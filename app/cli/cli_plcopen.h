#pragma once

// PLCopen TC6 XML for `convert` (docs/plcopen.md): --from plcopen reads a file other tools
// wrote into an Input for the target given; --to plcopen writes the program as XML.

#include "cli_common.h"

#include <QTextStream>

namespace rung::app {

// 0 with *input set; 1 when the file holds what the target cannot take (each item printed on
// err, with a mapping file of the devices proposed; nothing is to be written unless `force`,
// which imports the rest and still returns 1 in *status); 2 for a usage or I/O error.
int loadPlcopenInput(const CommonOptions &options, const QString &mapFile, bool force, Input *input,
                     int *status, QTextStream &err);

// The program as PLCopen XML; what other tools will not know is said on err as notes.
QByteArray plcopenOutput(const Input &input, QTextStream &err);

} // namespace rung::app
