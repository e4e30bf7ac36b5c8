#include "model/target/protocol_map.h"

#include "model/target/target.h"

namespace rung::model {

namespace {

int areaIndex(const Target &target, const char *key) {
    const QString k = QString::fromLatin1(key);
    for (std::size_t i = 0; i < target.areas.size(); ++i)
        if (target.areas[i].key == k)
            return int(i);
    return -1;
}

int unitsOf(const Area &area, ProtocolSpace space) {
    return std::max(1, area.wordBits / unitBits(space));
}

// The last element of the area the range reaches.
int lastOf(const ProtocolRange &r, const Area &area) {
    return r.last < 0 ? area.last : std::min(r.last, area.last);
}

} // namespace

int unitBits(ProtocolSpace space) {
    switch (space) {
    case ProtocolSpace::LinkBytes:
        return 8;
    case ProtocolSpace::Coils:
    case ProtocolSpace::DiscreteInputs:
    case ProtocolSpace::HostLinkCompletion:
        return 1;
    default:
        return 16;
    }
}

const ProtocolMap *findProtocolMap(const Target &target, ProtocolId protocol) {
    for (const auto &map : target.protocolMaps)
        if (map.protocol == protocol)
            return &map;
    return nullptr;
}

std::optional<ProtocolAddress> toProtocol(const Target &target, const ProtocolMap &map,
                                          const Address &address, DevicePart part) {
    if (!address.valid() || address.area >= int(target.areas.size()))
        return std::nullopt;
    const Area &area = target.area(address.area);
    if (address.index < area.first || address.index > area.last)
        return std::nullopt;
    // A word's bit (V3.5, 010.00) is the Bit part of a word area.
    if (address.bit >= 0 && part != DevicePart::Bit)
        return std::nullopt;
    for (const auto &r : map.ranges) {
        if (r.part != part || areaIndex(target, r.area) != address.area ||
            address.index < r.origin || address.index > lastOf(r, area))
            continue;
        const int element = address.index - r.origin;
        const int width = unitBits(r.space);
        if (part == DevicePart::Value)
            return ProtocolAddress{r.space, r.start + element * unitsOf(area, r.space), -1,
                                   unitsOf(area, r.space)};
        int position = element;
        if (area.holdsWords()) {
            if (address.bit < 0 || address.bit >= area.wordBits)
                return std::nullopt;
            position = element * area.wordBits + address.bit;
        }
        if (width == 1)
            return ProtocolAddress{r.space, r.start + position, -1, 1};
        return ProtocolAddress{r.space, r.start + position / width, position % width, 1};
    }
    return std::nullopt;
}

std::optional<MappedDevice> fromProtocol(const Target &target, const ProtocolMap &map,
                                         ProtocolSpace space, int unit, int bit) {
    const int width = unitBits(space);
    if (width > 1 && (bit < -1 || bit >= width))
        return std::nullopt; // no such bit in the unit: it would reach into the next one
    const bool wantBit = width == 1 || bit >= 0;
    for (const auto &r : map.ranges) {
        if (r.space != space || (r.part == DevicePart::Value) == wantBit || unit < r.start)
            continue;
        const int ai = areaIndex(target, r.area);
        if (ai < 0)
            continue;
        const Area &area = target.area(ai);
        MappedDevice d{ai, 0, -1, r.part, 0, r.readOnly};
        if (r.part == DevicePart::Value) {
            const int units = unitsOf(area, space);
            d.index = r.origin + (unit - r.start) / units;
            d.unitOffset = (unit - r.start) % units;
        } else {
            const int position = (unit - r.start) * width + (width == 1 ? 0 : bit);
            if (area.holdsWords()) {
                d.index = r.origin + position / area.wordBits;
                d.bit = position % area.wordBits;
            } else {
                d.index = r.origin + position;
            }
        }
        if (d.index >= area.first && d.index <= lastOf(r, area))
            return d;
    }
    return std::nullopt;
}

std::optional<int> fixedUnitValue(const ProtocolMap &map, ProtocolSpace space, int unit) {
    for (const ProtocolFixedUnits &f : map.fixedUnits)
        if (f.space == space && unit >= f.first && unit <= f.last)
            return f.value;
    return std::nullopt;
}

} // namespace rung::model
