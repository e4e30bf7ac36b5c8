#include "model/target/target_data.h"

#include <QCoreApplication>

// PL110 (PL110 manual, Italian). The vendor tool PLProg is graphical only, so the listing is the
// product's own design (docs/targets.md): IEC-style contact mnemonics (LD, LDN, AND, ANDN,
// OR, ORN), ANB / ORB for blocks, and the PLProg element names for everything else (NOT, P, N,
// TON, MUP, FM, ...). Bit devices are numbered from 1, sixteen to a word (I20 is bit 3 of
// word 2); word areas V and SM are numbered from 0 and take a bit as V3.5 / SM0.1.

namespace rung::model::detail {

namespace {

using K = OperandKind;

void addContactFamily(Target &t, const char *mnemonic, const char *negatedMnemonic,
                      const char *negatedAlias, Op op, const char *summary,
                      const char *negatedSummary) {
    addSpec(t, mnemonic, op, {{K::BitSource}}, summary, "I/Q/B/M/T/C, V3.5, SM0.1");
    InstructionSpec &n =
        addSpec(t, negatedMnemonic, op, {{K::BitSource}}, negatedSummary, "I/Q/B/M/T/C");
    n.mode = ContactMode::Negated;
    n.aliases = {QString::fromLatin1(negatedAlias)};
}

// The immediate contacts read the terminals I1..I8 only (4.2.11).
void addImmediate(Target &t, const char *mnemonic, Op op, ContactMode mode, const char *summary) {
    OperandSpec terminal{K::BitSource};
    terminal.area = "I";
    terminal.lowest = 1;
    terminal.highest = 8;
    addSpec(t, mnemonic, op, {terminal}, summary, "I1..I8").mode = mode;
}

void addCompares(Target &t, const char *prefix, Op op) {
    for (const CompareOp cmp : kCompareOps) {
        const char *symbol = compareSymbol(cmp);
        const QByteArray name = QByteArray(prefix) + symbol;
        InstructionSpec &s = addSpec(
            t, "", op, {{K::WordSource}, {K::WordSource}},
            QT_TRANSLATE_NOOP("rung::model::Target", "IF contact: ON while S1 ? S2 is true"),
            "S1 S2");
        s.mnemonic = QString::fromLatin1(name);
        // "LDIF=" names the PLProg element; the short form is canonical.
        s.aliases = {QString::fromLatin1(QByteArray(prefix) + "IF" + symbol)};
        s.compare = cmp;
    }
}

InstructionSpec &addBox(Target &t, const char *mnemonic, ApplyFunction function,
                        std::vector<OperandSpec> operands, const char *summary, const char *help) {
    InstructionSpec &s = addSpec(t, mnemonic, Op::Apply, std::move(operands), summary, help);
    s.function = function;
    return s;
}

} // namespace

Target makePl110Target() {
    Target t;
    t.family = Family::Pl110;
    t.id = QStringLiteral("pl110");
    t.displayName = QStringLiteral("PL110");
    t.defaultTimerBaseMs = 100.0;

    // Bit areas (PL110 manual, sections 2.1.3..2.1.5, 4.2.1..4.2.5 and the Modbus map).
    Area &in = addArea(t, "I", "I", AreaKind::Bit, 1, 256,
                       QT_TRANSLATE_NOOP("rung::model::Target", "digital inputs"));
    in.writable = false;
    in.physical = true;
    addArea(t, "Q", "Q", AreaKind::Bit, 1, 256,
            QT_TRANSLATE_NOOP("rung::model::Target", "digital outputs"))
        .physical = true;
    // A bistable relay changes state only on its own coil (4.2.3).
    addArea(t, "B", "B", AreaKind::Bit, 1, 32,
            QT_TRANSLATE_NOOP("rung::model::Target", "bistable relays"))
        .onlyWrittenBy = ApplyFunction::Toggle;
    addArea(t, "M", "M", AreaKind::Bit, 1, 128,
            QT_TRANSLATE_NOOP("rung::model::Target", "markers"));
    // A word operand may name 16 bits of a bit area from I1, I17, ... (Area::bitsAsWords).
    for (Area &a : t.areas)
        a.bitsAsWords = a.kind == AreaKind::Bit;
    // SM0.13 (2.1.2) trades the counters C1..C16 for the timers T49..T64, "normalmente
    // disabilitati": those run only while it is ON, the counters only while it is OFF.
    addArea(t, "T", "T", AreaKind::Timer, 1, 48,
            QT_TRANSLATE_NOOP("rung::model::Target", "timers"));
    Area &t49 = addArea(t, "T49", "T", AreaKind::Timer, 49, 64,
                        QT_TRANSLATE_NOOP("rung::model::Target", "timers (with SM0.13 ON)"));
    t49.enabledBy = "SM0.13";
    Area &counters = addArea(t, "C", "C", AreaKind::Counter, 1, 16,
                             QT_TRANSLATE_NOOP("rung::model::Target", "counters"));
    counters.enabledBy = "SM0.13";
    counters.enabledWhenOn = false;

    // Word areas. V and SM are retained by the backup battery (2.1.1, 2.1.2).
    Area &v = addArea(t, "V", "V", AreaKind::Word, 0, 349,
                      QT_TRANSLATE_NOOP("rung::model::Target", "variables"));
    v.numbering = Numbering::ChannelBit;
    v.retentive = true;
    v.prefixAliases = {QStringLiteral("VW")}; // the PL110 manual writes word access as VW30, SMW4

    // SM0..SM185: the table of 2.1.2 runs to the display parameters SM176..SM185; the
    // user-page program of 5.4 sets SMW103.0 and SMW103.1.
    Area &sm = addArea(t, "SM", "SM", AreaKind::Word, 0, 185,
                       QT_TRANSLATE_NOOP("rung::model::Target", "special markers"));
    sm.numbering = Numbering::ChannelBit;
    sm.prefixAliases = {QStringLiteral("SMW")};
    sm.retentive = true;
    sm.system = true;
    // Double words (2.1.1): VD n is V n (high word) and V n+1 (low word), so consecutive
    // double words are VD0, VD2, ...; SMD20 is the encoder count SM20 (high) : SM21 (low).
    Area &vd = addArea(t, "VD", "VD", AreaKind::Word, 0, 348,
                       QT_TRANSLATE_NOOP("rung::model::Target", "variables, double words"));
    vd.doubleWordsOf = "V";
    vd.wordBits = 32;
    vd.retentive = true;
    Area &smd = addArea(t, "SMD", "SMD", AreaKind::Word, 0, 184,
                        QT_TRANSLATE_NOOP("rung::model::Target", "special markers, double words"));
    smd.doubleWordsOf = "SM";
    smd.wordBits = 32;
    smd.retentive = true;
    smd.system = true;
    Area &ai = addArea(t, "AI", "AI", AreaKind::Word, 1, 4,
                       QT_TRANSLATE_NOOP("rung::model::Target", "analog inputs"));
    ai.writable = false;
    ai.physical = true;
    // The trimmers TR: a source of presets (4.2.4, 4.2.5), scaled by RANGE like the analog
    // inputs (4.2.16), an area of its own in SM107's list. The manual gives no count: four,
    // as AI1..AI4, is the product's choice.
    Area &tr = addArea(t, "TR", "TR", AreaKind::Word, 1, 4,
                       QT_TRANSLATE_NOOP("rung::model::Target", "trimmers"));
    tr.writable = false;
    tr.physical = true;
    addArea(t, "AQ", "AQ", AreaKind::Word, 1, 2,
            QT_TRANSLATE_NOOP("rung::model::Target", "analog outputs"))
        .physical = true;
    // The presets in force (2.1.9, 2.1.11): reading PT1 gives T1's preset, writing it
    // changes it; a constant preset is loaded there when the program starts.
    addArea(t, "PT", "PT", AreaKind::Word, 1, 48,
            QT_TRANSLATE_NOOP("rung::model::Target", "timer presets"))
        .presetsOf = "T";
    addArea(t, "PT49", "PT", AreaKind::Word, 49, 64,
            QT_TRANSLATE_NOOP("rung::model::Target", "timer presets"))
        .presetsOf = "T49";
    addArea(t, "PV", "PV", AreaKind::Word, 1, 16,
            QT_TRANSLATE_NOOP("rung::model::Target", "counter presets"))
        .presetsOf = "C";
    addArea(t, "EEP", "EEP", AreaKind::Word, 0, 999,
            QT_TRANSLATE_NOOP("rung::model::Target", "EEPROM words"))
        .retentive = true;
    addArea(t, "MMC", "MMC", AreaKind::Word, 0, 12999,
            QT_TRANSLATE_NOOP("rung::model::Target", "MMC words"))
        .retentive = true;
    Area &disp = addArea(t, "DISP", "DISP", AreaKind::Word, 0, 167,
                         QT_TRANSLATE_NOOP("rung::model::Target", "display characters"));
    disp.wordBits = 8;        // one character per byte, 8 rows x 21 (2.1.16)
    addPl110SerialBuffers(t); // COM1_TX, COM1_RX, ... (target_pl110_comm.cpp)

    // SM0 bits and the scan-time words SM6..SM8 (section 2.1.2).
    t.systemDevices = {
        {QStringLiteral("SM0.0"), SystemRole::Run,
         QT_TRANSLATE_NOOP("rung::model::Target", "RUN/STOP (1 = RUN)")},
        {QStringLiteral("SM0.1"), SystemRole::FirstScan,
         QT_TRANSLATE_NOOP("rung::model::Target", "ON for the first scan")},
        {QStringLiteral("SM0.2"), SystemRole::Clock1min,
         QT_TRANSLATE_NOOP("rung::model::Target", "60 s clock (30 s ON, 30 s OFF)")},
        {QStringLiteral("SM0.3"), SystemRole::Clock1s,
         QT_TRANSLATE_NOOP("rung::model::Target", "1 s clock (0.5 s ON, 0.5 s OFF)")},
        {QStringLiteral("SM0.4"), SystemRole::ScanToggle,
         QT_TRANSLATE_NOOP("rung::model::Target", "toggles every scan")},
        // TEST (2.1.2): the program sets SM0.5 and SM37 (R/W); I1..I8 then read SM37.0..7.
        {QStringLiteral("SM0.5"), SystemRole::InputTest,
         QT_TRANSLATE_NOOP("rung::model::Target", "TEST: inputs are taken from SM37"), 0, true},
        {QStringLiteral("SM37"), SystemRole::InputTestImage,
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "inputs I1..I8 in TEST mode (bit 0 = I1), cleared at power-on"),
         0, true, 8},
        {QStringLiteral("SM0.13"), SystemRole::Other,
         QT_TRANSLATE_NOOP("rung::model::Target", "counters C1..C16 off, timers T49..T64 on")},
        {QStringLiteral("SM6"), SystemRole::ScanTimeCurrent,
         QT_TRANSLATE_NOOP("rung::model::Target", "last scan time (0.1 ms)"), 100},
        {QStringLiteral("SM7"), SystemRole::ScanTimeMin,
         QT_TRANSLATE_NOOP("rung::model::Target", "minimum scan time (0.1 ms)"), 100},
        {QStringLiteral("SM8"), SystemRole::ScanTimeMax,
         QT_TRANSLATE_NOOP("rung::model::Target", "maximum scan time (0.1 ms)"), 100},
    };

    // What the simulator keeps as plain memory (2.1.2): the hardware behind the special
    // markers (encoders, stepper output, clock, protocol address, filters and analog
    // configuration, the protocols' line settings and COM2's slave markers) and the timed
    // interrupts (the display and its terminal are simulated: target_pl110_panel.cpp). `check`
    // warns at each use (SIM101). SM1 (faults) reads 0, no fault, as it should in a simulation;
    // SM3, SM19 and SM111..SM117 are not in the manual's table. The ports' markers of COM / EXP and
    // free-port (SM0.6..SM0.8, SM70, SM73..SM80, SM83..SM89, SM98, SM99) are simulated
    // (PortMarkers); of a slave port, SM70 / SM80 (the link supervision) too.
    t.unmodelled = {
        {QStringLiteral("SM2"), QStringLiteral("SM2"),
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "the encoders' load bits and the stepper motor output on AQ1 are not "
                           "modelled; the word is plain memory")},
        {QStringLiteral("SM4"), QStringLiteral("SM5"),
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "the protocol address (the offset and the rotary switch) is not "
                           "modelled; the word is plain memory")},
        {QStringLiteral("SM9"), QStringLiteral("SM15"),
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "the real-time clock is not modelled: the word keeps what the program "
                           "writes and does not count")},
        {QStringLiteral("SM16"), QStringLiteral("SM18"),
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "the timed interrupts and the stepper ramp are not modelled "
                           "(interrupt programs are not supported)")},
        {QStringLiteral("SM20"), QStringLiteral("SM31"),
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "the encoders are not modelled: no count, no load, no rate; the word "
                           "is plain memory")},
        {QStringLiteral("SM38"), QStringLiteral("SM69"),
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "the input filters and analog settings are not modelled: an analog "
                           "input reads the value set in the simulator")},
        // 4.2.19 switches free-port with SM32..SM34 and counts what came in SM35..SM37; the
        // table of 2.1.2 has SM78 / SM88 / SM98 and SM79 / SM89 / SM99 for that, SM37 for the
        // TEST inputs and no SM32..SM36. The table is the more detailed: the simulator follows
        // it (docs/targets.md), and a program that uses SM32..SM36 is told so.
        {QStringLiteral("SM32"), QStringLiteral("SM36"),
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "not in the manual's table of special markers: 4.2.19 names SM32..SM34 "
                           "for free-port and SM35..SM37 for the characters received, the table "
                           "(2.1.2) has SM78 / SM88 / SM98 and SM79 / SM89 / SM99, which the "
                           "simulator follows; the word is plain memory")},
        {QStringLiteral("SM71"), QStringLiteral("SM72"),
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "the protocol's baud rate and format come from the port's settings "
                           "(project or network file), not from the program; the word is plain "
                           "memory")},
        {QStringLiteral("SM81"), QStringLiteral("SM82"),
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "the protocol's baud rate and format come from the port's settings "
                           "(project or network file), not from the program; the word is plain "
                           "memory")},
        {QStringLiteral("SM90"), QStringLiteral("SM97"),
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "COM2 runs the MODBUS slave only: its status, reply delay, supervision "
                           "time and counters are not modelled; the word is plain memory")},
    };

    // Contacts. The plain spellings come first: Target::findInstruction(op, mode) returns the
    // first match, and that is what the converter writes.
    addContactFamily(
        t, "LD", "LDN", "LD NOT", Op::Load,
        QT_TRANSLATE_NOOP("rung::model::Target", "Start a block with a normally open contact"),
        QT_TRANSLATE_NOOP("rung::model::Target", "Start a block with a normally closed contact"));
    addContactFamily(t, "AND", "ANDN", "AND NOT", Op::And,
                     QT_TRANSLATE_NOOP("rung::model::Target", "Normally open contact in series"),
                     QT_TRANSLATE_NOOP("rung::model::Target", "Normally closed contact in series"));
    addContactFamily(
        t, "OR", "ORN", "OR NOT", Op::Or,
        QT_TRANSLATE_NOOP("rung::model::Target", "Normally open contact in parallel"),
        QT_TRANSLATE_NOOP("rung::model::Target", "Normally closed contact in parallel"));
    addCompares(t, "LD", Op::Load);
    addCompares(t, "AND", Op::And);
    addCompares(t, "OR", Op::Or);
    addSpec(t, "ANB", Op::AndBlock, {},
            QT_TRANSLATE_NOOP("rung::model::Target", "Connect the last two blocks in series"));
    addSpec(t, "ORB", Op::OrBlock, {},
            QT_TRANSLATE_NOOP("rung::model::Target", "Connect the last two blocks in parallel"));
    addSpec(t, "NOT", Op::Invert, {},
            QT_TRANSLATE_NOOP("rung::model::Target", "NOT contact: invert the power flow"));
    // P / N act on the power flow, not on a device: an operand-less element like NOT, told
    // apart by its mode.
    addSpec(t, "P", Op::Invert, {},
            QT_TRANSLATE_NOOP("rung::model::Target",
                              "P contact: power flows for one scan when it turns ON"))
        .mode = ContactMode::Rising;
    addSpec(t, "N", Op::Invert, {},
            QT_TRANSLATE_NOOP("rung::model::Target",
                              "N contact: power flows for one scan when it turns OFF"))
        .mode = ContactMode::Falling;
    // Immediate input contacts (II, 4.2.11): read the terminal, not the input image.
    addImmediate(
        t, "LDII", Op::Load, ContactMode::Normal,
        QT_TRANSLATE_NOOP("rung::model::Target", "Start a block with an immediate input contact"));
    addImmediate(t, "LDNII", Op::Load, ContactMode::Negated,
                 QT_TRANSLATE_NOOP("rung::model::Target",
                                   "Start a block with a normally closed immediate input contact"));
    addImmediate(t, "ANDII", Op::And, ContactMode::Normal,
                 QT_TRANSLATE_NOOP("rung::model::Target", "Immediate input contact in series"));
    addImmediate(t, "ANDNII", Op::And, ContactMode::Negated,
                 QT_TRANSLATE_NOOP("rung::model::Target",
                                   "Normally closed immediate input contact in series"));
    addImmediate(t, "ORII", Op::Or, ContactMode::Normal,
                 QT_TRANSLATE_NOOP("rung::model::Target", "Immediate input contact in parallel"));
    addImmediate(t, "ORNII", Op::Or, ContactMode::Negated,
                 QT_TRANSLATE_NOOP("rung::model::Target",
                                   "Normally closed immediate input contact in parallel"));

    // Coils.
    addSpec(t, "OUT", Op::Out, {{K::BitDest}},
            QT_TRANSLATE_NOOP("rung::model::Target", "Output coil"), "Q/M");
    // QI writes the terminals Q1..Q8 only (4.2.12).
    OperandSpec terminal{K::BitDest};
    terminal.area = "Q";
    terminal.lowest = 1;
    terminal.highest = 8;
    addSpec(t, "OUTQI", Op::Out, {terminal},
            QT_TRANSLATE_NOOP("rung::model::Target",
                              "Immediate output coil: writes the terminal at once"),
            "Q1..Q8")
        .aliases = {QStringLiteral("QI")};
    addBox(t, "OUTB", ApplyFunction::Toggle, {{K::BitDest}},
           QT_TRANSLATE_NOOP("rung::model::Target",
                             "Bistable relay coil: each activation toggles the relay"),
           "B1..B32")
        .steps = 1;
    // SBIT / RBIT name a bit 0..15 of a word (4.2.14).
    OperandSpec bitNumber{K::Constant, true};
    bitNumber.lowest = 0;
    bitNumber.highest = 15;
    bitNumber.name = QT_TRANSLATE_NOOP("rung::model::Target", "bit number");
    // A word's bit 0..15: no double words (OperandSpec::wholeWords).
    OperandSpec bitWord{K::WordDest};
    bitWord.wholeWords = true;
    addBox(t, "SBIT", ApplyFunction::SetBit, {bitWord, bitNumber},
           QT_TRANSLATE_NOOP("rung::model::Target", "Set a bit (0..15) of a word to 1"),
           "V3 5 | V3.5 | Q1");
    addBox(t, "RBIT", ApplyFunction::ResetBit, {bitWord, bitNumber},
           QT_TRANSLATE_NOOP("rung::model::Target", "Reset a bit (0..15) of a word to 0"),
           "V3 5 | V3.5 | Q1");

    // Timers: T, preset (constant or VW/SMW/AI/TR), optional time base in ms (10, 100, 1000).
    // "base tempi di 10 ms, 100ms e 1s" (4.2.4): no other time base exists.
    const char *timerHelp = "T1..T64 PT [10|100|1000]";
    OperandSpec preset{K::SetValue};
    preset.sourceAreas = {"V", "SM", "AI", "TR"};
    preset.name = QT_TRANSLATE_NOOP("rung::model::Target", "preset");
    OperandSpec timeBase{K::Constant, true};
    timeBase.allowedValues = {10, 100, 1000};
    timeBase.name = QT_TRANSLATE_NOOP("rung::model::Target", "time base (ms)");
    addSpec(t, "TON", Op::Timer, {{K::TimerNumber}, preset, timeBase},
            QT_TRANSLATE_NOOP("rung::model::Target",
                              "On-delay timer: T ON once the time reaches PT; OFF resets"),
            timerHelp);
    addSpec(t, "TOFF", Op::Timer, {{K::TimerNumber}, preset, timeBase},
            QT_TRANSLATE_NOOP("rung::model::Target",
                              "Off-delay timer: T ON at once, OFF when PT has elapsed after OFF"),
            timerHelp)
        .timerMode = TimerMode::OffDelay;
    InstructionSpec &tonr =
        addSpec(t, "TONR", Op::Timer, {{K::TimerNumber}, preset, timeBase},
                QT_TRANSLATE_NOOP("rung::model::Target",
                                  "Accumulating on-delay timer: keeps its time while OFF"),
                timerHelp);
    tonr.timerMode = TimerMode::Accumulating;

    // Counters: UP = first block, DOWN = second, RESET = last (4.2.5).
    InstructionSpec &mup = addSpec(
        t, "MUP", Op::UpDownCounter, {{K::CounterNumber}, preset},
        QT_TRANSLATE_NOOP("rung::model::Target",
                          "Up counter: UP, DOWN and RESET inputs; C ON while the count >= PV"),
        "C1..C16 PV");
    mup.inputs = 3;
    InstructionSpec &mdown = addSpec(
        t, "MDOWN", Op::UpDownCounter, {{K::CounterNumber}, preset},
        QT_TRANSLATE_NOOP("rung::model::Target",
                          "Down counter from PV: UP, DOWN and RESET (load PV) inputs; C ON at 0"),
        "C1..C16 PV");
    mdown.inputs = 3;
    mdown.counterMode = CounterMode::Down;

    // Functions.
    const OperandSpec src{K::WordSource};
    const OperandSpec dst{K::WordDest};
    // "operazioni matematiche (+, -, *, /, |, & *, <<, >>)" (4.2.6; the OCR's "& *" is & ^,
    // PLProg's XOR): no other operator.
    OperandSpec mathOperator{K::Constant};
    mathOperator.allowedTexts = {"+", "-", "*", "/", "|", "&", "^", "<<", ">>"};
    mathOperator.name = QT_TRANSLATE_NOOP("rung::model::Target", "operator");
    addBox(t, "FM", ApplyFunction::Math, {src, mathOperator, src, dst},
           QT_TRANSLATE_NOOP("rung::model::Target",
                             "Math formula: D = S1 op S2, op one of + - * / | & ^ << >>"),
           "S1 OP S2 D");
    addBox(t, "MOV", ApplyFunction::Mov, {src, dst},
           QT_TRANSLATE_NOOP("rung::model::Target", "Move a value or a word to D"), "S D");
    OperandSpec blockSrc = src;
    blockSrc.wholeWords = true;
    OperandSpec blockDst = dst;
    blockDst.wholeWords = true;
    // "al blocco di memoria, a partire dalla locazione di memoria specificata" (4.2.8): n
    // words from S and from D, each block inside the memory, n at least 1.
    blockSrc.countFrom = 2;
    blockDst.countFrom = 2;
    OperandSpec blockCount{K::Count};
    blockCount.lowest = 1;
    blockCount.name = QT_TRANSLATE_NOOP("rung::model::Target", "number of words");
    addBox(t, "BLKMOV", ApplyFunction::BlockMove, {blockSrc, blockDst, blockCount},
           QT_TRANSLATE_NOOP("rung::model::Target", "Move n words from S (or the value S) to D"),
           "S D n");
    addBox(t, "MOVIND", ApplyFunction::IndirectMove, {src, blockDst, src},
           QT_TRANSLATE_NOOP("rung::model::Target",
                             "Indexed move: D[index] = S, the area used as a vector"),
           "S D INDEX");
    // SEND, COM and EXP (4.2.19, 4.2.21): target_pl110_comm.cpp.
    addPl110Communication(t);
    // MOVTXT D n "TEXT" (4.2.10): the characters of the text from D, one a word
    // (UN_CARATTERE_PER_WORD, n = 1) or two, "iniziando dalla parte alta della word"
    // (DUE_CARATTERI_PER_WORD, n = 2); 2.1.16 writes a display row with it: MOVTXT (DISP42,
    // 1 Char per word) "TESTO DISPLAY". The listing's order is PLProg's box: D, n, the text.
    OperandSpec textDest = dst;
    textDest.wholeWords = true;
    OperandSpec perWord{K::Constant};
    perWord.allowedValues = {1, 2};
    perWord.name = QT_TRANSLATE_NOOP("rung::model::Target", "characters per word");
    OperandSpec text{K::Text};
    text.storedFrom = 0;
    text.charactersPerWord = 1;
    text.name = QT_TRANSLATE_NOOP("rung::model::Target", "text");
    addBox(t, "MOVTXT", ApplyFunction::MoveText, {textDest, perWord, text},
           QT_TRANSLATE_NOOP("rung::model::Target",
                             "Store a text from D: 1 or 2 characters per word, high byte first"),
           "D 1|2 \"TEXT\"");
    // Known to the editor, not simulated (scaling, positioning, PID).
    const OperandSpec any{K::Constant, true};
    const std::pair<const char *, const char *> boxes[] = {
        {"RANGE",
         QT_TRANSLATE_NOOP("rung::model::Target", "Set the range of an AI, TR, AQ or PID output")},
        {"TunePOS", QT_TRANSLATE_NOOP("rung::model::Target", "Tune an on/off positioner")},
        {"POS", QT_TRANSLATE_NOOP("rung::model::Target", "On/off positioner")},
        {"StartPID", QT_TRANSLATE_NOOP("rung::model::Target", "Start a PID loop")},
        {"PID", QT_TRANSLATE_NOOP("rung::model::Target", "PID control loop")},
        {"SetOutPID", QT_TRANSLATE_NOOP("rung::model::Target", "Set the output of a PID loop")},
        {"GENSET",
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "Setpoint generator with acceleration and deceleration ramps")},
        {"CONV", QT_TRANSLATE_NOOP("rung::model::Target", "Convert a value")},
    };
    for (const auto &[name, summary] : boxes)
        addBox(t, name, ApplyFunction::NotSimulated, {any, any, any, any, any, any}, summary,
               "...");
    // SetPAR, FormatPAR, PosPAR (4.2.26..4.2.28): one of the four numeric fields of the
    // PL110-2A's user pages, its parameters in the manual's order, written into the field's
    // words of 2.1.2 (from SM118, 17 a field) each scan the coil is on. The state, the type,
    // the fill and the access are the numbers those words hold (0 disabled, 1 shown, 2
    // editable; 0 16 bit signed, 1 16 bit unsigned, 2 32 bit signed; 0 spaces, 1 zeros; 0 free,
    // 1 after the user password) *(choice: PLProg's boxes show them as words, the listing is
    // the product's)*. The variable and a variable limit are of the areas of SM107's list.
    const auto ranged = [](int lowest, int highest, const char *name) {
        OperandSpec o{K::Constant};
        o.lowest = lowest;
        o.highest = highest;
        o.name = name;
        return o;
    };
    const auto oneOf = [](std::vector<int> values, const char *name) {
        OperandSpec o{K::Constant};
        o.allowedValues = std::move(values);
        o.name = name;
        return o;
    };
    const OperandSpec field =
        ranged(1, 4, QT_TRANSLATE_NOOP("rung::model::Target", "display field"));
    const std::vector<const char *> listed = {"V",  "SM", "VD", "SMD", "AI",  "TR",  "AQ",
                                              "PT", "PV", "T",  "C",   "EEP", "MMC", "DISP"};
    OperandSpec variable{K::WordSource};
    variable.deviceOnly = true;
    variable.sourceAreas = listed;
    variable.name = QT_TRANSLATE_NOOP("rung::model::Target", "variable shown");
    OperandSpec lowest{K::WordSource};
    lowest.sourceAreas = listed;
    lowest.name = QT_TRANSLATE_NOOP("rung::model::Target", "minimum");
    OperandSpec highest = lowest;
    highest.name = QT_TRANSLATE_NOOP("rung::model::Target", "maximum");
    addBox(t, "SetPAR", ApplyFunction::PanelFieldSet,
           {field,
            oneOf({0, 1, 2}, QT_TRANSLATE_NOOP("rung::model::Target",
                                               "state (0 disabled, 1 shown, 2 editable)")),
            variable, lowest, highest},
           QT_TRANSLATE_NOOP("rung::model::Target",
                             "Set a display field: its state, variable and limits"),
           "N STATE VAR MIN MAX");
    addBox(t, "FormatPAR", ApplyFunction::PanelFieldFormat,
           {field,
            oneOf({0, 1, 2},
                  QT_TRANSLATE_NOOP("rung::model::Target", "type (0 16 bit signed, 1 16 "
                                                           "bit unsigned, 2 32 bit signed)")),
            ranged(1, 12, QT_TRANSLATE_NOOP("rung::model::Target", "total digits")),
            ranged(0, 10, QT_TRANSLATE_NOOP("rung::model::Target", "decimals")),
            oneOf({0, 1}, QT_TRANSLATE_NOOP("rung::model::Target", "fill (0 spaces, 1 zeros)"))},
           QT_TRANSLATE_NOOP("rung::model::Target",
                             "Format a display field: type, digits, decimals, fill"),
           "N TYPE DIGITS DECIMALS FILL");
    addBox(
        t, "PosPAR", ApplyFunction::PanelFieldPosition,
        {field, ranged(1, 8, QT_TRANSLATE_NOOP("rung::model::Target", "row")),
         ranged(1, 22, QT_TRANSLATE_NOOP("rung::model::Target", "column")),
         oneOf({0, 1}, QT_TRANSLATE_NOOP("rung::model::Target", "access (0 free, 1 password)"))},
        QT_TRANSLATE_NOOP("rung::model::Target", "Place a display field: row, column and access"),
        "N ROW COLUMN ACCESS");
    addSpec(t, "END", Op::End, {}, QT_TRANSLATE_NOOP("rung::model::Target", "End of the program"));

    // The PL110 manual gives no program size; 4096 elements is the product's choice
    // (docs/targets.md).
    t.limits.programSteps = 4096;
    t.limits.stackDepth = 8;
    t.limits.contactsPerRow = 10;
    t.limits.maxBlocksInRow = 0;
    t.limits.jumpLabels = 0;
    t.limits.allowsStack = false;
    t.limits.duplicateCoilIsError = true;
    t.limits.outputNeedsCondition = false; // PLProg coils may hang on the left rail
    t.limits.timerMax = 32767;             // PL110 manual 4.2.4
    t.limits.counterMin = -32768;          // PL110 manual 4.2.5: the C word saturates
    t.limits.counterMax = 32767;

    // The listing is the product's design: plain numbers, '#' accepted before them as PLProg
    // writes "MOV(Tx = #0)"; FM operators and time bases are words in constant slots.
    t.constants.plain = true;
    t.constants.hashPlain = true;
    t.constants.wordsInConstantSlots = true;
    t.semantics.timerCountsInWord = true;
    t.semantics.upDownCountersSaturate = true; // MUP / MDOWN, PL110 manual 4.2.5

    // Same I/O on both; only PL110-2A has the OLED terminal and its DISP area (1.2, 2.1.16).
    t.models = {
        ModelVariant{QStringLiteral("PL110-1A"), {{QStringLiteral("DISP"), 0, -1}}, 0, {}},
        ModelVariant{QStringLiteral("PL110-2A"), {}, 0, {}},
    };
    // The terminals (1.1, 1.3): 8 digital inputs I.1..I.8, 8 relay outputs, 4 analog inputs
    // of 10 bits (0..1023) and the analog output AQ.1 (8 bits: 0..255 after RANGE scales it;
    // the panel shows its word).
    for (ModelVariant &v : t.models) {
        addTerminals(v, "I", 1, 8);
        addTerminals(v, "Q", 1, 8);
        addWordTerminals(v, "AI", 1, 4, 0, 1023);
        addWordTerminals(v, "AQ", 1, 1, -32768, 32767);
    }
    t.protocolMaps = pl110ProtocolMaps();
    t.ports = pl110Ports();
    addPl110Panel(t);
    return t;
}

} // namespace rung::model::detail
