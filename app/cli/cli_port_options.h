#pragma once

// The options `record` and `terminal` share: "--name VALUE" pairs and a serial line's
// --baud / --frame (comms::parseFrameFormat).

#include "comms/transport/serial_settings.h"

#include <QStringList>

#include <initializer_list>

namespace rung::app {

struct ValuedOption {
    const char *name;
    QString *value;
};

// Takes every argument as one of `options` followed by its value; false with the reason for
// a missing value or anything else.
bool takeValuedOptions(const QStringList &args, std::initializer_list<ValuedOption> options,
                       QString *error);
// --baud B and --frame 8N1 (either may be empty: the default stays) into `line`.
bool parseLineOptions(const QString &baud, const QString &frame, comms::SerialSettings *line,
                      QString *error);

} // namespace rung::app
