#include "model/image/power_flow.h"

#include "model/tr.h"

#include "model/image/bcd.h"
#include "model/listing/il.h"

#include <QCoreApplication>

namespace rung::model {

namespace {

bool isDevice(const Operand &o) {
    return o.kind == Operand::Kind::Device && o.address.valid();
}

// A bit the snapshot can say ON or OFF: a bit device, a channel's bit, a timer's or
// counter's done bit.
bool hasBit(const Snapshot &s, const Address &a) {
    return s.layout && s.layout->bit(a).valid();
}

AreaKind kindOf(const Snapshot &s, const Address &a) {
    return s.layout->target().area(a.area).kind;
}

// Time base in seconds as the overlay writes it: "0.1", "0.01", "1".
QString seconds(double baseMs) {
    return QString::number(baseMs / 1000.0, 'g', 6);
}

bool isCoil(Op op) {
    return op == Op::Out || op == Op::Set || op == Op::Reset || op == Op::PulseRise ||
           op == Op::PulseFall || op == Op::Keep;
}

} // namespace

ProgramFlow::ProgramFlow(const LadderProgram &ladder, const ToListingResult &listing,
                         const Snapshot &snapshot)
    : m_ladder(ladder)
    , m_listing(listing)
    , m_snapshot(snapshot) {
    const auto &instructions = listing.list.instructions;
    const std::size_t n = instructions.size();
    const std::vector<bool> &flow = snapshot.powerFlow;
    m_hasFlow = n > 0 && flow.size() == n && listing.origin.size() == n && snapshot.layout;
    if (!snapshot.layout || listing.origin.size() != n)
        return;
    m_conducts.assign(n, kUnknown);
    m_gate.assign(n, 1);
    // The engine's gate (docs/simulator.md): every LD is ANDed with interlock && step. Without
    // power flow (an online PLC) the step relays still tell the steps; an interlock is then
    // taken as ON.
    bool interlock = true;
    bool step = true;
    const auto known = [](bool v) { return static_cast<std::int8_t>(v ? 1 : 0); };
    for (std::size_t i = 0; i < n; ++i) {
        const Instruction &ins = instructions[i];
        const bool gate = interlock && step;
        m_gate[i] = gate ? 1 : 0;
        const bool result = m_hasFlow && flow[i];
        const bool before = m_hasFlow && i > 0 && flow[i - 1];
        switch (ins.op()) {
        case Op::Load: // result = gate AND contact
            if (m_hasFlow && gate)
                m_conducts[i] = known(result);
            break;
        case Op::And: // result = before AND contact
            if (m_hasFlow && before)
                m_conducts[i] = known(result);
            break;
        case Op::Or: // result = before OR contact
            if (m_hasFlow && !before)
                m_conducts[i] = known(result);
            break;
        case Op::Invert: // INV / NOT, PL110 P / N: what the element passes on
            if (m_hasFlow)
                m_conducts[i] = known(result);
            break;
        case Op::Interlock:
            interlock = m_hasFlow ? result : true;
            break;
        case Op::InterlockClear:
            interlock = true;
            break;
        case Op::StepLadder:
            // The result is interlock AND step: it tells the step only while the interlock is
            // ON; otherwise the step relay's bit does.
            if (m_hasFlow && interlock)
                step = result;
            else
                step = !ins.operands.empty() && isDevice(ins.operands[0]) &&
                       snapshot.bit(ins.operands[0].address);
            break;
        case Op::Return:
            step = true;
            break;
        default:
            break;
        }
    }
}

std::int8_t ProgramFlow::fromDevices(const Contact &c) const {
    if (c.invert || c.operands.empty() || !m_snapshot.layout)
        return kUnknown;
    if (c.compare != CompareOp::None) {
        if (c.operands.size() < 2)
            return kUnknown;
        qint64 v[2] = {0, 0};
        for (int k = 0; k < 2; ++k) {
            const Operand &o = c.operands[static_cast<std::size_t>(k)];
            if (isDevice(o))
                v[k] = m_snapshot.value(o.address);
            else if (o.kind == Operand::Kind::Constant)
                v[k] = o.constant.value;
            else
                return kUnknown;
        }
        const bool holds = compareHolds(c.compare, v[0], v[1]);
        return (c.mode == ContactMode::Negated ? !holds : holds) ? 1 : 0;
    }
    const Operand &o = c.operands.front();
    if (!isDevice(o) || !hasBit(m_snapshot, o.address))
        return kUnknown;
    const bool on = m_snapshot.bit(o.address);
    switch (c.mode) {
    case ContactMode::Normal:
        return on ? 1 : 0;
    case ContactMode::Negated:
        return on ? 0 : 1;
    case ContactMode::Rising:
    case ContactMode::Falling:
        break; // an edge lasts one scan: only the power flow knows it
    }
    return kUnknown;
}

RungOverlay ProgramFlow::rung(int index, bool stale) const {
    RungOverlay o;
    if (index < 0 || index >= static_cast<int>(m_ladder.rungs.size()) || !m_snapshot.layout)
        return o;
    const Rung &r = m_ladder.rungs[static_cast<std::size_t>(index)];
    const int rows = r.rows;
    const int columns = r.columns;
    const int nodes = columns + 1;
    const auto cell = [columns](int row, int column) {
        return static_cast<std::size_t>(row * columns + column);
    };
    o.rows = rows;
    o.columns = columns;
    o.stale = stale;
    o.node.assign(static_cast<std::size_t>(rows * nodes), 0);
    o.closed.assign(static_cast<std::size_t>(rows * columns), 0);
    o.passing.assign(static_cast<std::size_t>(rows * columns), 0);
    o.forced.assign(static_cast<std::size_t>(rows * columns), 0);
    o.value.assign(static_cast<std::size_t>(rows * columns), QString());
    o.outputs.resize(static_cast<std::size_t>(rows));

    // What the scan found, by cell: the first instruction written from a cell that tells.
    std::vector<std::int8_t> scanned(static_cast<std::size_t>(rows * columns), kUnknown);
    bool rail = true;
    const auto &first = m_listing.rungFirst;
    if (!m_gate.empty() && static_cast<std::size_t>(index) + 1 < first.size()) {
        const int begin = first[static_cast<std::size_t>(index)];
        const int end = first[static_cast<std::size_t>(index) + 1];
        if (begin < end && begin >= 0 && static_cast<std::size_t>(begin) < m_gate.size())
            rail = m_gate[static_cast<std::size_t>(begin)] != 0;
        for (int i = std::max(0, begin); i < end && static_cast<std::size_t>(i) < m_conducts.size();
             ++i) {
            const CellOrigin &at = m_listing.origin[static_cast<std::size_t>(i)];
            if (at.rung != index || at.row < 0 || at.row >= rows || at.column < 0 ||
                at.column >= columns)
                continue;
            std::int8_t &s = scanned[cell(at.row, at.column)];
            if (s == kUnknown)
                s = m_conducts[static_cast<std::size_t>(i)];
        }
    }
    o.rail = rail;

    // Each cell's conduction: the drawing's (the device, or the scan where the device cannot
    // tell) and the one power follows (the scan's, else the device's).
    enum class Pass : std::uint8_t { None, Wire, Contact, Invert, Scanned };
    std::vector<Pass> pass(static_cast<std::size_t>(rows * columns), Pass::None);
    std::vector<std::uint8_t> follows(static_cast<std::size_t>(rows * columns), 0);
    for (int row = 0; row < rows; ++row)
        for (int column = 0; column < columns; ++column) {
            const Cell &c = r.cell(row, column);
            const std::size_t k = cell(row, column);
            if (c.kind == CellKind::Wire) {
                pass[k] = Pass::Wire;
                o.closed[k] = 1;
                continue;
            }
            if (c.kind != CellKind::Contact)
                continue;
            const Contact &contact = c.contact;
            if (contact.invert) {
                // NOT inverts what reaches it; P / N pass one scan's edge of it.
                const bool edge = contact.mode != ContactMode::Normal;
                pass[k] = edge ? Pass::Scanned : Pass::Invert;
                follows[k] = scanned[k] == 1 ? 1 : 0;
                continue;
            }
            pass[k] = Pass::Contact;
            const std::int8_t device = fromDevices(contact);
            const std::int8_t shown = device != kUnknown ? device : scanned[k];
            const std::int8_t power = scanned[k] != kUnknown ? scanned[k] : device;
            o.closed[k] = shown == 1 ? 1 : 0;
            follows[k] = power == 1 ? 1 : 0;
            QStringList values;
            for (const Operand &operand : contact.operands) {
                if (!isDevice(operand))
                    continue;
                if (m_snapshot.forced(operand.address))
                    o.forced[k] = 1;
                if (contact.compare != CompareOp::None)
                    values << wordText(m_snapshot, operand.address);
            }
            o.value[k] = values.join(QStringLiteral(", "));
        }

    // Left to right: a cell passes what reaches its left node; the vertical links join the
    // nodes of a column into one.
    for (int row = 0; row < rows; ++row)
        o.node[static_cast<std::size_t>(row * nodes)] = rail ? 1 : 0;
    for (int column = 0; column < columns; ++column) {
        for (int row = 0; row < rows; ++row) {
            const std::size_t k = cell(row, column);
            const bool left = o.node[static_cast<std::size_t>(row * nodes + column)] != 0;
            bool passes = false;
            switch (pass[k]) {
            case Pass::None:
                break;
            case Pass::Wire:
                passes = left;
                break;
            case Pass::Contact:
                passes = left && follows[k];
                break;
            case Pass::Invert:
                passes = !left;
                o.closed[k] = passes ? 1 : 0;
                break;
            case Pass::Scanned:
                passes = follows[k] != 0;
                o.closed[k] = passes ? 1 : 0;
                break;
            }
            o.passing[k] = passes ? 1 : 0;
            o.node[static_cast<std::size_t>(row * nodes + column + 1)] = passes ? 1 : 0;
        }
        for (int top = 0; top < rows;) {
            int bottom = top;
            while (bottom + 1 < rows && r.link(bottom, column + 1))
                ++bottom;
            bool any = false;
            for (int row = top; row <= bottom; ++row)
                any = any || o.node[static_cast<std::size_t>(row * nodes + column + 1)];
            for (int row = top; row <= bottom; ++row)
                o.node[static_cast<std::size_t>(row * nodes + column + 1)] = any ? 1 : 0;
            top = bottom + 1;
        }
    }

    for (int row = 0; row < rows; ++row) {
        const auto &ins = r.outputs[static_cast<std::size_t>(row)];
        if (!ins || !ins->spec)
            continue;
        RungOverlay::Output &out = o.outputs[static_cast<std::size_t>(row)];
        out.present = true;
        const Op op = ins->op();
        // END, STL, RET, ILC, JPE take no condition: no power flows to them.
        if (isUnconditional(op))
            o.node[static_cast<std::size_t>(row * nodes + columns)] = 0;
        out.powered = o.node[static_cast<std::size_t>(row * nodes + columns)] != 0;
        const Operand *device = !ins->operands.empty() && isDevice(ins->operands.front())
                                    ? &ins->operands.front()
                                    : nullptr;
        // A coil's device, a timer's or counter's done bit, the step relay of an STL.
        if (device &&
            (isCoil(op) || op == Op::Timer || op == Op::Counter || op == Op::UpDownCounter ||
             op == Op::StepLadder) &&
            hasBit(m_snapshot, device->address)) {
            out.hasBit = true;
            out.on = m_snapshot.bit(device->address);
        }
        for (const Operand &operand : ins->operands)
            if (isDevice(operand) && m_snapshot.forced(operand.address))
                out.forced = true;
        if (!isCoil(op) && op != Op::StepLadder)
            out.value = valuesText(m_ladder.target ? *m_ladder.target : m_snapshot.layout->target(),
                                   *ins, m_snapshot);
    }
    return o;
}

QString ProgramFlow::wordText(const Snapshot &snapshot, const Address &address) {
    if (!snapshot.layout)
        return {};
    if (address.bit >= 0 || kindOf(snapshot, address) == AreaKind::Bit)
        return bitText(snapshot.bit(address));
    return QString::number(snapshot.value(address));
}

namespace {

// A CPM1 TIM's or CNT's present and set values hold BCD digits (W353); a word that is not
// BCD is shown as it is rather than as a wrong number.
qint64 setValueNumber(const Target &target, qint64 word) {
    return target.constants.bcdSetValues ? fromBcd(word).value_or(word) : word;
}

QString numberOrUnknown(std::optional<qint64> value) {
    return value ? QString::number(*value) : QStringLiteral("?");
}

} // namespace

qint64 ProgramFlow::presentOf(const Target &target, const Address &element,
                              const Snapshot &snapshot) {
    return setValueNumber(target, snapshot.value(element));
}

std::optional<qint64> ProgramFlow::presetWordOf(const Target &target, const Instruction *box,
                                                const Address &element, const Snapshot &snapshot) {
    const Operand *preset =
        box && box->operands.size() >= 2 && box->operands.front().address == element
            ? &box->operands[1]
            : nullptr;
    if (preset && preset->modified()) // indexed: only the PLC knows which word it read
        preset = nullptr;
    // CPM1 #0150 is the number 150 already; its word holds the digits.
    if (preset && preset->kind == Operand::Kind::Constant)
        return target.constants.bcdSetValues ? toBcd(preset->constant.value)
                                             : preset->constant.value;
    if (snapshot.setValueKnown(element))
        return snapshot.setValue(element);
    if (preset && isDevice(*preset) && snapshot.valueKnown(preset->address))
        return snapshot.value(preset->address);
    return std::nullopt;
}

std::optional<qint64> ProgramFlow::presetOf(const Target &target, const Instruction *box,
                                            const Address &element, const Snapshot &snapshot) {
    const std::optional<qint64> word = presetWordOf(target, box, element, snapshot);
    return word ? std::optional<qint64>(setValueNumber(target, *word)) : std::nullopt;
}

const Instruction *ProgramFlow::boxOf(const std::vector<Instruction> &program,
                                      const Address &element) {
    for (const Instruction &ins : program) {
        const Op op = ins.op();
        if ((op == Op::Timer || op == Op::Counter || op == Op::UpDownCounter) &&
            !ins.operands.empty() && isDevice(ins.operands.front()) &&
            ins.operands.front().address == element)
            return &ins;
    }
    return nullptr;
}

QString ProgramFlow::timerText(const Target &target, const Instruction &timer,
                               const Snapshot &snapshot) {
    if (timer.operands.empty() || !isDevice(timer.operands.front()))
        return {};
    const Address &t = timer.operands.front().address;
    const qint64 current = presentOf(target, t, snapshot);
    const std::optional<qint64> set = presetOf(target, &timer, t, snapshot);
    const bool down = timerCountsDown(target, t);
    // A timer that counts down shows the time elapsed, which needs the set value.
    const std::optional<qint64> elapsed = !down ? std::optional<qint64>(current)
                                          : set ? std::optional<qint64>(*set - current)
                                                : std::nullopt;
    const double base = timerBaseMs(target, timer);
    if (base <= 0)
        return QStringLiteral("%1/%2").arg(numberOrUnknown(elapsed), numberOrUnknown(set));
    //: a timer's time elapsed / set value in its units, then the unit: "23/50 ×0.1 s"
    return PowerFlowTr::tr("%1/%2 ×%3 s")
        .arg(numberOrUnknown(elapsed), numberOrUnknown(set))
        .arg(seconds(base));
}

QString ProgramFlow::counterText(const Target &target, const Instruction &counter,
                                 const Snapshot &snapshot) {
    if (counter.operands.empty() || !isDevice(counter.operands.front()))
        return {};
    const Address &c = counter.operands.front().address;
    return QStringLiteral("%1/%2").arg(QString::number(presentOf(target, c, snapshot)),
                                       numberOrUnknown(presetOf(target, &counter, c, snapshot)));
}

QString ProgramFlow::valuesText(const Target &target, const Instruction &ins,
                                const Snapshot &snapshot) {
    if (!snapshot.layout)
        return {};
    const Op op = ins.op();
    if (op == Op::Timer)
        return timerText(target, ins, snapshot);
    if (op == Op::Counter || op == Op::UpDownCounter)
        return counterText(target, ins, snapshot);
    QStringList parts;
    for (const Operand &o : ins.operands) {
        if (!isDevice(o) || o.address.bit >= 0 || kindOf(snapshot, o.address) == AreaKind::Bit)
            continue;
        //: a device and its value under a box: "D0 = 12"
        parts << PowerFlowTr::tr("%1 = %2").arg(formatOperand(target, o),
                                                wordText(snapshot, o.address));
    }
    return parts.join(QStringLiteral("  "));
}

QString ProgramFlow::bitText(bool on) {
    return on ? PowerFlowTr::tr("ON") : PowerFlowTr::tr("OFF");
}

} // namespace rung::model
