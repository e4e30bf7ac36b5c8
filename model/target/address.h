#pragma once

// Parsing and printing device addresses and constants per target. The rules come from the
// target's area table (target.h); this file holds the only code that reads them.

#include "model/target/target.h"

#include <QString>
#include <QStringView>

#include <optional>
#include <variant>
#include <vector>

namespace rung::model {

// Why an address could not be parsed, with the column (0-based, within the text given)
// where the problem starts. The message is already translated.
struct AddressError {
    QString message;
    int column = 0;
};

// An address as parseAddress compares it with the table's prefixes: without spaces, upper
// case. "TIM 000", "TIM000" and "tim000" are one device, and VPC's "i00" may be typed "I00".
QString squeezeAddress(QStringView text);

// Parse a device address as the target writes it: "X10", "i00", "010.00", "HR00.05",
// "TIM 000" (CPM1 timer number), "I20", "SM0.0". With a model the model's ranges apply
// ("o31 is beyond VPC2416's outputs o00..o15"); without one, the family's full ranges.
std::variant<Address, AddressError> parseAddress(const Target &target, QStringView text,
                                                 const ModelVariant *model = nullptr);

// The element `offset` places after `address` (before it when negative) among the areas that
// share its prefix: D199 + 1 = D200 (the latched D area), X7 + 1 = X10 on an octal area.
// Invalid when no area of that prefix (on the model, if one is given) holds it.
Address offsetAddress(const Target &target, const Address &address, qint64 offset,
                      const ModelVariant *model = nullptr);

// Where a run of `count` elements from `first` breaks: the first element no area holds, or
// nullopt when all exist. The run goes on from an area only into the area after it in the
// table of the same prefix and kind that starts at the next number (D199 -> D200, the latched
// registers; M499 -> M500): such bit, word and channel areas lie one after another in the
// memory image (MemoryLayout), so a block of words stays a block. Timer and counter areas
// hold bits, values and set values apart, so a block of words (wordBlock) stops at their end;
// one element at a time (a zone reset, MUL's D+1) goes on from T199 to T200. A block
// instruction, MUL's D+1, CMP's three bits and a zone reset all ask it, in `check` and the
// simulator.
std::optional<Address> runBreaks(const Target &target, const Address &first, qint64 count,
                                 bool wordBlock = false);

// A range of devices as a user types it into a watch table: "D0..D15", "X0..X17" (Vigor X
// is octal: 16 inputs), "000.00..000.11" (CPM1 bits, across channels too), "M490..M510" (one
// prefix, though the table splits it in areas). Every device from the first to the last in
// the target's numbering, at most kMaxRange of them; a single device is a range of one.
constexpr int kMaxRange = 1024;
std::variant<std::vector<Address>, AddressError>
parseAddressRange(const Target &target, QStringView text, const ModelVariant *model = nullptr);

// The address of the target's system device with this role (VPC r88, CPM1 253.13 for
// AlwaysOn); an invalid Address when the target has none.
Address systemAddress(const Target &target, SystemRole role);

// Print an address in the target's canonical listing form.
QString formatAddress(const Target &target, const Address &address);

// A constant operand as written: Vigor K10 / H1F, CPM1 #0150 (BCD digits), VPC and PL110 plain
// numbers. value is the numeric value (for #0150: 150, the digits read as decimal).
struct Constant {
    qint64 value = 0;
    enum class Style : std::uint8_t { Decimal, Hex, Bcd, Plain } style = Style::Plain;
    friend bool operator==(const Constant &, const Constant &) = default;
};

std::variant<Constant, AddressError> parseConstant(const Target &target, QStringView text);
QString formatConstant(const Target &target, const Constant &constant);

} // namespace rung::model
