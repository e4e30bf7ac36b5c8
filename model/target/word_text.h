#pragma once

// How a word's value is shown and typed where the user watches the PLC's memory. A target
// whose constants are BCD digits (CPM1 `#0150`, Omron CPM1 guide; its timers, counters and
// most channels hold BCD, W353) shows a word as its four hexadecimal digits, `#0012`, as its
// listing writes constants and its programming tools monitor channels; the others show the
// number.

#include "model/target/target.h"

#include <optional>

namespace rung::model {

QString formatWord(const Target &target, qint64 value);

// A typed word: a whole number, `0x` before a hexadecimal one, and on a BCD target `#0012`
// (the word 0012h); nullopt when it is none of these.
std::optional<qint64> parseWordValue(const Target &target, const QString &typed);

} // namespace rung::model
