#include "model/target/target_data.h"

#include <QCoreApplication>

// VPC (VPC user's manual): two-digit decimal operands, compares and transfers written infix
// ("LD p01<p00", "OUT p21,p12"), timers and counters with the element number fused into the
// mnemonic ("TIM00"). The infix forms share their mnemonic with the plain instruction; the
// plain one comes first so a lookup by spelling finds it.

namespace rung::model::detail {

namespace {

using K = OperandKind;

void addContacts(Target &t, const char *mnemonic, const char *negatedMnemonic, Op op,
                 const char *summary, const char *negatedSummary) {
    addSpec(t, mnemonic, op, {{K::BitSource}}, summary, "i/o/r/t/c");
    InstructionSpec &n =
        addSpec(t, negatedMnemonic, op, {{K::BitSource}}, negatedSummary, "i/o/r/t/c");
    n.mode = ContactMode::Negated;
    n.aliases = {QString::fromLatin1(mnemonic) + QLatin1Char('*')};
}

void addCompares(Target &t, const char *mnemonic, const char *negatedMnemonic, Op op) {
    for (CompareOp cmp : {CompareOp::Eq, CompareOp::Lt, CompareOp::Gt}) {
        for (bool negated : {false, true}) {
            InstructionSpec &s = addSpec(
                t, negated ? negatedMnemonic : mnemonic, op, {{K::WordSource}, {K::WordSource}},
                QT_TRANSLATE_NOOP("rung::model::Target",
                                  "Compare contact between two decimal operands"),
                "p01<p00");
            s.compare = cmp;
            if (negated) {
                s.mode = ContactMode::Negated;
                s.aliases = {QString::fromLatin1(mnemonic) + QLatin1Char('*')};
            }
        }
    }
}

} // namespace

Target makeVpcTarget() {
    Target t;
    t.family = Family::Vpc;
    t.id = QStringLiteral("vpc");
    t.displayName = QStringLiteral("VPC");
    t.defaultTimerBaseMs = 10.0;

    Area &i = addArea(t, "i", "i", AreaKind::Bit, 0, 39,
                      QT_TRANSLATE_NOOP("rung::model::Target", "inputs"));
    i.digits = 2;
    i.writable = false;
    i.physical = true;
    Area &o = addArea(t, "o", "o", AreaKind::Bit, 0, 29,
                      QT_TRANSLATE_NOOP("rung::model::Target", "outputs"));
    o.digits = 2;
    o.physical = true;
    Area &tm = addArea(t, "t", "t", AreaKind::Timer, 0, 31,
                       QT_TRANSLATE_NOOP("rung::model::Target", "timers"));
    tm.digits = 2;
    tm.bank = 0;
    tm.retentive = true;
    Area &c = addArea(t, "c", "c", AreaKind::Counter, 0, 31,
                      QT_TRANSLATE_NOOP("rung::model::Target", "counters"));
    c.digits = 2;
    c.bank = 0;
    c.retentive = true;
    addArea(t, "r", "r", AreaKind::Bit, 0, 71,
            QT_TRANSLATE_NOOP("rung::model::Target", "auxiliary relays"))
        .digits = 2;
    Area &rl = addArea(t, "rl", "r", AreaKind::Bit, 72, 87,
                       QT_TRANSLATE_NOOP("rung::model::Target", "retentive auxiliary relays"));
    rl.digits = 2;
    rl.retentive = true;
    // The VPC user's manual (III) lists r88..r95 as system registers, yet lets OUT/LR drive
    // r00..r89: the program may drop r88 (RUN) to stop and raise r89 (ERR) to signal an alarm.
    // r90..r95 are read-only.
    Area &rsw = addArea(t, "rsw", "r", AreaKind::Bit, 88, 89,
                        QT_TRANSLATE_NOOP("rung::model::Target", "system relays"));
    rsw.digits = 2;
    rsw.system = true;
    Area &rs = addArea(t, "rs", "r", AreaKind::Bit, 90, 95,
                       QT_TRANSLATE_NOOP("rung::model::Target", "system relays"));
    rs.digits = 2;
    rs.system = true;
    rs.writable = false;
    Area &a = addArea(t, "a", "a", AreaKind::Word, 0, 7,
                      QT_TRANSLATE_NOOP("rung::model::Target", "analog inputs"));
    a.digits = 2;
    a.writable = false;
    a.physical = true;
    Area &d = addArea(t, "d", "d", AreaKind::Word, 0, 3,
                      QT_TRANSLATE_NOOP("rung::model::Target", "analog outputs"));
    d.digits = 2;
    d.physical = true;
    Area &p = addArea(t, "p", "p", AreaKind::Word, 0, 75,
                      QT_TRANSLATE_NOOP("rung::model::Target", "registers"));
    p.digits = 2;
    p.retentive = true;
    addArea(t, "p76", "p", AreaKind::Word, 76, 76,
            QT_TRANSLATE_NOOP("rung::model::Target", "parallel output (o00..o11)"))
        .digits = 2;
    Area &p77 = addArea(t, "p77", "p", AreaKind::Word, 77, 77,
                        QT_TRANSLATE_NOOP("rung::model::Target", "parallel input (i00..i11)"));
    p77.digits = 2;
    p77.writable = false;

    t.systemDevices = {
        {QStringLiteral("r88"), SystemRole::AlwaysOn,
         QT_TRANSLATE_NOOP("rung::model::Target", "RUN: always ON"), 0, true},
        {QStringLiteral("r89"), SystemRole::Error,
         QT_TRANSLATE_NOOP("rung::model::Target", "ERR: program error"), 0, true},
        {QStringLiteral("r90"), SystemRole::Connected,
         QT_TRANSLATE_NOOP("rung::model::Target", "CON: PC connected")},
        {QStringLiteral("r91"), SystemRole::Other,
         QT_TRANSLATE_NOOP("rung::model::Target", "VPCIO connected")},
        {QStringLiteral("r92"), SystemRole::ScanToggle,
         QT_TRANSLATE_NOOP("rung::model::Target", "toggles every scan")},
        {QStringLiteral("r93"), SystemRole::Clock10ms,
         QT_TRANSLATE_NOOP("rung::model::Target", "0.01 s clock")},
        {QStringLiteral("r94"), SystemRole::Clock100ms,
         QT_TRANSLATE_NOOP("rung::model::Target", "0.1 s clock")},
        {QStringLiteral("r95"), SystemRole::Clock1s,
         QT_TRANSLATE_NOOP("rung::model::Target", "1 s clock")},
    };

    addContacts(
        t, "LD", "LD NOT", Op::Load,
        QT_TRANSLATE_NOOP("rung::model::Target", "Start a block with a normally open contact"),
        QT_TRANSLATE_NOOP("rung::model::Target", "Start a block with a normally closed contact"));
    addContacts(t, "AND", "AND NOT", Op::And,
                QT_TRANSLATE_NOOP("rung::model::Target", "Normally open contact in series"),
                QT_TRANSLATE_NOOP("rung::model::Target", "Normally closed contact in series"));
    addContacts(t, "OR", "OR NOT", Op::Or,
                QT_TRANSLATE_NOOP("rung::model::Target", "Normally open contact in parallel"),
                QT_TRANSLATE_NOOP("rung::model::Target", "Normally closed contact in parallel"));
    addSpec(t, "AND LD", Op::AndBlock, {},
            QT_TRANSLATE_NOOP("rung::model::Target", "Connect the last two blocks in series"));
    addSpec(t, "OR LD", Op::OrBlock, {},
            QT_TRANSLATE_NOOP("rung::model::Target", "Connect the last two blocks in parallel"));
    addSpec(t, "OUT", Op::Out, {{K::BitDest}},
            QT_TRANSLATE_NOOP("rung::model::Target", "Output coil"), "o/r");
    InstructionSpec &outNot =
        addSpec(t, "OUT NOT", Op::Out, {{K::BitDest}},
                QT_TRANSLATE_NOOP("rung::model::Target", "Inverted output coil"), "o/r");
    outNot.negated = true;
    outNot.aliases = {QStringLiteral("OUT*")};
    addCompares(t, "LD", "LD NOT", Op::Load);
    addCompares(t, "AND", "AND NOT", Op::And);
    addCompares(t, "OR", "OR NOT", Op::Or);
    for (bool negated : {false, true}) {
        for (TransferOp op : {TransferOp::Assign, TransferOp::Add, TransferOp::Subtract}) {
            InstructionSpec &s = addSpec(
                t, negated ? "OUT NOT" : "OUT", Op::Transfer, {{K::WordDest}, {K::WordSource}},
                negated ? QT_TRANSLATE_NOOP("rung::model::Target",
                                            "Transfer while the condition is OFF: d,s  d+s  d-s")
                        : QT_TRANSLATE_NOOP("rung::model::Target",
                                            "Transfer while the condition is ON: d,s  d+s  d-s"),
                "p21,p12");
            s.transfer = op;
            s.negated = negated;
            if (negated)
                s.aliases = {QStringLiteral("OUT*")};
        }
    }
    InstructionSpec &lr =
        addSpec(t, "LR", Op::Keep, {{K::BitDest}},
                QT_TRANSLATE_NOOP("rung::model::Target",
                                  "Latching relay: set = last but one block, reset = last block"),
                "o/r");
    lr.inputs = 2;
    InstructionSpec &tim =
        addSpec(t, "TIM", Op::Timer, {{K::TimerNumber}},
                QT_TRANSLATE_NOOP("rung::model::Target",
                                  "Timer: 00..15 count down, 16..31 count up, 0.01 s"),
                "TIM00..TIM31");
    tim.fusedOperand = true;
    InstructionSpec &cnt =
        addSpec(t, "CNT", Op::Counter, {{K::CounterNumber}},
                QT_TRANSLATE_NOOP("rung::model::Target",
                                  "Counter: count = last but one block, reset = last block"),
                "CNT00..CNT31");
    cnt.fusedOperand = true;
    cnt.inputs = 2;
    addSpec(t, "IL", Op::Interlock, {},
            QT_TRANSLATE_NOOP("rung::model::Target",
                              "Interlock: what follows runs under this condition"));
    addSpec(t, "ILC", Op::InterlockClear, {},
            QT_TRANSLATE_NOOP("rung::model::Target", "Clear the interlock"));
    addSpec(t, "JMP", Op::Jump, {},
            QT_TRANSLATE_NOOP("rung::model::Target",
                              "Jump: skip up to JPE while the condition is OFF"));
    addSpec(t, "JPE", Op::JumpEnd, {}, QT_TRANSLATE_NOOP("rung::model::Target", "End of a jump"));
    addSpec(t, "END", Op::End, {}, QT_TRANSLATE_NOOP("rung::model::Target", "End of the program"));

    t.limits.programSteps = 2048;
    t.limits.stackDepth = 8;
    t.limits.contactsPerRow = 10;
    t.limits.maxBlocksInRow = 8;
    t.limits.allowsStack = false;
    t.limits.duplicateCoilIsError = true;
    t.limits.decimalDigits = 4;

    // VPC user's manual: operands are plain decimal numbers; coils take effect from the next scan;
    // TIM00..15 / CNT00..15 count down, TIM16..31 / CNT16..31 up; p76 appears binary on
    // o00..o11 (value mod 4096, o11 = MSB) and i00..i11 read as a number into p77.
    t.constants.plain = true;
    t.semantics.deferredBitWrites = true;
    t.semantics.downTimersBelow = 16;
    t.semantics.downCountersBelow = 16;
    t.semantics.parallelOut = {QStringLiteral("p76"), QStringLiteral("o00"), 12};
    t.semantics.parallelIn = {QStringLiteral("p77"), QStringLiteral("i00"), 12};

    // Discrete in / out / analog in / analog out per model (VPC user's manual).
    struct Io {
        const char *name;
        int in, out, ain, aout;
    };
    const Io models[] = {
        {"VPC106", 10, 6, 0, 0},      {"VPC108A4", 10, 8, 4, 0}, {"VPC1410", 14, 10, 0, 0},
        {"VPC1812", 18, 12, 0, 0},    {"VPC2416", 24, 16, 0, 0}, {"VPC3224L", 32, 24, 0, 0},
        {"VPC3224A63", 32, 24, 6, 3}, {"VPC4030", 40, 30, 0, 0}, {"VPC4030A84", 40, 30, 8, 4}};
    for (const Io &m : models) {
        ModelVariant v;
        v.name = QString::fromLatin1(m.name);
        v.overrides = {{QStringLiteral("i"), 0, m.in - 1},
                       {QStringLiteral("o"), 0, m.out - 1},
                       {QStringLiteral("a"), 0, m.ain - 1},
                       {QStringLiteral("d"), 0, m.aout - 1}};
        // The terminal strip: inputs and outputs in eights; the analog values are register
        // values 0000..9999 (VPC user's manual, III: decimal registers; the manual gives no
        // converter resolution).
        addTerminals(v, "i", 0, m.in);
        addTerminals(v, "o", 0, m.out);
        addWordTerminals(v, "a", 0, m.ain, 0, 9999);
        addWordTerminals(v, "d", 0, m.aout, 0, 9999);
        t.models.push_back(v);
    }
    // The console's error texts (VPC user's manual, VI), quoted in the checks' messages.
    t.console.blockMissing = "IL (JMP) missing";
    t.console.interlace = "IL-JMP interlace";
    t.console.duplicate = "Oper duplication";
    // The console's LCD in its first RUN & MONITOR window (VPC user's manual, V.a): "The upper
    // part of the display is for the outputs, shown by 16 per line. The lower part of the
    // display is for the inputs, shown in the same manner. A filled field represents the state
    // ON, the empty one - OFF." The other windows and the console's keys edit and search the
    // program; they are not simulated.
    // The front's LEDs (VPC user's manual, II Technical specifications, "Indication": "LEDs to show
    // which inputs/outputs are driven ON (VPC2416 and higher)", higher in the manual's list of
    // models): one a point, lit while it is ON. The manual names no lamp for power, RUN or errors
    // (r89 ERR is a register), gives the LEDs no colour and no arrangement: they are drawn plainly,
    // in the order of the devices.
    const QStringList withLeds = {QStringLiteral("VPC2416"), QStringLiteral("VPC3224L"),
                                  QStringLiteral("VPC3224A63"), QStringLiteral("VPC4030"),
                                  QStringLiteral("VPC4030A84")};
    t.panel.pointLamps = {
        {QStringLiteral("i"), withLeds, LampColour::Unstated,
         QT_TRANSLATE_NOOP("rung::model::Target", "input LED: lit while the input is ON")},
        {QStringLiteral("o"), withLeds, LampColour::Unstated,
         QT_TRANSLATE_NOOP("rung::model::Target", "output LED: lit while the output is ON")},
    };
    t.panel.display.kind = DisplayKind::IoLines;
    t.panel.display.lineAreas = {QStringLiteral("o"), QStringLiteral("i")};
    t.panel.display.perLine = 16;
    return t;
}

} // namespace rung::model::detail
