#include "comms/slave/mapped_image.h"

#include "model/target/address.h"

#include <map>

namespace rung::comms::slave {

namespace {

using model::DeviceCommand;
using model::DevicePart;
using model::ProtocolSpace;

model::Address addressOf(const model::MappedDevice &d) {
    return {d.area, d.index, d.part == DevicePart::Value ? -1 : d.bit};
}

std::uint32_t unitMask(int width) {
    return width >= 32 ? 0xFFFFFFFFu : (1u << width) - 1u;
}

} // namespace

MappedImage::MappedImage(const model::Target &target, const model::ProtocolMap &map, int station)
    : m_target(&target)
    , m_map(&map)
    , m_station(station)
    , m_run(model::systemAddress(target, model::SystemRole::Run)) {}

std::optional<model::MappedDevice> MappedImage::device(ProtocolSpace space, int unit,
                                                       int bit) const {
    return model::fromProtocol(*m_target, *m_map, space, unit, bit);
}

// The registers that describe the PLC (PL110 words 0, 1 and 5, PL110 manual 3.2) and the
// units the map lists with no device (ProtocolMap::fixedUnits). Read only.
std::optional<std::uint32_t> MappedImage::special(ProtocolSpace space, int unit) const {
    if (space == ProtocolSpace::HoldingRegisters) {
        if (unit == m_map->modelRegister)
            return std::uint32_t(std::max(0, m_map->modelCode));
        if (unit == m_map->versionRegister)
            return 0u; // the virtual PLC has no firmware version of the vendor's to report
        if (unit == m_map->stationRegister)
            return std::uint32_t(m_station & 0xFFFF);
    }
    if (const auto v = model::fixedUnitValue(*m_map, space, unit))
        return std::uint32_t(*v);
    return std::nullopt;
}

bool MappedImage::isRunBit(const model::Address &address) const {
    return m_run.valid() && address == m_run;
}

std::optional<bool> MappedImage::bitValue(const model::Snapshot &s, OperatingMode mode,
                                          const model::MappedDevice &d) const {
    const model::Address a = addressOf(d);
    if (d.part == DevicePart::Coil)
        return s.coil(a); // nullopt: an image that does not know its coils
    if (isRunBit(a))
        return mode != OperatingMode::Program;
    return s.bit(a);
}

std::vector<model::MappedDevice> MappedImage::withBankMates(const model::MappedDevice &d) const {
    std::vector<model::MappedDevice> out{d};
    const int bank = m_target->area(d.area).bank;
    if (bank < 0)
        return out;
    for (std::size_t k = 0; k < m_target->areas.size(); ++k) {
        const model::Area &other = m_target->areas[k];
        if (int(k) != d.area && other.bank == bank && d.index >= other.first &&
            d.index <= other.last) {
            model::MappedDevice mate = d;
            mate.area = int(k);
            out.push_back(mate);
        }
    }
    return out;
}

std::uint32_t MappedImage::value(const model::Snapshot &s, OperatingMode mode,
                                 const model::Address &a) const {
    auto v = static_cast<std::uint32_t>(s.value(a));
    if (m_run.valid() && m_run.bit >= 0 && a.area == m_run.area && a.index == m_run.index) {
        const std::uint32_t bit = 1u << m_run.bit;
        v = mode != OperatingMode::Program ? (v | bit) : (v & ~bit);
    }
    return v;
}

MappedImage::Units MappedImage::read(const model::Snapshot &s, OperatingMode mode,
                                     ProtocolSpace space, int first, int count) const {
    Units out;
    const int width = model::unitBits(space);
    out.values.reserve(static_cast<std::size_t>(std::max(0, count)));
    for (int unit = first; unit < first + count; ++unit) {
        auto refuse = [&](Refusal why) {
            out.refusal = why;
            out.unit = unit;
            out.values.clear();
            return out;
        };
        if (const auto v = special(space, unit)) {
            out.values.push_back(std::uint16_t(*v));
            continue;
        }
        if (const auto d = device(space, unit); d && (width == 1 || d->part == DevicePart::Value)) {
            if (width == 1) {
                bool known = true;
                bool on = false;
                for (const model::MappedDevice &m : withBankMates(*d)) {
                    const std::optional<bool> b = bitValue(s, mode, m);
                    known = known && b.has_value();
                    on = on || b.value_or(false);
                }
                if (!known)
                    return refuse(Refusal::NotServed);
                out.values.push_back(on ? 1 : 0);
            } else {
                std::uint32_t whole = 0;
                for (const model::MappedDevice &m : withBankMates(*d))
                    if ((whole = value(s, mode, addressOf(m))) != 0)
                        break;
                const std::uint32_t v = whole >> (d->unitOffset * width);
                out.values.push_back(std::uint16_t(v & unitMask(width)));
            }
            continue;
        }
        if (width == 1)
            return refuse(Refusal::NoDevice);
        bool any = false;
        std::uint32_t packed = 0;
        for (int b = 0; b < width; ++b) {
            const auto d = device(space, unit, b);
            if (!d)
                continue;
            const std::optional<bool> on = bitValue(s, mode, *d);
            if (!on)
                return refuse(Refusal::NotServed);
            any = true;
            if (*on)
                packed |= 1u << b;
        }
        if (!any)
            return refuse(Refusal::NoDevice);
        out.values.push_back(std::uint16_t(packed));
    }
    return out;
}

MappedImage::Refusal MappedImage::addBit(Change &change, const model::MappedDevice &d,
                                         bool on) const {
    // A coil is the program's: the next scan drives it from the box's input again.
    if (d.readOnly || d.part == DevicePart::Coil)
        return Refusal::ReadOnly;
    const model::Address a = addressOf(d);
    if (isRunBit(a) && m_map->runBitStartsStops) {
        change.mode = on ? OperatingMode::Run : OperatingMode::Program;
        return Refusal::None;
    }
    change.commands.push_back({DeviceCommand::Kind::WriteBit, a, on ? 1 : 0});
    return Refusal::None;
}

MappedImage::Change MappedImage::write(const model::Snapshot &s, ProtocolSpace space, int first,
                                       const std::vector<std::uint16_t> &values) const {
    Change change;
    const int width = model::unitBits(space);
    // Values written in parts (a 32-bit value from two registers, a word from two link bytes)
    // are gathered, so that each device gets one write, in the order the request names them.
    std::map<model::Address, std::uint32_t> wholeValues;
    std::vector<model::Address> order;
    auto refuse = [&change](Refusal why, int unit) {
        change.refusal = why;
        change.unit = unit;
        change.commands.clear();
        change.mode.reset();
        return change;
    };
    for (std::size_t i = 0; i < values.size(); ++i) {
        const int unit = first + int(i);
        const std::uint32_t v = values[i] & unitMask(width);
        if (special(space, unit))
            return refuse(Refusal::ReadOnly, unit);
        if (const auto d = device(space, unit); d && (width == 1 || d->part == DevicePart::Value)) {
            if (width == 1) {
                if (const Refusal r = addBit(change, *d, v != 0); r != Refusal::None)
                    return refuse(r, unit);
                continue;
            }
            if (d->readOnly)
                return refuse(Refusal::ReadOnly, unit);
            for (const model::MappedDevice &m : withBankMates(*d)) {
                const model::Address a = addressOf(m);
                auto [it, added] =
                    wholeValues.try_emplace(a, static_cast<std::uint32_t>(s.value(a)));
                if (added)
                    order.push_back(a);
                const int shift = d->unitOffset * width;
                it->second = (it->second & ~(unitMask(width) << shift)) | (v << shift);
            }
            continue;
        }
        if (width == 1)
            return refuse(Refusal::NoDevice, unit);
        bool any = false;
        for (int b = 0; b < width; ++b) {
            const auto d = device(space, unit, b);
            if (!d)
                continue;
            any = true;
            if (const Refusal r = addBit(change, *d, (v >> b) & 1u); r != Refusal::None)
                return refuse(r, unit);
        }
        if (!any)
            return refuse(Refusal::NoDevice, unit);
    }
    for (const model::Address &a : order) {
        std::uint32_t v = wholeValues[a];
        if (m_run.valid() && m_run.bit >= 0 && a.area == m_run.area && a.index == m_run.index &&
            m_map->runBitStartsStops) {
            // The word that holds the RUN bit: the bit asks for a mode, the rest is written
            // with the bit as the PLC keeps it.
            const std::uint32_t bit = 1u << m_run.bit;
            change.mode = (v & bit) ? OperatingMode::Run : OperatingMode::Program;
            v = (v & ~bit) | (static_cast<std::uint32_t>(s.value(a)) & bit);
        }
        change.commands.push_back({DeviceCommand::Kind::WriteWord, a, qint64(v)});
    }
    return change;
}

MappedImage::Change MappedImage::writeBit(ProtocolSpace space, int unit, int bit, bool on) const {
    Change change;
    const auto d = device(space, unit, model::unitBits(space) == 1 ? -1 : bit);
    if (!d || d->part == DevicePart::Value) {
        change.refusal = Refusal::NoDevice;
        change.unit = unit;
        return change;
    }
    if (const Refusal r = addBit(change, *d, on); r != Refusal::None) {
        change = {};
        change.refusal = r;
        change.unit = unit;
    }
    return change;
}

} // namespace rung::comms::slave
