#pragma once

// What texts name from the target tables: the families a text lists and the device a message
// shows as an example. A text takes them from here, never writes one of its own, so adding a
// fifth PLC needs no new text.

#include "model/target/target.h"

#include <QString>
#include <QStringList>

namespace rung::model {

// The families' ids ("vpc", "vigor", ...) and display names, in Target::families() order.
QStringList targetIds();
QStringList targetDisplayNames();

// The target's first input terminal (Vigor X0, VPC i00, CPM1 000.00, PL110 I1), or its first
// output terminal (Y0, o00, 010.00, Q1), as the target writes it.
QString exampleDevice(const Target &target, bool output = false);
// A data word `offset` elements after the first of the target's data memory (Vigor D10,
// CPM1 DM 0010, PL110 V10 for offset 10), for hints like "D10 > 100" or "D0..D3".
QString exampleWord(const Target &target, int offset = 0);
// "D0..D3": a range of the first `count` data words.
QString exampleWordRange(const Target &target, int count);

} // namespace rung::model
