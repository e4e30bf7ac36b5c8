#include "model/target/target_data.h"

#include <QCoreApplication>

#include <tuple>

// Omron SYSMAC CPM1 (Omron CPM1 guide): 16-bit channels written CCC.BB, BCD constants with '#',
// instructions with Omron's function codes. The canonical spelling carries the function code
// as SYSWIN prints it ("KEEP(11)"); the bare name is an alias.

namespace rung::model::detail {

namespace {

using K = OperandKind;

InstructionSpec &withCode(InstructionSpec &s, const char *bare, int code) {
    s.functionCode = code;
    s.aliases.append(QString::fromLatin1(bare));
    return s;
}

// The CPU unit's peripheral port: the Omron CPM1 guide names it (2.1, item 9
// "Perifériacsatlakozó") and uses it for "Monitorozás (PLC-PC on-line kapcsolat)" (3), and
// gives nothing of its settings. Those are Omron's public Host Link documentation (the
// CPM1/SRM1 programming manual W353, PC Setup of the peripheral port, DM 6650 / 6651): Host
// Link at 1200, 2400, 4800, 9600 or 19200 bps, 7 or 8 data bits, even, odd or no parity, 1 or
// 2 stop bits, unit number 00..31; the standard setting 9600 bps, 7 data bits, even parity, 2
// stop bits, unit 0 (Omron's Host Link C-mode: docs/comms.md). The
// port answers a host from the PLC's memory through the Host Link map (target_cpm1_maps.cpp).
std::vector<PortSpec> cpm1Ports() {
    PortApplication hostLink;
    hostLink.id = "host-link";
    hostLink.name = QT_TRANSLATE_NOOP("rung::model::Target", "Host Link");
    hostLink.bauds = {9600, 1200, 2400, 4800, 19200};
    hostLink.frame = "7E2";
    hostLink.stationMin = 0;
    hostLink.stationMax = 31;
    hostLink.station = 0;
    hostLink.answers = ProtocolId::HostLink;
    PortSpec peripheral;
    peripheral.name = QStringLiteral("PERIPHERAL");
    peripheral.description = QT_TRANSLATE_NOOP(
        "rung::model::Target", "the CPU unit's peripheral port (Host Link, 9600 bps 7E2, unit 0)");
    peripheral.applications = {hostLink};
    return {peripheral};
}

} // namespace

Target makeCpm1Target() {
    Target t;
    t.family = Family::Cpm1;
    t.id = QStringLiteral("cpm1");
    t.displayName = QStringLiteral("CPM1");
    t.defaultTimerBaseMs = 100.0;

    auto channels = [&t](const char *key, int first, int last, const char *description) -> Area & {
        Area &a = addArea(t, key, "", AreaKind::Channel, first, last, description);
        a.numbering = Numbering::ChannelBit;
        a.digits = 3;
        return a;
    };
    Area &in = channels("IN", 0, 9, QT_TRANSLATE_NOOP("rung::model::Target", "input channels"));
    in.writable = false;
    in.physical = true;
    channels("OUT", 10, 19, QT_TRANSLATE_NOOP("rung::model::Target", "output channels")).physical =
        true;
    channels("WR", 200, 231, QT_TRANSLATE_NOOP("rung::model::Target", "work channels"));
    Area &sr =
        channels("SR", 232, 255, QT_TRANSLATE_NOOP("rung::model::Target", "special channels"));
    sr.system = true;
    sr.writable = false;
    Area &hr = addArea(t, "HR", "HR", AreaKind::Channel, 0, 19,
                       QT_TRANSLATE_NOOP("rung::model::Target", "holding relays"));
    hr.numbering = Numbering::ChannelBit;
    hr.digits = 2;
    hr.retentive = true;
    // Link relays LR00..LR15 (the Omron CPM1 guide names LR among the channels a set value may
    // come from; W353: LR 00..15, bits LR 00.00..LR 15.15, work bits when no 1:1 link is used,
    // cleared at power-on).
    Area &lr = addArea(t, "LR", "LR", AreaKind::Channel, 0, 15,
                       QT_TRANSLATE_NOOP("rung::model::Target", "link relays"));
    lr.numbering = Numbering::ChannelBit;
    lr.digits = 2;
    // Temporary relays TR 0..7 (W353): OUT TR 0 keeps a branch point's condition for a later
    // LD TR 0 in the same rung, as W353's own examples write branching rungs; every rung may
    // use them again.
    Area &tr = addArea(t, "TR", "TR ", AreaKind::Bit, 0, 7,
                       QT_TRANSLATE_NOOP("rung::model::Target", "temporary relays"));
    tr.digits = 1;
    tr.branchMemory = true;
    Area &tim = addArea(t, "TIM", "TIM ", AreaKind::Timer, 0, 127,
                        QT_TRANSLATE_NOOP("rung::model::Target", "timers"));
    tim.digits = 3;
    tim.bank = 0;
    // The Omron CPM1 guide (3.5) calls the shared bank the "TC - terület TC000-TC127": TC 005
    // is TIM 005 or CNT 005, whichever the program makes of it (the parser decides, bankAlias).
    tim.prefixAliases = {QStringLiteral("TC ")};
    tim.bankAlias = true;
    Area &cnt = addArea(t, "CNT", "CNT ", AreaKind::Counter, 0, 127,
                        QT_TRANSLATE_NOOP("rung::model::Target", "counters"));
    cnt.digits = 3;
    cnt.bank = 0;
    cnt.prefixAliases = {QStringLiteral("TC ")};
    cnt.bankAlias = true;
    cnt.retentive = true;
    Area &dm = addArea(t, "DM", "DM ", AreaKind::Word, 0, 1023,
                       QT_TRANSLATE_NOOP("rung::model::Target", "data memory"));
    dm.digits = 4;
    dm.retentive = true;
    Area &dmr = addArea(t, "DMR", "DM ", AreaKind::Word, 6144, 6667,
                        QT_TRANSLATE_NOOP("rung::model::Target", "read-only data memory"));
    dmr.digits = 4;
    dmr.writable = false;
    dmr.retentive = true;

    t.systemDevices = {
        {QStringLiteral("253.13"), SystemRole::AlwaysOn,
         QT_TRANSLATE_NOOP("rung::model::Target", "always ON")},
        {QStringLiteral("253.14"), SystemRole::Other,
         QT_TRANSLATE_NOOP("rung::model::Target", "always OFF")},
        {QStringLiteral("253.15"), SystemRole::FirstScan,
         QT_TRANSLATE_NOOP("rung::model::Target", "ON for the first scan")},
        {QStringLiteral("254.00"), SystemRole::Clock1min,
         QT_TRANSLATE_NOOP("rung::model::Target", "1 min clock")},
        {QStringLiteral("254.01"), SystemRole::Other,
         QT_TRANSLATE_NOOP("rung::model::Target", "0.02 s clock")},
        {QStringLiteral("255.00"), SystemRole::Clock100ms,
         QT_TRANSLATE_NOOP("rung::model::Target", "0.1 s clock")},
        {QStringLiteral("255.01"), SystemRole::Other,
         QT_TRANSLATE_NOOP("rung::model::Target", "0.2 s clock")},
        {QStringLiteral("255.02"), SystemRole::Clock1s,
         QT_TRANSLATE_NOOP("rung::model::Target", "1 s clock")},
        // The arithmetic flags (W353 appendix B), set by the application instructions and
        // turned OFF at END(01), and the step flag (W353 STEP(08)).
        {QStringLiteral("255.03"), SystemRole::InstructionError,
         QT_TRANSLATE_NOOP("rung::model::Target", "ER: instruction execution error")},
        {QStringLiteral("255.04"), SystemRole::Carry,
         QT_TRANSLATE_NOOP("rung::model::Target", "CY: carry")},
        {QStringLiteral("255.05"), SystemRole::Greater,
         QT_TRANSLATE_NOOP("rung::model::Target", "GR: greater than")},
        {QStringLiteral("255.06"), SystemRole::Equal,
         QT_TRANSLATE_NOOP("rung::model::Target", "EQ: equal")},
        {QStringLiteral("255.07"), SystemRole::Less,
         QT_TRANSLATE_NOOP("rung::model::Target", "LE: less than")},
        {QStringLiteral("254.07"), SystemRole::StepStart,
         QT_TRANSLATE_NOOP("rung::model::Target", "ON for one cycle when a step starts")},
        // The FAL area (W353 FAL(06)): the number of the last non-fatal error, BCD, in
        // 253.00..253.07.
        {QStringLiteral("253"), SystemRole::AlarmNumber,
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "FAL number of a non-fatal error in 253.00..253.07 (BCD)")},
        {QStringLiteral("250"), SystemRole::Other,
         QT_TRANSLATE_NOOP("rung::model::Target", "analog setting 0 (BCD 0..200)")},
        {QStringLiteral("251"), SystemRole::Other,
         QT_TRANSLATE_NOOP("rung::model::Target", "analog setting 1 (BCD 0..200)")},
    };

    for (auto [mnemonic, op, mode, summary] :
         {std::tuple{"LD", Op::Load, ContactMode::Normal,
                     QT_TRANSLATE_NOOP("rung::model::Target",
                                       "Start a block with a normally open contact")},
          {"LD NOT", Op::Load, ContactMode::Negated,
           QT_TRANSLATE_NOOP("rung::model::Target",
                             "Start a block with a normally closed contact")},
          {"AND", Op::And, ContactMode::Normal,
           QT_TRANSLATE_NOOP("rung::model::Target", "Normally open contact in series")},
          {"AND NOT", Op::And, ContactMode::Negated,
           QT_TRANSLATE_NOOP("rung::model::Target", "Normally closed contact in series")},
          {"OR", Op::Or, ContactMode::Normal,
           QT_TRANSLATE_NOOP("rung::model::Target", "Normally open contact in parallel")},
          {"OR NOT", Op::Or, ContactMode::Negated,
           QT_TRANSLATE_NOOP("rung::model::Target", "Normally closed contact in parallel")}}) {
        addSpec(t, mnemonic, op, {{K::BitSource}}, summary, "CCC.BB / TIM n / CNT n").mode = mode;
    }
    addSpec(t, "AND LD", Op::AndBlock, {},
            QT_TRANSLATE_NOOP("rung::model::Target", "Connect the last two blocks in series"));
    addSpec(t, "OR LD", Op::OrBlock, {},
            QT_TRANSLATE_NOOP("rung::model::Target", "Connect the last two blocks in parallel"));
    addSpec(t, "OUT", Op::Out, {{K::BitDest}},
            QT_TRANSLATE_NOOP("rung::model::Target", "Output coil"), "CCC.BB");
    addSpec(t, "OUT NOT", Op::Out, {{K::BitDest}},
            QT_TRANSLATE_NOOP("rung::model::Target", "Inverted output coil"), "CCC.BB")
        .negated = true;
    addSpec(t, "SET", Op::Set, {{K::BitDest}},
            QT_TRANSLATE_NOOP("rung::model::Target", "Set (latch) a bit"), "CCC.BB");
    addSpec(t, "RESET", Op::Reset, {{K::BitDest}},
            QT_TRANSLATE_NOOP("rung::model::Target", "Reset a bit"), "CCC.BB");
    withCode(
        addSpec(t, "KEEP(11)", Op::Keep, {{K::BitDest}},
                QT_TRANSLATE_NOOP("rung::model::Target",
                                  "Keep: set = last but one block, reset = last block; reset wins"),
                "CCC.BB"),
        "KEEP", 11)
        .inputs = 2;
    withCode(addSpec(t, "DIFU(13)", Op::PulseRise, {{K::BitDest}},
                     QT_TRANSLATE_NOOP("rung::model::Target", "ON for one scan on a rising edge"),
                     "CCC.BB"),
             "DIFU", 13);
    withCode(addSpec(t, "DIFD(14)", Op::PulseFall, {{K::BitDest}},
                     QT_TRANSLATE_NOOP("rung::model::Target", "ON for one scan on a falling edge"),
                     "CCC.BB"),
             "DIFD", 14);
    addSpec(t, "TIM", Op::Timer, {{K::TimerNumber}, {K::SetValue}},
            QT_TRANSLATE_NOOP("rung::model::Target",
                              "Timer, 0.1 s, counts down from the BCD set value"),
            "000..127 #0000..#9999");
    withCode(
        addSpec(t, "TIMH(15)", Op::Timer, {{K::TimerNumber}, {K::SetValue}},
                QT_TRANSLATE_NOOP("rung::model::Target",
                                  "High-speed timer, 0.01 s, counts down from the BCD set value"),
                "000..127 #0000..#9999"),
        "TIMH", 15)
        .timerBaseMs = 10.0;
    addSpec(t, "CNT", Op::Counter, {{K::CounterNumber}, {K::SetValue}},
            QT_TRANSLATE_NOOP("rung::model::Target",
                              "Down counter: count = last but one block, reset = last block"),
            "000..127 #0000..#9999")
        .inputs = 2;
    withCode(addSpec(t, "CNTR(12)", Op::UpDownCounter, {{K::CounterNumber}, {K::SetValue}},
                     QT_TRANSLATE_NOOP(
                         "rung::model::Target",
                         "Reversible counter: up, down and reset inputs; wraps at the limits"),
                     "000..127 #0000..#9999"),
             "CNTR", 12)
        .inputs = 3;
    withCode(addSpec(t, "IL(02)", Op::Interlock, {},
                     QT_TRANSLATE_NOOP("rung::model::Target",
                                       "Interlock: what follows runs under this condition")),
             "IL", 2);
    withCode(addSpec(t, "ILC(03)", Op::InterlockClear, {},
                     QT_TRANSLATE_NOOP("rung::model::Target", "Clear the interlock")),
             "ILC", 3);
    withCode(addSpec(t, "JMP(04)", Op::Jump, {{K::Label}},
                     QT_TRANSLATE_NOOP("rung::model::Target",
                                       "Jump: while OFF, skip to the JME with the same number"),
                     "00..49"),
             "JMP", 4);
    withCode(addSpec(t, "JME(05)", Op::JumpEnd, {{K::Label}},
                     QT_TRANSLATE_NOOP("rung::model::Target", "End of the jump with this number"),
                     "00..49"),
             "JME", 5);
    addCpm1ApplicationInstructions(t); // target_cpm1_instructions.cpp
    withCode(addSpec(t, "NOP(00)", Op::Nop, {},
                     QT_TRANSLATE_NOOP("rung::model::Target", "No operation")),
             "NOP", 0);
    withCode(addSpec(t, "END(01)", Op::End, {},
                     QT_TRANSLATE_NOOP("rung::model::Target", "End of the program")),
             "END", 1);

    t.limits.programSteps = 2048;
    t.limits.stackDepth = 8;
    t.limits.contactsPerRow = 10;
    t.limits.maxBlocksInRow = 0; // "AND LD / OR LD: no limit on count" (Omron CPM1 guide)
    t.limits.jumpLabels = 50;
    t.limits.allowsStack = false;
    t.limits.duplicateCoilIsError = true;

    // Omron CPM1 guide: constants are BCD with '#' (without it a number is an address), and so
    // are the set values of TIM / CNT; every timer and counter counts down from its set value.
    t.constants.bcd = true;
    t.constants.bcdSetValues = true;
    t.semantics.downTimersBelow = 1 << 30;
    t.semantics.downCountersBelow = 1 << 30;

    // CPU units by I/O points; inputs from channel 000, outputs from 010 (Omron CPM1 guide). The
    // terminals: the Omron CPM1 guide gives the 20-point unit's 12 inputs / 8 outputs; the 10-
    // and 30-point units (6/4, 18/12) split their points the same way, 12 inputs to a channel
    // (000.00..000.11, then 001.00..) and 8 outputs (010.00..010.07, then 011.00..).
    // The two analog setting pots write 0..200 as BCD into channels 250 and 251 (Omron CPM1
    // guide 3.4); the panel offers them as analog values.
    struct Io {
        const char *name;
        int inChannels, outChannels, inputs, outputs;
    };
    const auto strip = [](ModelVariant &v, int inputs, int outputs) {
        for (int channel = 0; inputs > 0; ++channel, inputs -= 12)
            addTerminals(v, "IN", channel, std::min(12, inputs), 16);
        for (int channel = 10; outputs > 0; ++channel, outputs -= 8)
            addTerminals(v, "OUT", channel, std::min(8, outputs), 16);
        addWordTerminals(v, "SR", 250, 2, 0, 200, true,
                         QT_TRANSLATE_NOOP("rung::model::Target", "analog settings"));
    };
    const Io models[] = {
        {"CPM1-10CDR", 1, 1, 6, 4}, {"CPM1-20CDR", 1, 1, 12, 8}, {"CPM1-30CDR", 2, 2, 18, 12}};
    for (const Io &m : models) {
        ModelVariant v;
        v.name = QString::fromLatin1(m.name);
        v.overrides = {{QStringLiteral("IN"), 0, m.inChannels - 1},
                       {QStringLiteral("OUT"), 10, 10 + m.outChannels - 1}};
        v.programSteps = 2048;
        strip(v, m.inputs, m.outputs);
        t.models.push_back(v);
    }
    // Expansion units add channels the program names; the panel shows the CPU's strip and
    // the further channels the program uses.
    ModelVariant expanded;
    expanded.name = QStringLiteral("CPM1-30CDR+expansion");
    strip(expanded, 18, 12);
    t.models.push_back(expanded);
    t.protocolMaps = cpm1ProtocolMaps();
    t.ports = cpm1Ports();
    // The CPU unit's front (Omron CPM1 guide 2.1, "A CPU egységen található állapotjelző
    // LED-ek értelmezése"; 3.4 the analog settings: "0. Potenciométer: 250 -es csatorna").
    // ERROR/ALARM: "Világít - Lényegi hiba, a CPU leállt"; "Villog - Nem lényegi hiba, a CPU
    // tovább dolgozik": while a FAL(06) number is in 253.00..253.07, and on an error the
    // simulation reports while the program runs on (errorsGoOn: an instruction it skipped, ER
    // 255.03, a result out of range; every error the simulated CPM1 reports is of this kind,
    // none stops it). RUN: "Nem világít - PROGRAM üzemmód, vagy hiba": dark on an error that
    // stopped the CPU. Neither the guide nor W353 gives the blink's rate: 0.5 s on, 0.5 s off
    // is our choice.
    // COMM: "Világít - A PLC kommunikál", "Nem világít - A PLC éppen nem kommunikál": lit while
    // the peripheral port carries bytes (a network station's, docs/network.md). The guide gives
    // no time; the lamp stays lit 0.2 s of simulated time after the last byte (our choice: long
    // enough to be seen after one frame, short enough to go dark between a host's polls a
    // second apart).
    t.panel.errorsGoOn = true;
    t.panel.lamps = {
        {QStringLiteral("POWER"),
         LampColour::Green,
         LampSignal::Power,
         {},
         0,
         QT_TRANSLATE_NOOP("rung::model::Target", "lit while the PLC has power")},
        {QStringLiteral("RUN"),
         LampColour::Green,
         LampSignal::Running,
         {},
         0,
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "lit in RUN or MONITOR mode; dark in PROGRAM mode or on an error")},
        {QStringLiteral("ERROR/ALARM"), LampColour::Red, LampSignal::Alarm, QStringLiteral("253"),
         0,
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "lit on a fatal error: the CPU stopped; blinks on a non-fatal error "
                           "the CPU goes on after (FAL 01..99 in 253.00..253.07, an instruction "
                           "skipped with ER 255.03)"),
         0x00ff, 500},
        {QStringLiteral("COMM"),
         LampColour::Orange,
         LampSignal::Communication,
         {},
         0,
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "lit while the PLC communicates: a byte sent or received on its "
                           "peripheral port within the last 0.2 s"),
         0xffff,
         0,
         200},
    };
    for (int pot = 0; pot < 2; ++pot)
        t.panel.knobs.push_back(
            {QString::number(pot), QString::number(250 + pot), 0, 200, true,
             QT_TRANSLATE_NOOP("rung::model::Target",
                               "analog setting: 0..200 as BCD into its channel")});
    return t;
}

} // namespace rung::model::detail
