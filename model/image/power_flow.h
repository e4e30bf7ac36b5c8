#pragma once

// What the live overlay draws on a rung: which nodes carry power, which contacts conduct,
// which coils are ON, which devices are forced, and the values under timers, counters and
// words. Computed from a monitor's snapshot alone (no widget, no source), so the simulator,
// an online PLC and a past scan all draw the same way.
//
// Power flow. A rung is a grid whose cells pass power left to right; a node (the point
// between two cells, joined to the rows above and below by vertical links) carries power when
// a conducting path leads to it from the left rail. The wires between elements show that:
// left of a contact the node it hangs on, through it the power it passes on. Each contact's
// conduction is read as the scan read it where the snapshot's power flow says so (the logic
// result after each instruction, mapped to its cell by the origin map): LD gives it
// outright, AND when the result before it was ON, OR when it was OFF. Where that leaves it
// open (an AND behind an open contact, an OR beside a closed one, a source without power
// flow such as an online PLC) the device's value decides. So ANB and ORB blocks need no
// rule of their own: the nodes do the joining, as the wires do in the drawing. The rail
// itself is OFF in an interlock (IL..ILC) or a step (STL) that is off, replayed from the
// power flow of IL, ILC, STL and RET (without power flow: from the step relays).

#include "model/convert/convert.h"
#include "model/image/snapshot.h"
#include "model/ladder/ladder.h"

#include <QString>

#include <optional>

#include <cstdint>
#include <vector>

namespace rung::model {

struct RungOverlay {
    int rows = 0;
    int columns = 0;
    bool stale = false; // the source lost its PLC: these are the last values known
    bool rail = false;  // the left rail carries power
    // rows * (columns + 1): the node at (row, node column) carries power.
    std::vector<std::uint8_t> node;
    // rows * columns: the contact conducts (a wire always does).
    std::vector<std::uint8_t> closed;
    // rows * columns: a device of the contact is forced.
    std::vector<std::uint8_t> forced;
    // rows * columns: the values a compare contact compares ("1234"), empty elsewhere.
    std::vector<QString> value;

    struct Output {
        bool present = false;
        bool powered = false; // its condition is ON (the node at the output column)
        bool on = false;      // a coil's device, a timer's or counter's done bit, a step's relay
        bool hasBit = false;  // `on` means something (a coil, a timer, a counter, an STL)
        bool forced = false;
        QString value; // "23/50 ×0.1 s", "3/10", "D0 = 12"
        friend bool operator==(const Output &, const Output &) = default;
    };
    std::vector<Output> outputs; // per row

    // rows * columns: power passes through the cell (its left node carries power and it
    // conducts; an INV / NOT passes what its left node lacks, a P / N what the scan found).
    std::vector<std::uint8_t> passing;

    bool nodeOn(int row, int nodeColumn) const {
        return at(node, row * (columns + 1) + nodeColumn) != 0;
    }
    bool conducts(int row, int column) const { return at(closed, row * columns + column) != 0; }
    bool passes(int row, int column) const { return at(passing, row * columns + column) != 0; }
    bool isForced(int row, int column) const { return at(forced, row * columns + column) != 0; }
    QString valueAt(int row, int column) const {
        const auto i = static_cast<std::size_t>(row * columns + column);
        return row >= 0 && column >= 0 && column < columns && i < value.size() ? value[i]
                                                                               : QString();
    }
    const Output *output(int row) const {
        return row >= 0 && static_cast<std::size_t>(row) < outputs.size() &&
                       outputs[static_cast<std::size_t>(row)].present
                   ? &outputs[static_cast<std::size_t>(row)]
                   : nullptr;
    }

    friend bool operator==(const RungOverlay &, const RungOverlay &) = default;

private:
    static std::uint8_t at(const std::vector<std::uint8_t> &v, int i) {
        return i >= 0 && static_cast<std::size_t>(i) < v.size() ? v[static_cast<std::size_t>(i)]
                                                                : 0;
    }
};

// The program's state in one snapshot, once: which contacts the scan found conducting and
// which rungs an interlock or a step holds off. rung() then answers for any rung in time
// proportional to its size, so a view computes only the rungs it shows.
class ProgramFlow {
public:
    // `listing` is the running program's listing with its origin map; the snapshot must stay
    // alive as long as this object.
    ProgramFlow(const LadderProgram &ladder, const ToListingResult &listing,
                const Snapshot &snapshot);

    RungOverlay rung(int index, bool stale = false) const;
    // Whether the snapshot's power flow matches the program (one result per instruction).
    bool hasPowerFlow() const { return m_hasFlow; }

    // Texts the overlay and the instruction list show for devices (translated).
    static QString timerText(const Target &target, const Instruction &timer,
                             const Snapshot &snapshot);
    static QString counterText(const Target &target, const Instruction &counter,
                               const Snapshot &snapshot);
    // A timer's or counter's values as numbers (a CPM1 word's BCD digits decoded). A
    // constant preset (K350, #0150) is the program's, shown as the box has it whether or not
    // the source ran the box yet (a stopped simulation's memory holds 0 until the box runs)
    // or can read it (online, no protocol area holds a Vigor K constant). Else the memory's
    // set value where it is known, else the word device the box names once read. Unknown:
    // nullopt.
    static qint64 presentOf(const Target &target, const Address &element, const Snapshot &snapshot);
    static std::optional<qint64> presetOf(const Target &target, const Instruction *box,
                                          const Address &element, const Snapshot &snapshot);
    // The same as the memory word holds it (a CPM1's BCD digits), for a view that shows the
    // word in a format of its own (the watch table).
    static std::optional<qint64> presetWordOf(const Target &target, const Instruction *box,
                                              const Address &element, const Snapshot &snapshot);
    // The timer or counter box of the program that drives an element (its first operand);
    // null when none does.
    static const Instruction *boxOf(const std::vector<Instruction> &program,
                                    const Address &element);
    // The values of an instruction's word devices ("D0 = 12  D1 = 3"); for a timer or
    // counter its elapsed / preset.
    static QString valuesText(const Target &target, const Instruction &ins,
                              const Snapshot &snapshot);
    // A word's value as the monitor writes it (decimal, sign as the word holds it).
    static QString wordText(const Snapshot &snapshot, const Address &address);
    // A bit's state as the monitor writes it ("ON", "OFF", translated).
    static QString bitText(bool on);

private:
    enum : std::int8_t { kUnknown = -1 };
    // A contact's conduction from the devices' values (-1: cannot be told, an edge).
    std::int8_t fromDevices(const Contact &contact) const;

    const LadderProgram &m_ladder;
    const ToListingResult &m_listing;
    const Snapshot &m_snapshot;
    bool m_hasFlow = false;
    std::vector<std::int8_t> m_conducts; // per instruction, from the power flow
    std::vector<std::uint8_t> m_gate;    // per instruction: the interlock / step let it run
};

} // namespace rung::model
