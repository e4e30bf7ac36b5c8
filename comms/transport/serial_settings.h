#pragma once

// Line settings of a serial port: the model's (model/comm/serial_line.h), which a PLC's port in
// a simulated network and a program that sets its port read too.

#include "model/comm/serial_line.h"

namespace rung::comms {

using model::frameFormatText;
using model::parseFrameFormat;
using model::SerialSettings;

} // namespace rung::comms
