#include "model/checks/checks_list_detail.h"
#include "model/checks/operand_rules.h"
#include "model/checks/unmodelled.h"
#include "model/tr.h"

#include <QCoreApplication>

#include <algorithm>

// The operands (OP001..OP005) and what the simulator does not model (SIM100, SIM101), each
// finding at its operand's column when the source text is at hand (docs/diagnostics.md).

namespace rung::model::detail {

namespace {

// The instructions that drive a relay (a bit); RST and the zone reset also clear timers,
// counters and registers.
bool drivesABit(Op op) {
    return op == Op::Out || op == Op::Set || op == Op::Keep || op == Op::PulseRise ||
           op == Op::PulseFall;
}

} // namespace

// The system devices the PLC itself drives (always-on, clocks, first scan, scan times).
const SystemDevice *ListChecker::driveBySystem(const Address &a) {
    if (!m_systemParsed) {
        m_systemParsed = true;
        for (const SystemDevice &d : m_t.systemDevices) {
            if (!drivenByPlc(d))
                continue;
            const auto parsed = parseAddress(m_t, d.device, nullptr);
            if (const Address *at = std::get_if<Address>(&parsed))
                m_systemDriven.emplace(*at, &d);
        }
    }
    const auto it = m_systemDriven.find(a);
    return it == m_systemDriven.end() ? nullptr : it->second;
}

// Moves the finding to the column of `device` on the instruction's line, when the source
// text is at hand.
void ListChecker::atOperand(Finding &f, int i, const QString &device) {
    if (!m_source || at(i).line <= 0)
        return;
    if (m_sourceLines.isEmpty())
        m_sourceLines = m_source->split(QLatin1Char('\n'));
    const QString line = m_sourceLines.value(at(i).line - 1);
    const qsizetype found = line.indexOf(device, std::max(0, at(i).column), Qt::CaseInsensitive);
    if (found >= 0)
        f.diagnostic.location.column = static_cast<int>(found) + 1;
}

// Moves the finding to the column of operand k when it is a constant or a word (SBIT V3
// 16: the 16), found as a whole word after the mnemonic; the mnemonic's column otherwise.
void ListChecker::atWordOperand(Finding &f, int i, std::size_t k) {
    const Instruction &ins = at(i);
    if (!m_source || ins.line <= 0 || k >= ins.operands.size())
        return;
    if (m_sourceLines.isEmpty())
        m_sourceLines = m_source->split(QLatin1Char('\n'));
    const auto written = [this](const Operand &o) {
        return o.kind == Operand::Kind::Constant ? formatConstant(m_t, o.constant)
               : o.kind == Operand::Kind::Text   ? o.text.trimmed()
                                                 : formatOperand(m_t, o);
    };
    if (ins.operands[k].kind == Operand::Kind::String) {
        // A quoted text: the first quote after the mnemonic (MOVTXT takes one text).
        const QString line = m_sourceLines.value(ins.line - 1);
        if (const qsizetype quote = line.indexOf(QLatin1Char('"'), std::max(0, ins.column - 1));
            quote >= 0)
            f.diagnostic.location.column = static_cast<int>(quote) + 1;
        return;
    }
    const QString wanted = written(ins.operands[k]);
    int skip = 0; // earlier operands written the same way
    for (std::size_t j = 0; j < k; ++j)
        if (written(ins.operands[j]).compare(wanted, Qt::CaseInsensitive) == 0)
            ++skip;
    QString line = m_sourceLines.value(ins.line - 1);
    if (const qsizetype comment = line.indexOf(QLatin1Char(';')); comment >= 0)
        line.truncate(comment);
    qsizetype pos = std::max(0, ins.column - 1);
    bool mnemonic = true;
    while (pos < line.size()) {
        while (pos < line.size() && line[pos].isSpace())
            ++pos;
        qsizetype end = pos;
        while (end < line.size() && !line[end].isSpace())
            ++end;
        if (end == pos)
            break;
        if (!mnemonic &&
            QStringView(line).mid(pos, end - pos).compare(wanted, Qt::CaseInsensitive) == 0 &&
            skip-- == 0) {
            f.diagnostic.location.column = static_cast<int>(pos) + 1;
            return;
        }
        mnemonic = false;
        pos = end;
    }
}

void ListChecker::operands() {
    std::map<int, std::pair<int, int>> bankUse; // number -> (timer use, counter use)
    for (int i = 0; i < size(); ++i) {
        const Instruction &ins = at(i);
        if (!ins.spec)
            continue;
        // The table's narrower rules, read by the simulator too: what it refuses, check does.
        // What the simulator will not model is said before a simulation is tried.
        if (ins.spec->function == ApplyFunction::NotSimulated)
            add("SIM100", Severity::Warning, i, notSimulatedMessage(*ins.spec));
        for (const UnmodelledUse &use : unmodelledUses(m_t, ins)) {
            Finding &f = add("SIM101", Severity::Warning, i, use.message);
            atOperand(f, i,
                      formatOperand(m_t, ins.operands[static_cast<std::size_t>(use.operand)]));
        }
        for (const OperandBreach &b : operandBreaches(m_t, ins)) {
            const Operand &o = ins.operands[static_cast<std::size_t>(b.operand)];
            Finding &f = add("OP005", Severity::Error, i, b.message);
            if (o.kind == Operand::Kind::Device)
                atOperand(f, i, formatOperand(m_t, o));
            else
                atWordOperand(f, i, static_cast<std::size_t>(b.operand));
        }
        for (std::size_t k = 0; k < ins.operands.size(); ++k)
            if (const QString why = undisplayedCharacters(m_t, ins, k); !why.isEmpty())
                atWordOperand(add("OP007", Severity::Warning, i, why), i, k);
        for (std::size_t k = 0; k < ins.operands.size(); ++k) {
            const Operand &o = ins.operands[k];
            const OperandKind kind =
                k < ins.spec->operands.size() ? ins.spec->operands[k].kind : OperandKind::BitSource;
            if (o.kind == Operand::Kind::Constant && kind == OperandKind::SetValue) {
                const qint64 v = o.constant.value;
                const bool bcd = o.constant.style == Constant::Style::Bcd;
                if ((bcd && (v < 0 || v > 9999)) || (!bcd && (v < 0 || v > 32767)))
                    add("OP004", Severity::Error, i,
                        ChecksTr::tr("Set value %1 is out of range").arg(v));
            }
            if (o.kind != Operand::Kind::Device)
                continue;
            const Area &area = m_t.area(o.address.area);
            const auto range = m_t.range(o.address.area, m_model);
            if (!range || o.address.index < range->first || o.address.index > range->second) {
                // The address rules word the message ("o20 is beyond VPC2416's outputs").
                auto check = parseAddress(m_t, formatAddress(m_t, o.address), m_model);
                if (auto *e = std::get_if<AddressError>(&check))
                    add("OP001", Severity::Error, i, e->message);
            }
            const bool destination = kind == OperandKind::BitDest || kind == OperandKind::WordDest;
            const QString device = formatOperand(m_t, o);
            // A digit-designated destination writes each of its bits (K4M9000: M9000..).
            const SystemDevice *driven = driveBySystem(o.address);
            for (int b = 1; destination && !driven && b < o.digits * 4; ++b)
                driven = driveBySystem(offsetAddress(m_t, o.address, b, m_model));
            if (destination && !area.writable && ins.op() != Op::Reset) {
                atOperand(add("OP002", Severity::Error, i,
                              ChecksTr::tr("%1 cannot be written: the program only reads it (%2)")
                                  .arg(device, QCoreApplication::translate("rung::model::Target",
                                                                           area.description))),
                          i, device);
            } else if (destination && driven) {
                atOperand(add("OP002", Severity::Error, i,
                              ChecksTr::tr("%1 cannot be written: the PLC drives it (%2)")
                                  .arg(device, QCoreApplication::translate("rung::model::Target",
                                                                           driven->description))),
                          i, device);
            } else if (kind == OperandKind::BitDest && drivesABit(ins.op()) &&
                       (area.kind == AreaKind::Timer || area.kind == AreaKind::Counter ||
                        (area.kind == AreaKind::Word && o.address.bit < 0))) {
                atOperand(add("OP002", Severity::Error, i,
                              ChecksTr::tr("%1 cannot drive %2: %3 are not relays")
                                  .arg(name(i), device,
                                       QCoreApplication::translate("rung::model::Target",
                                                                   area.description))),
                          i, device);
            }
            if (area.bank >= 0 &&
                (area.kind == AreaKind::Timer || area.kind == AreaKind::Counter)) {
                auto &use = bankUse[o.address.index];
                (area.kind == AreaKind::Timer ? use.first : use.second) = i + 1;
            }
        }
    }
    for (const auto &[n, use] : bankUse)
        if (use.first && use.second) {
            Finding &f = add(
                "OP003", Severity::Error, use.second - 1,
                ChecksTr::tr("Number %1 is used as a timer and as a counter; they share one bank")
                    .arg(n));
            f.diagnostic.related.push_back(location(use.first - 1));
        }
}

} // namespace rung::model::detail
