#pragma once

// A device image seen through a protocol map: the units a request names (Vigor link bytes,
// Modbus coils and registers, Host Link words and flags) read from a snapshot and turned into
// device commands for a write. The map (model/target/protocol_map.h, fromProtocol) decides
// which device a unit holds; nothing here knows a family.
//
//  - A unit of 1-bit space (a coil, a completion flag) is one bit device.
//  - A unit that holds a value, or part of one (a register of a 32-bit Vigor C200, a link byte
//    of a D word, low part first), reads that part of the value; a write changes that part
//    and keeps the rest.
//  - A unit that packs bit devices (a link byte of X, a PL110 register of Q) reads its bits;
//    bits the map leaves empty read 0 and are not written. A unit with no device is refused.
//  - Areas that share their element numbers (CPM1 TIM / CNT) are one element to the protocol:
//    a read answers with the one that holds something, a write goes to each.
//  - A timer's or counter's coil (Vigor link 0780h..07BFh) reads Snapshot::coils; a write to
//    it is refused, as the program drives it.
//  - The target's RUN bit (SystemRole::Run) reads the operating mode; where the map says so
//    (ProtocolMap::runBitStartsStops) writing it starts or stops the PLC.

#include "comms/slave/device_image.h"

#include "model/target/protocol_map.h"

#include <optional>
#include <vector>

namespace rung::comms::slave {

class MappedImage {
public:
    MappedImage(const model::Target &target, const model::ProtocolMap &map, int station);

    const model::Target &target() const { return *m_target; }
    const model::ProtocolMap &map() const { return *m_map; }

    enum class Refusal : std::uint8_t {
        None,
        NoDevice,  // the unit holds no device of the map
        ReadOnly,  // the protocol reads it but does not write it (ProtocolRange::readOnly), or
                   // the program drives it (a Vigor timer / counter coil)
        NotServed, // a part of a device the image does not hold (coils of an online image)
    };

    struct Units {
        Refusal refusal = Refusal::None;
        int unit = 0; // the first unit refused
        std::vector<std::uint16_t> values;
    };
    // count units from first, as the wire carries them (8 bits for a link byte, 16 for a word,
    // 0 / 1 for a unit of a 1-bit space).
    Units read(const model::Snapshot &snapshot, OperatingMode mode, model::ProtocolSpace space,
               int first, int count) const;

    struct Change {
        Refusal refusal = Refusal::None;
        int unit = 0;
        std::vector<model::DeviceCommand> commands;
        std::optional<OperatingMode> mode; // the RUN bit was written (runBitStartsStops)
    };
    // What writing these unit values means; nothing is applied yet.
    Change write(const model::Snapshot &snapshot, model::ProtocolSpace space, int first,
                 const std::vector<std::uint16_t> &values) const;
    // One bit of a unit that packs bit devices (Vigor 70h / 71h), or a unit of a 1-bit space.
    Change writeBit(model::ProtocolSpace space, int unit, int bit, bool on) const;

    // The device at a unit's bit (-1: the unit of a 1-bit space or the value a unit holds).
    std::optional<model::MappedDevice> device(model::ProtocolSpace space, int unit,
                                              int bit = -1) const;

private:
    std::optional<std::uint32_t> special(model::ProtocolSpace space, int unit) const;
    // The device and the same element of the areas that share its numbers (CPM1 TIM / CNT, one
    // bank: TC 005 is TIM 005 or CNT 005, whichever the program makes of it). The image keeps
    // each area's words apart, so a unit reads the one that holds something (a bit: any ON; a
    // value: the first that is not 0) and a value written goes to each.
    std::vector<model::MappedDevice> withBankMates(const model::MappedDevice &d) const;
    bool isRunBit(const model::Address &address) const;
    // nullopt: the image does not hold this bit (the coils of an image that does not know them).
    std::optional<bool> bitValue(const model::Snapshot &s, OperatingMode mode,
                                 const model::MappedDevice &d) const;
    std::uint32_t value(const model::Snapshot &s, OperatingMode mode,
                        const model::Address &a) const;
    Refusal addBit(Change &change, const model::MappedDevice &d, bool on) const;

    const model::Target *m_target;
    const model::ProtocolMap *m_map;
    int m_station;
    model::Address m_run; // the target's RUN bit, invalid when it has none
};

} // namespace rung::comms::slave
