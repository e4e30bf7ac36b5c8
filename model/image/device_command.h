#pragma once

// A change a user asks of a PLC's memory: write a bit or a word, write a timer/counter preset,
// force a bit, release it. One shape for every origin: the simulator's command inbox applies
// it at the start of a scan, an online driver turns it into a protocol write.

#include "model/target/target.h"

#include <QtGlobal>

namespace rung::model {

struct DeviceCommand {
    enum class Kind : std::uint8_t {
        WriteBit,      // address, value 0/1
        WriteWord,     // address, value (wrapped to the area's width)
        WriteSetValue, // timer/counter address, value
        Force,         // address, value 0/1: keep the bit at that value against the program
        Release,       // address: end a force
        ReleaseAll,    // every forced bit
    };

    Kind kind = Kind::WriteBit;
    Address address;
    qint64 value = 0;
};

} // namespace rung::model
