#include "model/comm/link_table.h"

#include "model/target/address.h"

#include <variant>

namespace rung::model {

namespace {

const LinkDeviceCode *findCode(const Target &target, LinkTableKind kind, int code) {
    for (const LinkDeviceCode &c : target.linkDeviceCodes)
        if (c.code == code && (kind == LinkTableKind::EasyLink || c.modbus))
            return &c;
    return nullptr;
}

bool isValueArea(const Area &a) {
    return a.kind != AreaKind::Bit;
}

// The first device of a run: the table's number written after the code's prefix, as a
// listing writes it (X10 on an octal area is the ninth input; X8 is no device), of the
// code's kind, and every one of the `length` devices there.
LinkStatus device(const Target &target, const LinkDeviceCode &code, int number, int length,
                  Address *out, int *valueBits) {
    if (number < 0)
        return LinkStatus::BadDeviceNumber;
    const auto parsed =
        parseAddress(target, QString::fromLatin1(code.prefix) + QString::number(number));
    const auto *a = std::get_if<Address>(&parsed);
    if (!a || a->bit >= 0)
        return LinkStatus::BadDeviceNumber;
    const Area &area = target.area(a->area);
    const bool values = !code.bits;
    if (values && !isValueArea(area))
        return LinkStatus::BadDeviceNumber;
    if (values && code.valueBits && area.wordBits != code.valueBits)
        return LinkStatus::BadDeviceNumber; // C200 is no 16-bit counter, C0 no 32-bit one
    for (int k = 1; k < length; ++k) {
        const Address next = linkDevice(target, *a, k);
        if (!next.valid() || target.area(next.area).wordBits != area.wordBits)
            return LinkStatus::BadDeviceNumber;
    }
    *out = *a;
    *valueBits = area.wordBits;
    return LinkStatus::Normal;
}

} // namespace

Address linkDevice(const Target &target, const Address &first, int offset) {
    const Address a = offsetAddress(target, first, offset);
    if (!a.valid() || target.area(a.area).prefix != target.area(first.area).prefix ||
        target.area(a.area).kind != target.area(first.area).kind)
        return {};
    return a;
}

LinkSet readLinkSet(const Target &target, LinkTableKind kind, const std::int32_t *r) {
    LinkSet set;
    set.station = r[0];
    const int command = r[1];
    set.length = r[2];
    const bool modbus = kind == LinkTableKind::Modbus;
    set.write = command == 2 || (modbus && command == 3);
    set.single = modbus && command == 3;
    if (set.single)
        set.length = 1; // B-3-6: the length "is ignored" for command 3
    // No status is listed for a command code out of range: it is a wrong designation, 4.
    if (command < 1 || command > (modbus ? 3 : 2)) {
        set.status = LinkStatus::BadDeviceType;
        return set;
    }
    const LinkDeviceCode *master = findCode(target, kind, r[3]);
    const LinkDeviceCode *slave = modbus ? nullptr : findCode(target, kind, r[5]);
    const bool slaveKnown =
        modbus ? (r[5] == 0 || r[5] == 1 || r[5] == 3 || r[5] == 4) : slave != nullptr;
    if (!master || !slaveKnown) {
        set.status = LinkStatus::BadDeviceType;
        return set;
    }
    set.bits = master->bits;
    const bool slaveBits = modbus ? (r[5] == 0 || r[5] == 1) : slave->bits;
    if (set.bits != slaveBits) {
        set.status = LinkStatus::AttributesDiffer;
        return set;
    }
    // B-3-3: 1..64 devices, 1..32 of a 32-bit counter.
    const int most = (!master->bits && master->valueBits == 32) ||
                             (slave && !slave->bits && slave->valueBits == 32)
                         ? 32
                         : 64;
    if (set.length < 1 || set.length > most) {
        set.status = LinkStatus::BadLength;
        return set;
    }
    if (const LinkStatus s =
            device(target, *master, r[4], set.length, &set.master, &set.masterValueBits);
        s != LinkStatus::Normal) {
        set.status = s;
        return set;
    }
    if (modbus) {
        // Types 1 and 3 are read-only on the slave: writing them is the wrong device type.
        if (set.write && (r[5] == 1 || r[5] == 3)) {
            set.status = LinkStatus::BadDeviceType;
            return set;
        }
        if (set.masterValueBits == 32) { // a MODBUS register holds 16 bits
            set.status = LinkStatus::AttributesDiffer;
            return set;
        }
        set.space = r[5] == 0   ? ProtocolSpace::Coils
                    : r[5] == 1 ? ProtocolSpace::DiscreteInputs
                    : r[5] == 3 ? ProtocolSpace::InputRegisters
                                : ProtocolSpace::HoldingRegisters;
        set.unit = r[6];
        if (set.unit < 0 || set.unit + set.length > 32768) // B-3-6: numbers 0..32767
            set.status = LinkStatus::BadDeviceNumber;
        return set;
    }
    int slaveBitsWide = 16;
    if (const LinkStatus s = device(target, *slave, r[6], set.length, &set.slave, &slaveBitsWide);
        s != LinkStatus::Normal) {
        set.status = s;
        return set;
    }
    if (!set.bits && slaveBitsWide != set.masterValueBits)
        set.status = LinkStatus::AttributesDiffer;
    return set;
}

} // namespace rung::model
