#pragma once

// A condition on one device that a monitor watches scan by scan: "Y0 rises", "Y0 falls",
// "D10 > 100". It fires in the scan where it becomes true (false after the scan before, true
// after this one), evaluated by the history recorder on the values it records, so it sees
// every scan however fast the engine runs and whatever the screen shows. The timing chart
// arms it to stop the simulation or to mark the moment; a breakpoint can read the same text.

#include "model/target/target.h"

#include <QString>

#include <optional>
#include <variant>

namespace rung::model {

struct Trigger {
    enum class Kind : std::uint8_t { Rises, Falls, Compare };
    enum class Action : std::uint8_t {
        Stop, // pause the source at that scan (a simulation), and mark it
        Mark, // only note the moment
    };

    Address device;
    Kind kind = Kind::Rises;
    CompareOp op = CompareOp::None; // Compare: device op value
    qint64 value = 0;
    Action action = Action::Stop;

    // Whether the condition holds for this value of the device (a bit: 0 or 1).
    bool holds(qint64 v) const;
    // True when it becomes true between these two values: a rising edge of the condition.
    bool fires(qint64 before, qint64 after) const { return !holds(before) && holds(after); }
    friend bool operator==(const Trigger &, const Trigger &) = default;
};

// Reads "DEVICE rises", "DEVICE falls" (a bit) or "DEVICE OP VALUE" with OP one of
// = <> < <= > >= (a word, a timer's or counter's current value; VALUE a whole number, 0x
// for hexadecimal). The words "rises" / "falls" are English as typed in every language;
// "↑" / "↓" mean the same. The error is translated and says what is wrong.
std::variant<Trigger, QString> parseTrigger(const Target &target, const QString &text,
                                            const ModelVariant *model = nullptr);
// The condition written the way parseTrigger reads it.
QString formatTrigger(const Target &target, const Trigger &trigger);

} // namespace rung::model
