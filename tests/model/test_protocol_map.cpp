#include "model/target/address.h"
#include "model/target/protocol_map.h"

#include <gtest/gtest.h>

namespace rung::model {
namespace {

using S = ProtocolSpace;
using P = DevicePart;

Address parse(const Target &t, const char *text) {
    auto parsed = parseAddress(t, QString::fromLatin1(text));
    EXPECT_TRUE(std::holds_alternative<Address>(parsed)) << text;
    return std::holds_alternative<Address>(parsed) ? std::get<Address>(parsed) : Address{};
}

// The device's protocol address, and the way back to the same device.
ProtocolAddress map(const Target &t, ProtocolId id, const char *device, P part = P::Bit) {
    const ProtocolMap *m = findProtocolMap(t, id);
    EXPECT_NE(m, nullptr);
    if (!m)
        return {};
    const Address a = parse(t, device);
    const auto p = toProtocol(t, *m, a, part);
    EXPECT_TRUE(p.has_value()) << device;
    if (!p)
        return {};
    const auto back = fromProtocol(t, *m, p->space, p->unit, p->bit);
    EXPECT_TRUE(back.has_value()) << device;
    if (back) {
        EXPECT_EQ(back->area, a.area) << device;
        EXPECT_EQ(back->index, a.index) << device;
        EXPECT_EQ(back->bit, a.bit) << device;
        EXPECT_EQ(back->part, part) << device;
    }
    return *p;
}

int bitAddress(const ProtocolAddress &p) {
    return p.unit << 3 | p.bit;
}

TEST(ProtocolMap, VigorLinkByteAndBitAddressesOfProtocolsMd) {
    const Target &t = Target::get(Family::Vigor);
    const auto L = ProtocolId::VigorLink;
    EXPECT_EQ(bitAddress(map(t, L, "S20")), 0x1814);
    EXPECT_EQ(bitAddress(map(t, L, "M10")), 0x040A);
    EXPECT_EQ(bitAddress(map(t, L, "M100")), 0x0464);
    EXPECT_EQ(map(t, L, "M8"), (ProtocolAddress{S::LinkBytes, 0x0081, 0, 1}));
    EXPECT_EQ(map(t, L, "X0"), (ProtocolAddress{S::LinkBytes, 0x0000, 0, 1}));
    EXPECT_EQ(map(t, L, "X777"), (ProtocolAddress{S::LinkBytes, 0x003F, 7, 1})); // octal
    EXPECT_EQ(map(t, L, "Y30"), (ProtocolAddress{S::LinkBytes, 0x0043, 0, 1}));
    EXPECT_EQ(map(t, L, "Y47").unit, 0x0044);
    EXPECT_EQ(map(t, L, "M5119"), (ProtocolAddress{S::LinkBytes, 0x02FF, 7, 1}));
    EXPECT_EQ(map(t, L, "S999").unit, 0x037C);
    EXPECT_EQ(map(t, L, "T255").unit, 0x039F);
    EXPECT_EQ(map(t, L, "C0").unit, 0x03A0);
    EXPECT_EQ(map(t, L, "M9000").unit, 0x03E0);
    EXPECT_EQ(map(t, L, "M9255").unit, 0x03FF);
    EXPECT_EQ(map(t, L, "T0", P::Coil).unit, 0x0780);
    EXPECT_EQ(map(t, L, "C255", P::Coil).unit, 0x07BF);
    EXPECT_EQ(map(t, L, "T255", P::Value), (ProtocolAddress{S::LinkBytes, 0x15FE, -1, 2}));
    EXPECT_EQ(map(t, L, "D9000", P::Value).unit, 0x1600);
    EXPECT_EQ(map(t, L, "C199", P::Value).unit, 0x198E);
    EXPECT_EQ(map(t, L, "C200", P::Value), (ProtocolAddress{S::LinkBytes, 0x1A00, -1, 4}));
    EXPECT_EQ(map(t, L, "C255", P::Value).unit, 0x1ADC);
    EXPECT_EQ(map(t, L, "D0", P::Value).unit, 0x1C00);
    EXPECT_EQ(map(t, L, "D1", P::Value).unit, 0x1C02);
    EXPECT_EQ(map(t, L, "D8191", P::Value).unit, 0x5BFE);
}

TEST(ProtocolMap, VigorLinkHighBytesOfAWideValueLeadBackToTheirDevice) {
    const Target &t = Target::get(Family::Vigor);
    const ProtocolMap &m = *findProtocolMap(t, ProtocolId::VigorLink);
    const auto high = fromProtocol(t, m, S::LinkBytes, 0x1A03);
    ASSERT_TRUE(high.has_value());
    EXPECT_EQ(t.area(high->area).key, QLatin1String("C32"));
    EXPECT_EQ(high->index, 200);
    EXPECT_EQ(high->unitOffset, 3);
    EXPECT_FALSE(fromProtocol(t, m, S::LinkBytes, 0x03C0, 0).has_value()); // gap before M9000
    EXPECT_FALSE(fromProtocol(t, m, S::LinkBytes, 0x5C00).has_value());    // past D8191
}

TEST(ProtocolMap, VigorCp2ModbusComponentNumbersOfProtocolsMd) {
    const Target &t = Target::get(Family::Vigor);
    const auto M = ProtocolId::Modbus;
    EXPECT_EQ(map(t, M, "Y0"), (ProtocolAddress{S::Coils, 0, -1, 1}));
    EXPECT_EQ(map(t, M, "Y777").unit, 511);
    EXPECT_EQ(map(t, M, "M0").unit, 512);
    EXPECT_EQ(map(t, M, "M5119").unit, 5631);
    EXPECT_EQ(map(t, M, "S0").unit, 5632);
    EXPECT_EQ(map(t, M, "S999").unit, 6631);
    EXPECT_EQ(map(t, M, "T0").unit, 6656);
    EXPECT_EQ(map(t, M, "C255").unit, 7167);
    EXPECT_EQ(map(t, M, "M9000").unit, 7424);
    EXPECT_EQ(map(t, M, "M9255").unit, 7679);
    EXPECT_EQ(map(t, M, "X0"), (ProtocolAddress{S::DiscreteInputs, 0, -1, 1}));
    EXPECT_EQ(map(t, M, "X777").unit, 511);
    EXPECT_EQ(map(t, M, "D0", P::Value), (ProtocolAddress{S::HoldingRegisters, 0, -1, 1}));
    EXPECT_EQ(map(t, M, "D8191", P::Value).unit, 8191);
    EXPECT_EQ(map(t, M, "T0", P::Value).unit, 8192);
    EXPECT_EQ(map(t, M, "T255", P::Value).unit, 8447);
    EXPECT_EQ(map(t, M, "C0", P::Value).unit, 8448);
    EXPECT_EQ(map(t, M, "C199", P::Value).unit, 8647);
    EXPECT_EQ(map(t, M, "C200", P::Value), (ProtocolAddress{S::HoldingRegisters, 8648, -1, 2}));
    EXPECT_EQ(map(t, M, "C255", P::Value).unit, 8758); // 48758..48759
    EXPECT_EQ(map(t, M, "D9000", P::Value).unit, 8760);
    EXPECT_EQ(map(t, M, "D9255", P::Value).unit, 9015);
}

TEST(ProtocolMap, Pl110ModbusBitsAndWordsOfProtocolsMd) {
    const Target &t = Target::get(Family::Pl110);
    const auto M = ProtocolId::Modbus;
    const ProtocolMap &m = *findProtocolMap(t, M);
    EXPECT_EQ(m.maxReadUnits, 30);
    EXPECT_EQ(m.maxWriteUnits, 30);
    EXPECT_EQ(m.modelRegister, 0);
    EXPECT_EQ(m.versionRegister, 1);
    EXPECT_EQ(map(t, M, "Q1"), (ProtocolAddress{S::Coils, 2400, -1, 1}));
    EXPECT_EQ(map(t, M, "Q256").unit, 2655);
    EXPECT_EQ(map(t, M, "I1").unit, 1600);
    EXPECT_EQ(map(t, M, "B32").unit, 3231);
    EXPECT_EQ(map(t, M, "M1").unit, 4000);
    EXPECT_EQ(map(t, M, "T48").unit, 4847);
    EXPECT_EQ(map(t, M, "C16").unit, 5615);
    EXPECT_EQ(map(t, M, "SM0.0").unit, 16000); // RUN
    EXPECT_EQ(map(t, M, "SM3.2").unit, 16050);
    EXPECT_EQ(map(t, M, "V0.0").unit, 32000);
    EXPECT_EQ(map(t, M, "V349.15").unit, 37599);
    EXPECT_EQ(map(t, M, "V0", P::Value), (ProtocolAddress{S::HoldingRegisters, 2000, -1, 1}));
    EXPECT_EQ(map(t, M, "V349", P::Value).unit, 2349);
    EXPECT_EQ(map(t, M, "SM4", P::Value).unit, 1004);
    EXPECT_EQ(map(t, M, "T1", P::Value).unit, 12000);
    EXPECT_EQ(map(t, M, "PT1", P::Value).unit, 13000);
    EXPECT_EQ(map(t, M, "C1", P::Value).unit, 14000);
    EXPECT_EQ(map(t, M, "PV16", P::Value).unit, 15015);
    EXPECT_EQ(map(t, M, "AI1", P::Value).unit, 19000);
    EXPECT_EQ(map(t, M, "AQ2", P::Value).unit, 19401);
    EXPECT_EQ(map(t, M, "EEP0", P::Value).unit, 20000);
    EXPECT_EQ(map(t, M, "MMC12999", P::Value).unit, 42999);
    // Bit areas as words, 16 to a word: Q17 is bit 0 of word 151.
    const auto q17 = toProtocol(t, m, parse(t, "Q17"), P::Bit);
    ASSERT_TRUE(q17);
    // toProtocol gives the first range (coils); the word form is found from the word side.
    const auto word = fromProtocol(t, m, S::HoldingRegisters, 151, 0);
    ASSERT_TRUE(word);
    EXPECT_EQ(t.area(word->area).key, QLatin1String("Q"));
    EXPECT_EQ(word->index, 17);
    const auto i256 = fromProtocol(t, m, S::HoldingRegisters, 115, 15);
    ASSERT_TRUE(i256);
    EXPECT_EQ(i256->index, 256);
}

TEST(ProtocolMap, Pl110SlaveFactsOfTheManualsChapter3) {
    const Target &t = Target::get(Family::Pl110);
    const ProtocolMap &m = *findProtocolMap(t, ProtocolId::Modbus);
    EXPECT_EQ(m.stationRegister, 5);       // "Indirizzo di protocollo"
    EXPECT_EQ(m.anyStationUnit, 0xFF);     // "indirizzo 0xFF a cui risponde qualsiasi slave"
    EXPECT_TRUE(m.runBitStartsStops);      // SM0 bit 0
    EXPECT_EQ(m.illegalValueException, 4); // "ILLEGAL DATA VALUE (0x04)"
    // The R column: inputs as words, timer / counter bits, analog inputs are read only; the
    // inputs as bits, outputs and analog outputs are R/W.
    const auto readOnly = [&](S space, int unit, int bit = -1) {
        const auto d = fromProtocol(t, m, space, unit, bit);
        EXPECT_TRUE(d.has_value()) << unit;
        return d && d->readOnly;
    };
    EXPECT_TRUE(readOnly(S::HoldingRegisters, 100, 0));
    EXPECT_TRUE(readOnly(S::HoldingRegisters, 300, 0));
    EXPECT_TRUE(readOnly(S::HoldingRegisters, 350, 15));
    EXPECT_TRUE(readOnly(S::HoldingRegisters, 19000));
    EXPECT_TRUE(readOnly(S::Coils, 4800));
    EXPECT_TRUE(readOnly(S::Coils, 5615));
    EXPECT_FALSE(readOnly(S::Coils, 1600));
    EXPECT_FALSE(readOnly(S::Coils, 2400));
    EXPECT_FALSE(readOnly(S::HoldingRegisters, 150, 0));
    EXPECT_FALSE(readOnly(S::HoldingRegisters, 19400));
    EXPECT_FALSE(readOnly(S::HoldingRegisters, 2000));
}

TEST(ProtocolMap, Cpm1HostLinkModelCodeOfW353) {
    EXPECT_EQ(findProtocolMap(Target::get(Family::Cpm1), ProtocolId::HostLink)->modelCode, 0x11);
    // The Vigor maps have no run bit, model code or any-station address.
    for (const ProtocolMap &m : Target::get(Family::Vigor).protocolMaps) {
        EXPECT_FALSE(m.runBitStartsStops);
        EXPECT_EQ(m.modelCode, -1);
        EXPECT_EQ(m.anyStationUnit, -1);
        EXPECT_EQ(m.illegalValueException, 3);
    }
}

TEST(ProtocolMap, Cpm1HostLinkAreas) {
    const Target &t = Target::get(Family::Cpm1);
    const auto H = ProtocolId::HostLink;
    EXPECT_EQ(map(t, H, "010.00"), (ProtocolAddress{S::HostLinkIr, 10, 0, 1}));
    EXPECT_EQ(map(t, H, "000.05"), (ProtocolAddress{S::HostLinkIr, 0, 5, 1}));
    EXPECT_EQ(map(t, H, "010", P::Value), (ProtocolAddress{S::HostLinkIr, 10, -1, 1}));
    EXPECT_EQ(map(t, H, "200.15"), (ProtocolAddress{S::HostLinkIr, 200, 15, 1}));
    EXPECT_EQ(map(t, H, "HR05.03"), (ProtocolAddress{S::HostLinkHr, 5, 3, 1}));
    EXPECT_EQ(map(t, H, "DM 0100", P::Value), (ProtocolAddress{S::HostLinkDm, 100, -1, 1}));
    EXPECT_EQ(map(t, H, "DM 6144", P::Value), (ProtocolAddress{S::HostLinkDm, 6144, -1, 1}));
    EXPECT_EQ(map(t, H, "TIM 005", P::Value), (ProtocolAddress{S::HostLinkTimerPv, 5, -1, 1}));
    EXPECT_EQ(map(t, H, "TIM 127"), (ProtocolAddress{S::HostLinkCompletion, 127, -1, 1}));
    // TIM and CNT share their numbers (one bank): CNT 127 is the same flag, and the way back
    // names the bank's first area.
    const ProtocolMap &m = *findProtocolMap(t, H);
    EXPECT_EQ(toProtocol(t, m, parse(t, "CNT 127"), P::Bit),
              (ProtocolAddress{S::HostLinkCompletion, 127, -1, 1}));
}

TEST(ProtocolMap, Cpm1HostLinkReachesWhatProtocolsMdGivesAndNoFurther) {
    // Omron CPM1/SRM1 manual W353 (Host Link RR / WR) and the Omron CPM1 guide 3.5 (memory
    // map): RR / WR reach the IR and SR words 000..255 (SR 253..255: the PLC's flags,
    // read with RR, never written), RD / WD DM 0000..1023 and 6144..6655. The PLC has DM past
    // 6655; the protocol map does not.
    const Target &t = Target::get(Family::Cpm1);
    const ProtocolMap &m = *findProtocolMap(t, ProtocolId::HostLink);
    const auto H = ProtocolId::HostLink;
    EXPECT_EQ(map(t, H, "000", P::Value), (ProtocolAddress{S::HostLinkIr, 0, -1, 1}));
    EXPECT_EQ(map(t, H, "252", P::Value), (ProtocolAddress{S::HostLinkIr, 252, -1, 1}));
    EXPECT_EQ(map(t, H, "253", P::Value), (ProtocolAddress{S::HostLinkIr, 253, -1, 1}));
    EXPECT_EQ(map(t, H, "255", P::Value), (ProtocolAddress{S::HostLinkIr, 255, -1, 1}));
    EXPECT_EQ(map(t, H, "253.13"), (ProtocolAddress{S::HostLinkIr, 253, 13, 1}));
    EXPECT_EQ(map(t, H, "255.06"), (ProtocolAddress{S::HostLinkIr, 255, 6, 1}));
    EXPECT_EQ(map(t, H, "DM 6655", P::Value), (ProtocolAddress{S::HostLinkDm, 6655, -1, 1}));
    // The way back: the flags' channels are SR, read only; the SR words below them are not.
    for (const int channel : {253, 254, 255}) {
        const auto word = fromProtocol(t, m, S::HostLinkIr, channel);
        ASSERT_TRUE(word.has_value()) << channel;
        EXPECT_EQ(formatAddress(t, {word->area, word->index, -1}), QString::number(channel));
        EXPECT_TRUE(word->readOnly) << channel;
    }
    const auto flag = fromProtocol(t, m, S::HostLinkIr, 253, 13);
    ASSERT_TRUE(flag.has_value());
    EXPECT_EQ(formatAddress(t, {flag->area, flag->index, flag->bit}), QStringLiteral("253.13"));
    EXPECT_TRUE(flag->readOnly);
    const auto analog = fromProtocol(t, m, S::HostLinkIr, 250);
    ASSERT_TRUE(analog.has_value());
    EXPECT_FALSE(analog->readOnly);
    EXPECT_FALSE(toProtocol(t, m, parse(t, "DM 6656"), P::Value).has_value());
    EXPECT_FALSE(fromProtocol(t, m, S::HostLinkIr, 256).has_value());
    EXPECT_FALSE(fromProtocol(t, m, S::HostLinkDm, 6656).has_value());
    EXPECT_TRUE(fromProtocol(t, m, S::HostLinkDm, 6655).has_value());
}

TEST(ProtocolMap, ABitTheUnitDoesNotHaveMapsToNothing) {
    // Bit 16 of register 150 (Q1..Q16) would be Q17, bit 0 of the next register: refused.
    const Target &pl = Target::get(Family::Pl110);
    const ProtocolMap &modbus = *findProtocolMap(pl, ProtocolId::Modbus);
    EXPECT_TRUE(fromProtocol(pl, modbus, S::HoldingRegisters, 150, 15).has_value());
    EXPECT_FALSE(fromProtocol(pl, modbus, S::HoldingRegisters, 150, 16).has_value());
    EXPECT_FALSE(fromProtocol(pl, modbus, S::HoldingRegisters, 150, -2).has_value());
    // A Vigor link byte holds 8 bits: bit 8 of M8..M15's byte is not M16.
    const Target &vigor = Target::get(Family::Vigor);
    const ProtocolMap &link = *findProtocolMap(vigor, ProtocolId::VigorLink);
    EXPECT_TRUE(fromProtocol(vigor, link, S::LinkBytes, 0x0081, 7).has_value());
    EXPECT_FALSE(fromProtocol(vigor, link, S::LinkBytes, 0x0081, 8).has_value());
    EXPECT_EQ(link.maxReadUnits, 128); // Vigor M/VB/VH communication manual, B-5-3
    // Coils are 1-bit units: the bit is ignored, as documented.
    EXPECT_TRUE(fromProtocol(pl, modbus, S::Coils, 2400, 99).has_value());
}

TEST(ProtocolMap, DevicesOutsideAMapHaveNoProtocolAddress) {
    const Target &t = Target::get(Family::Vigor);
    const ProtocolMap &m = *findProtocolMap(t, ProtocolId::Modbus);
    // X is an input: no coil; D has no bit part on the CP2 map.
    EXPECT_FALSE(toProtocol(t, m, parse(t, "D0"), P::Bit).has_value());
    EXPECT_FALSE(toProtocol(t, m, parse(t, "X0"), P::Value).has_value());
    EXPECT_FALSE(toProtocol(t, m, Address{}, P::Bit).has_value());
    EXPECT_EQ(findProtocolMap(Target::get(Family::Vpc), ProtocolId::Modbus), nullptr);
    EXPECT_EQ(findProtocolMap(Target::get(Family::Cpm1), ProtocolId::Modbus), nullptr);
}

} // namespace
} // namespace rung::model
