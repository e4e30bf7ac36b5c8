#include "model/target/target_data.h"

#include <QCoreApplication>

// Vigor M / VB / VH: devices from the communication address map of the Vigor M/VB/VH
// communication manual (B-5-3), instructions of the FX-style family described in PLC concepts
// (WPLSoft family). Where the manuals are silent (latched ranges, clock relays, step counts)
// the values follow the FX family the Vigor PLCs copy; docs/targets.md lists each such choice.

namespace rung::model::detail {

namespace {

using K = OperandKind;

InstructionSpec contact(const char *mnemonic, Op op, ContactMode mode, const char *summary) {
    InstructionSpec s;
    s.mnemonic = QString::fromLatin1(mnemonic);
    s.op = op;
    s.mode = mode;
    s.operands = {{K::BitSource}};
    s.summary = summary;
    s.operandHelp = "X/Y/M/S/T/C";
    return s;
}

InstructionSpec compareContact(const char *mnemonic, Op op, CompareOp compare) {
    InstructionSpec s;
    s.mnemonic = QString::fromLatin1(mnemonic);
    s.op = op;
    s.compare = compare;
    s.operands = {{K::WordSource}, {K::WordSource}};
    s.summary = QT_TRANSLATE_NOOP("rung::model::Target", "Compare contact: ON while S1 ? S2");
    s.operandHelp = "S1 S2";
    s.steps = 5;
    return s;
}

InstructionSpec bare(const char *mnemonic, Op op, const char *summary) {
    InstructionSpec s;
    s.mnemonic = QString::fromLatin1(mnemonic);
    s.op = op;
    s.summary = summary;
    return s;
}

InstructionSpec coil(const char *mnemonic, Op op, K kind, const char *summary, const char *help) {
    InstructionSpec s;
    s.mnemonic = QString::fromLatin1(mnemonic);
    s.op = op;
    s.operands = {{kind}};
    s.summary = summary;
    s.operandHelp = help;
    return s;
}

InstructionSpec apply(const char *mnemonic, ApplyFunction function,
                      std::vector<OperandSpec> operands, int steps, const char *summary,
                      const char *help) {
    InstructionSpec s;
    s.mnemonic = QString::fromLatin1(mnemonic);
    s.op = Op::Apply;
    s.function = function;
    s.operands = std::move(operands);
    s.steps = steps;
    s.summary = summary;
    s.operandHelp = help;
    return s;
}

// The serial ports (Vigor M/VB/VH communication manual, B-2, B-3-1 and the tables of B-3-2 ..
// B-3-9, B-4): CP1 on every main unit, CP2 on a communication card or module, CP3 on a VB-CADP,
// VB-1COM modules. Applications per series as the manual's tables give them.
std::vector<PortSpec> vigorPorts() {
    const QStringList mAndVb = {QStringLiteral("M"), QStringLiteral("VB")};
    const std::vector<int> link = {19200, 4800, 9600, 38400}; // B-3-2, B-3-3
    PortApplication computerLink;
    computerLink.id = "computer-link";
    computerLink.name = QT_TRANSLATE_NOOP("rung::model::Target", "Computer Link");
    computerLink.bauds = link;
    computerLink.frame = "7E1";
    computerLink.fixedFrame = true;
    computerLink.stationMax = 255;
    computerLink.answers = ProtocolId::VigorLink;

    PortSpec cp1;
    cp1.name = QStringLiteral("CP1");
    cp1.description = QT_TRANSLATE_NOOP("rung::model::Target",
                                        "CP1, the main unit's RS-232 port (Computer Link, 19200 "
                                        "bps, station 0)");
    PortApplication cp1Link = computerLink;
    cp1Link.bauds = {19200};
    cp1Link.stationMax = 0;
    cp1.applications = {cp1Link};

    PortSpec cp2;
    cp2.name = QStringLiteral("CP2");
    cp2.description = QT_TRANSLATE_NOOP("rung::model::Target",
                                        "CP2, the second communication port (a card or a module)");
    // The slaves answer Computer Link with either setting; the master runs LINK (B-3-3). The
    // VH takes part as a slave only, with Computer Link.
    PortApplication easyLink = computerLink;
    easyLink.id = "easy-link";
    easyLink.name = QT_TRANSLATE_NOOP("rung::model::Target", "Easy Link");
    easyLink.models = mAndVb;
    PortApplication cpuLink;
    cpuLink.id = "cpu-link";
    cpuLink.name = QT_TRANSLATE_NOOP("rung::model::Target", "CPU Link");
    cpuLink.models = mAndVb;
    cpuLink.bauds = {38400}; // B-3-4: 38400 bps
    cpuLink.frame = "7E1";
    cpuLink.stationMax = 7;
    cpuLink.published = false;
    cpuLink.sharedLink = 1;
    // B-3-4's transfer ranges: station s has D(10s).. and, from mode 2, M(1000 + 64s)..; the
    // table prints M1256..M1391 for station 4 in mode 3, the pattern gives M1256..M1319.
    cpuLink.sharedModes = {
        {{{"D", 0, 10, 4}}, {7, 11, 15, 19, 23, 27, 31}},
        {{{"D", 0, 10, 4}, {"M", 1000, 64, 32}}, {10, 15, 20, 25, 30, 35, 40}},
        {{{"D", 0, 10, 8}, {"M", 1000, 64, 64}}, {16, 24, 33, 42, 50, 59, 68}},
    };
    PortApplication parallelLink;
    parallelLink.id = "parallel-link";
    parallelLink.name = QT_TRANSLATE_NOOP("rung::model::Target", "Parallel Link");
    parallelLink.models = mAndVb;
    parallelLink.bauds = link;
    parallelLink.frame = "7E1";
    parallelLink.published = false;
    parallelLink.sharedLink = 2;
    // B-3-5: master -> slave M800..M899, D490..D499 (high speed D490, D491); slave -> master
    // M900..M999, D500..D509 (D500, D501); 73 ms (14 ms) at 19200 bps plus both scans.
    parallelLink.sharedModes = {
        {{{"M", 800, 100, 100}, {"D", 490, 10, 10}}, {73}},
        {{{"D", 490, 10, 2}}, {14}},
    };
    PortApplication modbus;
    modbus.id = "modbus";
    modbus.name = QT_TRANSLATE_NOOP("rung::model::Target", "MODBUS");
    modbus.bauds = {19200, 300, 600, 1200, 2400, 4800, 9600, 38400}; // B-3-6
    modbus.frame = "8N1";
    modbus.stationMin = 0; // the master of MBUS (B-3-6: "station 0")
    modbus.stationMax = 247;
    modbus.station = 1;
    modbus.answers = ProtocolId::Modbus;
    PortApplication nonProtocol;
    nonProtocol.id = "non-protocol";
    nonProtocol.name = QT_TRANSLATE_NOOP("rung::model::Target", "Non Protocol");
    nonProtocol.bauds = {19200, 300, 600, 1200, 2400, 4800, 9600}; // B-3-9 stops at 19200
    nonProtocol.frame = "7E1";
    nonProtocol.programDriven = true;
    cp2.applications = {computerLink, easyLink, cpuLink, parallelLink, modbus, nonProtocol};

    PortSpec cp3;
    cp3.name = QStringLiteral("CP3");
    cp3.description = QT_TRANSLATE_NOOP("rung::model::Target",
                                        "CP3, the VB-CADP's RS-485 port (Computer Link, 19200 "
                                        "bps, station 0..99)");
    cp3.models = {QStringLiteral("VB")};
    PortApplication cp3Link = computerLink;
    cp3Link.bauds = {19200};
    cp3Link.stationMax = 99;
    cp3.applications = {cp3Link};

    std::vector<PortSpec> ports = {cp1, cp2, cp3};
    // VB-1COM (B-4): no protocol, the program sets the line through BFM #0 (initial 0087H:
    // 9600 bps, 8 data bits, even parity, 1 stop bit) and drives it with FROM / TO.
    PortApplication module;
    module.id = "vb-1com";
    module.name = QT_TRANSLATE_NOOP("rung::model::Target", "VB-1COM serial module");
    module.bauds = {9600, 300, 600, 1200, 2400, 4800, 19200, 38400, 76800, 14400, 28800, 57600};
    module.frame = "8E1";
    module.programDriven = true;
    for (int k = 1; k <= 16; ++k) {
        PortSpec m;
        m.name = QStringLiteral("MODULE%1").arg(k);
        m.description = QT_TRANSLATE_NOOP("rung::model::Target",
                                          "a VB-1COM serial module, numbered as FROM / TO name it");
        m.models = {QStringLiteral("VB")};
        m.applications = {module};
        ports.push_back(m);
    }
    return ports;
}

} // namespace

Target makeVigorTarget() {
    Target t;
    t.family = Family::Vigor;
    t.id = QStringLiteral("vigor");
    t.displayName = QStringLiteral("Vigor");
    t.defaultTimerBaseMs = 100.0;

    Area &x = addArea(t, "X", "X", AreaKind::Bit, 0, 0777,
                      QT_TRANSLATE_NOOP("rung::model::Target", "inputs"));
    x.numbering = Numbering::Octal;
    x.writable = false;
    x.physical = true;
    Area &y = addArea(t, "Y", "Y", AreaKind::Bit, 0, 0777,
                      QT_TRANSLATE_NOOP("rung::model::Target", "outputs"));
    y.numbering = Numbering::Octal;
    y.physical = true;
    addArea(t, "M", "M", AreaKind::Bit, 0, 499,
            QT_TRANSLATE_NOOP("rung::model::Target", "auxiliary relays"));
    addArea(t, "ML", "M", AreaKind::Bit, 500, 5119,
            QT_TRANSLATE_NOOP("rung::model::Target", "latched auxiliary relays"))
        .retentive = true;
    Area &sm = addArea(t, "SM", "M", AreaKind::Bit, 9000, 9255,
                       QT_TRANSLATE_NOOP("rung::model::Target", "special relays"));
    // Writable as a whole: the programs of the Vigor M/VB/VH communication manual drive M9100
    // (start dialing) and M9122 (RS send); the read-only ones are known by name in
    // systemDevices.
    sm.system = true;
    addArea(t, "S", "S", AreaKind::Bit, 0, 499,
            QT_TRANSLATE_NOOP("rung::model::Target", "step relays"));
    addArea(t, "SL", "S", AreaKind::Bit, 500, 999,
            QT_TRANSLATE_NOOP("rung::model::Target", "latched step relays"))
        .retentive = true;
    // PLC concepts (WPLSoft family) 1.4: "Every timer has its resolution (unit:
    // 1ms/10ms/100ms)"; neither manual gives the ranges. The Vigor numbers its special devices
    // as the FX family does, 1000 higher (FX M8000 RUN, M8002, D8010..D8012, M8122, M8161,
    // M8168 are the Vigor's M9000, M9002, D9010..D9012, M9122, M9161, M9168 of the Vigor
    // M/VB/VH communication manual), so its timers follow the FX ranges: T0..T199 100 ms,
    // T200..T245 10 ms, T246..T249 1 ms and T250..T255 100 ms accumulating and retained. The
    // same on M, VB and VH (a model with other ranges gets overrides).
    addArea(t, "T", "T", AreaKind::Timer, 0, 199,
            QT_TRANSLATE_NOOP("rung::model::Target", "timers (100 ms)"));
    addArea(t, "T10", "T", AreaKind::Timer, 200, 245,
            QT_TRANSLATE_NOOP("rung::model::Target", "timers (10 ms)"))
        .timerBaseMs = 10;
    Area &t1 = addArea(t, "T1R", "T", AreaKind::Timer, 246, 249,
                       QT_TRANSLATE_NOOP("rung::model::Target", "accumulating timers (1 ms)"));
    t1.timerBaseMs = 1;
    t1.timerMode = TimerMode::Accumulating;
    t1.retentive = true;
    Area &t100 = addArea(t, "TR", "T", AreaKind::Timer, 250, 255,
                         QT_TRANSLATE_NOOP("rung::model::Target", "accumulating timers (100 ms)"));
    t100.timerMode = TimerMode::Accumulating;
    t100.retentive = true;
    addArea(t, "C", "C", AreaKind::Counter, 0, 99,
            QT_TRANSLATE_NOOP("rung::model::Target", "counters"));
    addArea(t, "CL", "C", AreaKind::Counter, 100, 199,
            QT_TRANSLATE_NOOP("rung::model::Target", "latched counters"))
        .retentive = true;
    Area &c32 = addArea(t, "C32", "C", AreaKind::Counter, 200, 255,
                        QT_TRANSLATE_NOOP("rung::model::Target", "32-bit counters"));
    c32.wordBits = 32;
    c32.retentive = true;
    addArea(t, "D", "D", AreaKind::Word, 0, 199,
            QT_TRANSLATE_NOOP("rung::model::Target", "data registers"));
    addArea(t, "DL", "D", AreaKind::Word, 200, 8191,
            QT_TRANSLATE_NOOP("rung::model::Target", "latched data registers"))
        .retentive = true;
    Area &sd = addArea(t, "SD", "D", AreaKind::Word, 9000, 9255,
                       QT_TRANSLATE_NOOP("rung::model::Target", "special registers"));
    sd.system = true;
    // Index registers. The operand tables of the Vigor M/VB/VH communication manual (LINK, RS,
    // MBUS: "V,Z ... VZ index") name the Vigor's V and Z, as in the FX family; the WPLSoft
    // family (PLC concepts (WPLSoft family) 1.4) calls them E0..E7 and F0..F7 (E the low word
    // like Z, F the high one like V). Both spellings are read; the Vigor's own is printed.
    // D0Z0 = D(0 + Z0), K10V0 = 10 + V0. Not in the link map of the Vigor M/VB/VH
    // communication manual, so no protocol reaches them.
    Area &z = addArea(t, "Z", "Z", AreaKind::Word, 0, 7,
                      QT_TRANSLATE_NOOP("rung::model::Target", "index registers"));
    z.indexRegister = true;
    z.prefixAliases = {QStringLiteral("E")};
    Area &v = addArea(t, "V", "V", AreaKind::Word, 0, 7,
                      QT_TRANSLATE_NOOP("rung::model::Target", "index registers"));
    v.indexRegister = true;
    v.prefixAliases = {QStringLiteral("F")};
    // The VB's variable resistors VR1, VR2 on its panel, read by VRRD (the Vigor M/VB/VH
    // communication manual's display programs: "VRRD K1 D0  Read the value of VR1"): word inputs
    // 0..255 that the simulator takes as a stimulus like a terminal (--set VR1=120@0). Not on the
    // link map.
    Area &vr = addArea(t, "VR", "VR", AreaKind::Word, 1, 2,
                       QT_TRANSLATE_NOOP("rung::model::Target", "variable resistors (panel)"));
    vr.writable = false;
    vr.physical = true;

    t.systemDevices = {
        {QStringLiteral("M9000"), SystemRole::AlwaysOn,
         QT_TRANSLATE_NOOP("rung::model::Target", "ON while the PLC runs")},
        {QStringLiteral("M9002"), SystemRole::FirstScan,
         QT_TRANSLATE_NOOP("rung::model::Target", "ON for the first scan")},
        {QStringLiteral("M9011"), SystemRole::Clock10ms,
         QT_TRANSLATE_NOOP("rung::model::Target", "10 ms clock")},
        {QStringLiteral("M9012"), SystemRole::Clock100ms,
         QT_TRANSLATE_NOOP("rung::model::Target", "100 ms clock")},
        {QStringLiteral("M9013"), SystemRole::Clock1s,
         QT_TRANSLATE_NOOP("rung::model::Target", "1 s clock")},
        {QStringLiteral("M9014"), SystemRole::Clock1min,
         QT_TRANSLATE_NOOP("rung::model::Target", "1 min clock")},
        // Set by the program (the RS programs of the Vigor M/VB/VH communication manual:
        // "M9161 Assign 8-bits processing mode").
        {QStringLiteral("M9161"), SystemRole::ByteMode,
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "RS, CCD, ASCI, HEX: 8-bit mode, one byte a word (OFF: 16-bit)"),
         1000, true},
        {QStringLiteral("M9168"), SystemRole::HexDigits,
         QT_TRANSLATE_NOOP("rung::model::Target", "SMOV works on hexadecimal digits"), 1000, true},
        {QStringLiteral("M9199"), SystemRole::LinkCycleDone,
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "ON for one scan when LINK or MBUS completed its table")},
        {QStringLiteral("D9010"), SystemRole::ScanTimeCurrent,
         QT_TRANSLATE_NOOP("rung::model::Target", "current scan time (0.1 ms)"), 100},
        {QStringLiteral("D9011"), SystemRole::ScanTimeMin,
         QT_TRANSLATE_NOOP("rung::model::Target", "minimum scan time (0.1 ms)"), 100},
        {QStringLiteral("D9012"), SystemRole::ScanTimeMax,
         QT_TRANSLATE_NOOP("rung::model::Target", "maximum scan time (0.1 ms)"), 100},
        // The Vigor M/VB/VH communication manual's communication chapters (B-3-4, B-3-5, B-3-8,
        // B-3-9); docs/network.md.
        {QStringLiteral("M9063"), SystemRole::CommError,
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "parallel operation or RS communication error, PLC keeps running")},
        {QStringLiteral("M9070"), SystemRole::ParallelMaster,
         QT_TRANSLATE_NOOP("rung::model::Target", "parallel link: this unit is the master")},
        {QStringLiteral("M9071"), SystemRole::ParallelSlave,
         QT_TRANSLATE_NOOP("rung::model::Target", "parallel link: this unit is a slave")},
        {QStringLiteral("M9072"), SystemRole::ParallelNormal,
         QT_TRANSLATE_NOOP("rung::model::Target", "parallel operation normal")},
        {QStringLiteral("M9100"), SystemRole::Other,
         QT_TRANSLATE_NOOP("rung::model::Target", "CP2 modem: start dialing (OFF to ON)")},
        {QStringLiteral("M9101"), SystemRole::Other,
         QT_TRANSLATE_NOOP("rung::model::Target", "CP2 modem: dialing failed")},
        // "Do not use the RST instruction to reset the M9122"; the program sets it to send,
        // resets M9123 to receive again and M9129 after a time-out (B-3-9).
        {QStringLiteral("M9122"), SystemRole::RsSendRequest,
         QT_TRANSLATE_NOOP("rung::model::Target", "RS instruction send flag"), 1000, true},
        {QStringLiteral("M9123"), SystemRole::RsReceiveDone,
         QT_TRANSLATE_NOOP("rung::model::Target", "RS instruction receive done"), 1000, true},
        {QStringLiteral("M9124"), SystemRole::Other,
         QT_TRANSLATE_NOOP("rung::model::Target", "CP2 modem CD signal")},
        {QStringLiteral("M9129"), SystemRole::RsTimeout,
         QT_TRANSLATE_NOOP("rung::model::Target", "time-out during RS"), 1000, true},
        {QStringLiteral("M9162"), SystemRole::ParallelHighSpeed,
         QT_TRANSLATE_NOOP("rung::model::Target", "parallel operation high-speed transfer")},
        {QStringLiteral("M9183"), SystemRole::CpuLinkFailed,
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "CPU link communication failed (master); M9184..M9190 slaves 1..7"),
         1000, false, 0, 8},
        {QStringLiteral("D9063"), SystemRole::CommErrorCode,
         QT_TRANSLATE_NOOP("rung::model::Target", "RS communication error code")},
        {QStringLiteral("D9080"), SystemRole::Other,
         QT_TRANSLATE_NOOP("rung::model::Target", "display mode of the display screen")},
        {QStringLiteral("D9081"), SystemRole::Other,
         QT_TRANSLATE_NOOP("rung::model::Target", "number of the D register shown in mode 3")},
        {QStringLiteral("D9121"), SystemRole::Other,
         QT_TRANSLATE_NOOP("rung::model::Target", "computer link station number")},
        {QStringLiteral("D9122"), SystemRole::RsSendLeft,
         QT_TRANSLATE_NOOP("rung::model::Target", "RS: number of data left to send")},
        {QStringLiteral("D9123"), SystemRole::RsReceived,
         QT_TRANSLATE_NOOP("rung::model::Target", "RS: number of data received")},
        {QStringLiteral("D9129"), SystemRole::CommTimeout,
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "RS, LINK and MBUS time-out, x 10 ms (0: 100 ms)"),
         1000, true},
        {QStringLiteral("D9172"), SystemRole::CpuLinkTimeout,
         QT_TRANSLATE_NOOP("rung::model::Target", "CPU link communication time-out time")},
        {QStringLiteral("D9177"), SystemRole::CpuLinkSlaves,
         QT_TRANSLATE_NOOP("rung::model::Target", "CPU link: number of slave stations")},
        {QStringLiteral("D9178"), SystemRole::CpuLinkRange,
         QT_TRANSLATE_NOOP("rung::model::Target", "CPU link: transfer range mode")},
        {QStringLiteral("D9179"), SystemRole::CpuLinkRetries,
         QT_TRANSLATE_NOOP("rung::model::Target", "CPU link: communication retries")},
        {QStringLiteral("D9201"), SystemRole::NetworkScanTime,
         QT_TRANSLATE_NOOP("rung::model::Target", "current network scan time")},
        {QStringLiteral("D9202"), SystemRole::NetworkScanMax,
         QT_TRANSLATE_NOOP("rung::model::Target", "maximum network scan time")},
        {QStringLiteral("D9203"), SystemRole::CpuLinkErrorCount,
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "CPU link: communication errors of the master; D9204..D9210 slaves "
                           "1..7"),
         1000, false, 0, 8},
        {QStringLiteral("D9212"), SystemRole::CpuLinkErrorCode,
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "CPU link: error code of slave 1 (D9213..D9218: slaves 2..7): 00H "
                           "none, 01H time-out, 05H sum error"),
         1000, false, 0, 7},
    };

    auto &in = t.instructions;
    using M = ContactMode;
    in.push_back(contact(
        "LD", Op::Load, M::Normal,
        QT_TRANSLATE_NOOP("rung::model::Target", "Start a block with a normally open contact")));
    in.push_back(contact(
        "LDI", Op::Load, M::Negated,
        QT_TRANSLATE_NOOP("rung::model::Target", "Start a block with a normally closed contact")));
    in.push_back(contact(
        "LDP", Op::Load, M::Rising,
        QT_TRANSLATE_NOOP("rung::model::Target", "Start a block with a rising-edge contact")));
    in.push_back(contact(
        "LDF", Op::Load, M::Falling,
        QT_TRANSLATE_NOOP("rung::model::Target", "Start a block with a falling-edge contact")));
    in.push_back(
        contact("AND", Op::And, M::Normal,
                QT_TRANSLATE_NOOP("rung::model::Target", "Normally open contact in series")));
    in.push_back(
        contact("ANI", Op::And, M::Negated,
                QT_TRANSLATE_NOOP("rung::model::Target", "Normally closed contact in series")));
    in.push_back(
        contact("ANDP", Op::And, M::Rising,
                QT_TRANSLATE_NOOP("rung::model::Target", "Rising-edge contact in series")));
    in.push_back(
        contact("ANDF", Op::And, M::Falling,
                QT_TRANSLATE_NOOP("rung::model::Target", "Falling-edge contact in series")));
    in.push_back(
        contact("OR", Op::Or, M::Normal,
                QT_TRANSLATE_NOOP("rung::model::Target", "Normally open contact in parallel")));
    in.push_back(
        contact("ORI", Op::Or, M::Negated,
                QT_TRANSLATE_NOOP("rung::model::Target", "Normally closed contact in parallel")));
    in.push_back(
        contact("ORP", Op::Or, M::Rising,
                QT_TRANSLATE_NOOP("rung::model::Target", "Rising-edge contact in parallel")));
    in.push_back(
        contact("ORF", Op::Or, M::Falling,
                QT_TRANSLATE_NOOP("rung::model::Target", "Falling-edge contact in parallel")));
    for (const CompareOp cmp : kCompareOps) {
        for (const auto &[prefix, op] :
             {std::pair{"LD", Op::Load}, {"AND", Op::And}, {"OR", Op::Or}}) {
            const QByteArray name = QByteArray(prefix) + compareSymbol(cmp);
            InstructionSpec s = compareContact("", op, cmp);
            s.mnemonic = QString::fromLatin1(name);
            in.push_back(s);
        }
    }
    in.push_back(
        bare("ANB", Op::AndBlock,
             QT_TRANSLATE_NOOP("rung::model::Target", "Connect the last two blocks in series")));
    in.push_back(
        bare("ORB", Op::OrBlock,
             QT_TRANSLATE_NOOP("rung::model::Target", "Connect the last two blocks in parallel")));
    in.push_back(
        bare("MPS", Op::Push,
             QT_TRANSLATE_NOOP("rung::model::Target", "Push the result onto the branch stack")));
    in.push_back(
        bare("MRD", Op::ReadStack,
             QT_TRANSLATE_NOOP("rung::model::Target", "Read the top of the branch stack")));
    in.push_back(
        bare("MPP", Op::Pop, QT_TRANSLATE_NOOP("rung::model::Target", "Pop the branch stack")));
    in.push_back(
        bare("INV", Op::Invert, QT_TRANSLATE_NOOP("rung::model::Target", "Invert the result")));
    in.push_back(coil("OUT", Op::Out, K::BitDest,
                      QT_TRANSLATE_NOOP("rung::model::Target", "Output coil"), "Y/M/S"));
    in.push_back(coil("SET", Op::Set, K::BitDest,
                      QT_TRANSLATE_NOOP("rung::model::Target", "Set (latch) a device"), "Y/M/S"));
    InstructionSpec rst =
        coil("RST", Op::Reset, K::BitDest,
             QT_TRANSLATE_NOOP("rung::model::Target", "Reset a device, a timer or a counter"),
             "Y/M/S/T/C/D");
    in.push_back(rst);
    in.push_back(coil("PLS", Op::PulseRise, K::BitDest,
                      QT_TRANSLATE_NOOP("rung::model::Target", "ON for one scan on a rising edge"),
                      "Y/M"));
    in.push_back(coil("PLF", Op::PulseFall, K::BitDest,
                      QT_TRANSLATE_NOOP("rung::model::Target", "ON for one scan on a falling edge"),
                      "Y/M"));
    InstructionSpec tmr = coil(
        "TMR", Op::Timer, K::TimerNumber,
        QT_TRANSLATE_NOOP("rung::model::Target",
                          "On-delay timer: T0..T199 100 ms, T200..T245 10 ms units; T246..T249 "
                          "1 ms, T250..T255 100 ms accumulating (reset with RST)"),
        "T0..T255 K1..K32767");
    tmr.operands.push_back({K::SetValue});
    tmr.steps = 3;
    in.push_back(tmr);
    InstructionSpec cnt = coil(
        "CNT", Op::Counter, K::CounterNumber,
        QT_TRANSLATE_NOOP("rung::model::Target", "Counter: counts rising edges, reset with RST"),
        "C0..C255 K1..K32767");
    cnt.operands.push_back({K::SetValue});
    cnt.steps = 3;
    in.push_back(cnt);
    in.push_back(coil("STL", Op::StepLadder, K::StepRelay,
                      QT_TRANSLATE_NOOP("rung::model::Target", "Step ladder: start of step S"),
                      "S0..S999"));
    in.push_back(bare("RET", Op::Return,
                      QT_TRANSLATE_NOOP("rung::model::Target", "End of the step ladder")));
    in.push_back(
        bare("END", Op::End, QT_TRANSLATE_NOOP("rung::model::Target", "End of the program")));
    in.push_back(bare("NOP", Op::Nop, QT_TRANSLATE_NOOP("rung::model::Target", "No operation")));

    const OperandSpec src{K::WordSource};
    const OperandSpec dst{K::WordDest};
    in.push_back(apply("MOV", ApplyFunction::Mov, {src, dst}, 5,
                       QT_TRANSLATE_NOOP("rung::model::Target", "Move S to D"), "S D"));
    // DMOV H00310035 D4 (Vigor M/VB/VH communication manual, B-3-9 and B-4-5: two ASCII
    // characters a call, "1" into D5 and "5" into D4): MOV's 32-bit form, FNC 12 with the FX
    // family's D prefix, 9 steps (one for the instruction, four for each 32-bit operand, as
    // Delta's DMOV).
    InstructionSpec dmov =
        apply("DMOV", ApplyFunction::Mov, {src, dst}, 9,
              QT_TRANSLATE_NOOP("rung::model::Target",
                                "Move 32 bits: S (S, S+1) to D (low word), D+1 (high word)"),
              "S D");
    dmov.functionCode = 12;
    dmov.doubleWord = true;
    for (OperandSpec &o : dmov.operands)
        o.wholeWords = true;    // a pair of words, not a group of 16 bits (K4M0)
    dmov.operands[0].words = 2; // S, S+1 unless a 32-bit device, a timer or a counter
    dmov.operands[1].words = 2;
    in.push_back(dmov);
    OperandSpec blockSrc = src;
    blockSrc.wholeWords = true;
    OperandSpec blockDst = dst;
    blockDst.wholeWords = true;
    // n words from S to D: both blocks lie inside the registers, n at least 1.
    blockSrc.countFrom = 2;
    blockDst.countFrom = 2;
    OperandSpec blockCount{K::Count};
    blockCount.lowest = 1;
    blockCount.name = QT_TRANSLATE_NOOP("rung::model::Target", "number of words");
    in.push_back(apply("BMOV", ApplyFunction::BlockMove, {blockSrc, blockDst, blockCount}, 7,
                       QT_TRANSLATE_NOOP("rung::model::Target", "Move n words from S to D"),
                       "S D n"));
    // D, D+1, D+2 take >, =, <: three bits one after another.
    OperandSpec compareBits{K::BitDest};
    compareBits.words = 3;
    in.push_back(
        apply("CMP", ApplyFunction::Compare, {src, src, compareBits}, 7,
              QT_TRANSLATE_NOOP("rung::model::Target", "Compare S1 with S2: D, D+1, D+2 = >, =, <"),
              "S1 S2 D"));
    // D1 and D2 of one kind, D1 not after D2.
    OperandSpec zoneEnd{K::BitDest};
    zoneEnd.rangeFrom = 0;
    in.push_back(apply("ZRST", ApplyFunction::ZoneReset, {{K::BitDest}, zoneEnd}, 5,
                       QT_TRANSLATE_NOOP("rung::model::Target", "Reset every device from D1 to D2"),
                       "D1 D2"));
    in.push_back(apply("ADD", ApplyFunction::Add, {src, src, dst}, 7,
                       QT_TRANSLATE_NOOP("rung::model::Target", "D = S1 + S2"), "S1 S2 D"));
    in.push_back(apply("SUB", ApplyFunction::Sub, {src, src, dst}, 7,
                       QT_TRANSLATE_NOOP("rung::model::Target", "D = S1 - S2"), "S1 S2 D"));
    // The product and the remainder go to D+1 as well.
    OperandSpec wordPair = dst;
    wordPair.words = 2;
    in.push_back(apply(
        "MUL", ApplyFunction::Mul, {src, src, wordPair}, 7,
        QT_TRANSLATE_NOOP("rung::model::Target", "D, D+1 = S1 x S2 (32-bit product)"), "S1 S2 D"));
    in.push_back(apply("DIV", ApplyFunction::Div, {src, src, wordPair}, 7,
                       QT_TRANSLATE_NOOP("rung::model::Target", "D = S1 / S2, D+1 = remainder"),
                       "S1 S2 D"));
    in.push_back(apply("INC", ApplyFunction::Inc, {dst}, 3,
                       QT_TRANSLATE_NOOP("rung::model::Target", "D = D + 1"), "D"));
    in.push_back(apply("DEC", ApplyFunction::Dec, {dst}, 3,
                       QT_TRANSLATE_NOOP("rung::model::Target", "D = D - 1"), "D"));
    // Word logic and BCD conversion (the programs of the Vigor M/VB/VH communication manual:
    // WAND D104 HFF D104).
    in.push_back(apply("WAND", ApplyFunction::AndWord, {src, src, dst}, 7,
                       QT_TRANSLATE_NOOP("rung::model::Target", "D = S1 AND S2, bit by bit"),
                       "S1 S2 D"));
    in.push_back(apply("WOR", ApplyFunction::OrWord, {src, src, dst}, 7,
                       QT_TRANSLATE_NOOP("rung::model::Target", "D = S1 OR S2, bit by bit"),
                       "S1 S2 D"));
    in.push_back(apply("WXOR", ApplyFunction::XorWord, {src, src, dst}, 7,
                       QT_TRANSLATE_NOOP("rung::model::Target", "D = S1 XOR S2, bit by bit"),
                       "S1 S2 D"));
    in.push_back(apply("CML", ApplyFunction::Complement, {src, dst}, 5,
                       QT_TRANSLATE_NOOP("rung::model::Target", "D = every bit of S inverted"),
                       "S D"));
    in.push_back(apply("BCD", ApplyFunction::ToBcd, {src, dst}, 5,
                       QT_TRANSLATE_NOOP("rung::model::Target", "D = S as BCD digits"), "S D"));
    in.push_back(apply(
        "BIN", ApplyFunction::FromBcd, {src, dst}, 5,
        QT_TRANSLATE_NOOP("rung::model::Target", "D = the value of the BCD digits S"), "S D"));
    // Special modules, I/O refresh and communication (docs/network.md). REF is accepted and not
    // simulated (check warns, SIM100); the rest is simulated. Neither manual gives step counts:
    // each is the FX family's 16-bit size, one step for the instruction and two for each
    // operand (Delta's tables, to which PLC concepts (WPLSoft family) belongs, give FROM/TO 9, CCD
    // 7, REF 5 the same way). Operands as the Vigor M/VB/VH communication manual's pages and
    // example programs write them. FROM / TO m1 m2 D n (the Vigor M/VB/VH communication manual's
    // VB-1COM pages: FROM K1 K2000 D50 K15, TO K1 K1000 D0 K15): n words at least one, the block
    // D..D+n-1 inside the registers.
    OperandSpec moduleWords{K::Count};
    moduleWords.lowest = 1;
    // m1: the module, K1..K16 (Vigor M/VB/VH communication manual, B-4-1: "up to 16" VB-1COM
    // modules; the examples use K1); m2: the first buffer memory word (B-4-4: #0..#30,
    // #1000..#1256, #2000..#2256).
    OperandSpec moduleNumber{K::Constant};
    moduleNumber.lowest = 1;
    moduleNumber.highest = 16;
    moduleNumber.name = QT_TRANSLATE_NOOP("rung::model::Target", "module number");
    OperandSpec moduleWord{K::Constant};
    moduleWord.lowest = 0;
    moduleWord.highest = 32767;
    moduleWord.name = QT_TRANSLATE_NOOP("rung::model::Target", "buffer memory word");
    moduleWords.name = QT_TRANSLATE_NOOP("rung::model::Target", "number of words");
    OperandSpec moduleDst = dst;
    moduleDst.countFrom = 3;
    OperandSpec moduleSrc = src;
    moduleSrc.countFrom = 3;
    // The module's port is MODULE1..MODULE16 (Target::ports), numbered by m1.
    auto modulePort = [](InstructionSpec s) {
        s.port = "MODULE";
        s.portOperand = 0;
        s.portApplications = {"vb-1com"};
        return s;
    };
    in.push_back(modulePort(apply(
        "FROM", ApplyFunction::ModuleRead, {moduleNumber, moduleWord, moduleDst, moduleWords}, 9,
        QT_TRANSLATE_NOOP("rung::model::Target", "Read n words of special module m1, from m2"),
        "m1 m2 D n")));
    in.push_back(modulePort(apply(
        "TO", ApplyFunction::ModuleWrite, {moduleNumber, moduleWord, moduleSrc, moduleWords}, 9,
        QT_TRANSLATE_NOOP("rung::model::Target", "Write n words to special module m1, at m2"),
        "m1 m2 S n")));
    // TOP K1 K0 H7096 K1 (Vigor M/VB/VH communication manual, B-4-5, the VB-1COM's communication
    // format): TO's pulse form, FNC 79, run once when its condition turns ON.
    InstructionSpec top = modulePort(apply(
        "TOP", ApplyFunction::ModuleWrite, {moduleNumber, moduleWord, moduleSrc, moduleWords}, 9,
        QT_TRANSLATE_NOOP("rung::model::Target",
                          "Write n words to special module m1, at m2, once on a rising edge"),
        "m1 m2 S n"));
    top.functionCode = 79;
    top.differentiated = true;
    in.push_back(top);
    // CCD D52 D104 K11 (Vigor M/VB/VH communication manual, B-3-9, B-4-5: the check code of a
    // frame, one character a word with M9161 ON). FNC 84; n = 1..256 bytes (FX, Delta).
    OperandSpec ccdSource = src;
    ccdSource.wholeWords = true;
    ccdSource.deviceOnly = true; // the bytes are read from words, not from a constant
    OperandSpec ccdSum = dst;
    ccdSum.words = 2; // D: the sum, D+1: the parity
    OperandSpec bytes{K::Count};
    bytes.lowest = 1;
    bytes.highest = 256;
    InstructionSpec ccd =
        apply("CCD", ApplyFunction::CheckCode, {ccdSource, ccdSum, bytes}, 7,
              QT_TRANSLATE_NOOP("rung::model::Target",
                                "Check code: the sum of n bytes from S into D, their parity into "
                                "D+1 (M9161 ON: one byte a word)"),
              "S D n");
    ccd.functionCode = 84;
    in.push_back(ccd);
    // PLC concepts (WPLSoft family) 1.1 ("Scan time exception"): "A direct I/O refresh
    // instruction REF allows the PLC to access I/O immediately": inputs or outputs, X or Y
    // only. (The FX / Delta habit of a start that is a multiple of 8 is not in the manuals and
    // not enforced.)
    OperandSpec refreshed{K::BitSource};
    refreshed.sourceAreas = {"X", "Y"};
    refreshed.deviceOnly = true;
    refreshed.name = QT_TRANSLATE_NOOP("rung::model::Target", "first input or output");
    in.push_back(apply("REF", ApplyFunction::NotSimulated, {refreshed, {K::Count}}, 5,
                       QT_TRANSLATE_NOOP("rung::model::Target", "Refresh n inputs or outputs now"),
                       "D n"));
    // HEX D59 D106 K2, ASCI D111 D12 K4 (the Vigor M/VB/VH communication manual's RS and VB-1COM
    // programs). The manual defines them only by those programs: a word's last n hexadecimal digits
    // (n = 2 or 4), one character a word with M9161 ON. n is 1..4, one word's digits
    // (docs/simulator.md).
    OperandSpec digits{K::Count};
    digits.lowest = 1;
    digits.highest = 4;
    digits.name = QT_TRANSLATE_NOOP("rung::model::Target", "number of digits");
    OperandSpec characters = src;
    characters.deviceOnly = true; // the characters are read from words
    characters.wholeWords = true;
    OperandSpec charactersOut = dst;
    charactersOut.wholeWords = true;
    InstructionSpec hex =
        apply("HEX", ApplyFunction::FromAscii, {characters, dst, digits}, 7,
              QT_TRANSLATE_NOOP("rung::model::Target", "Convert n ASCII characters from S to "
                                                       "hexadecimal in D"),
              "S D n");
    hex.functionCode = 83;
    in.push_back(hex);
    InstructionSpec asci = apply("ASCI", ApplyFunction::ToAscii, {src, charactersOut, digits}, 7,
                                 QT_TRANSLATE_NOOP("rung::model::Target",
                                                   "Convert n hexadecimal digits from S to ASCII "
                                                   "in D"),
                                 "S D n");
    asci.functionCode = 82;
    in.push_back(asci);
    // RS D0 D200 D100 D201 (FNC 80): send m words from S, receive n words into D.
    // Vigor M/VB/VH communication manual, FNC 80 RS, "Operand Devices": S and D in the D column
    // only; m and n a D or a K/H constant, "m,n=0~256".
    OperandSpec rsData{K::WordSource};
    rsData.sourceAreas = {"D", "DL"};
    rsData.deviceOnly = true;
    OperandSpec rsFirst = rsData;
    rsFirst.name = QT_TRANSLATE_NOOP("rung::model::Target", "first word to send");
    OperandSpec rsInto{K::WordDest};
    rsInto.sourceAreas = {"D", "DL"};
    rsInto.deviceOnly = true;
    rsInto.name = QT_TRANSLATE_NOOP("rung::model::Target", "first word received");
    OperandSpec rsCount{K::WordSource};
    rsCount.sourceAreas = {"D", "DL"};
    rsCount.lowest = 0;
    rsCount.highest = 256;
    rsCount.name = QT_TRANSLATE_NOOP("rung::model::Target", "number of words");
    InstructionSpec rs =
        apply("RS", ApplyFunction::SerialData, {rsFirst, rsCount, rsInto, rsCount}, 9,
              QT_TRANSLATE_NOOP("rung::model::Target",
                                "Serial communication on CP2: send m words from S, "
                                "receive n words into D"),
              "S m D n");
    rs.functionCode = 80;
    rs.port = "CP2";
    rs.portApplications = {"non-protocol"};
    in.push_back(rs);
    // LINK D1000 D100 (FNC 89), MBUS D1000 D100 (FNC 149): a table from S1, 4 working words
    // from S2.
    // Vigor M/VB/VH communication manual, FNC 89 LINK and FNC 149 MBUS, "Operand Devices": S1
    // and S2 in the D column; "S2: Instruction working area, occupies 4 consecutive registers".
    OperandSpec linkTable{K::WordSource};
    linkTable.sourceAreas = {"D", "DL"};
    linkTable.deviceOnly = true;
    linkTable.name = QT_TRANSLATE_NOOP("rung::model::Target", "table");
    OperandSpec linkWork{K::WordDest};
    linkWork.sourceAreas = {"D", "DL"};
    linkWork.deviceOnly = true;
    linkWork.words = 4;
    linkWork.name = QT_TRANSLATE_NOOP("rung::model::Target", "working area");
    // The table: a count, then 7 registers a set; at most 255 sets (B-3-3, B-3-6).
    linkTable.words = 1;
    // B-3-3: "When the CP2 is assigned to this instruction, the communication type should use
    // EASY LINK or COMPUTER LINK"; B-3-6: MBUS on CP2 "MODBUS".
    InstructionSpec link =
        apply("LINK", ApplyFunction::EasyLink, {linkTable, linkWork}, 5,
              QT_TRANSLATE_NOOP("rung::model::Target",
                                "Easy Link between PLCs: table from S1, working area S2"),
              "S1 S2");
    link.functionCode = 89;
    link.port = "CP2";
    link.portApplications = {"easy-link", "computer-link"};
    link.oncePerProgram = true;
    in.push_back(link);
    InstructionSpec mbus = apply(
        "MBUS", ApplyFunction::ModbusMaster, {linkTable, linkWork}, 5,
        QT_TRANSLATE_NOOP("rung::model::Target", "MODBUS master: table from S1, working area S2"),
        "S1 S2");
    mbus.functionCode = 149;
    mbus.port = "CP2";
    mbus.portApplications = {"modbus"};
    mbus.oncePerProgram = true;
    in.push_back(mbus);
    // VRRD K1 D0: the value of the volume VR1 into D0 (the panel's VR words, a stimulus).
    OperandSpec volume{K::Constant};
    volume.lowest = 1;
    volume.highest = 2;
    volume.name = QT_TRANSLATE_NOOP("rung::model::Target", "variable resistor");
    volume.elementOf = "VR";
    InstructionSpec vrrd = apply(
        "VRRD", ApplyFunction::ReadVolume, {volume, dst}, 5,
        QT_TRANSLATE_NOOP("rung::model::Target", "Read the variable resistor (volume) VRn into D"),
        "K D");
    vrrd.functionCode = 85;
    in.push_back(vrrd);
    OperandSpec swapped = dst;
    swapped.wholeWords = true;
    InstructionSpec swap =
        apply("SWAP", ApplyFunction::Swap, {swapped}, 3,
              QT_TRANSLATE_NOOP("rung::model::Target", "Swap the high and low bytes of D"), "D");
    swap.functionCode = 147;
    in.push_back(swap);
    // SMOV D55 K2 K2 D110 K4 (Vigor M/VB/VH communication manual, with M9168 choosing hexadecimal
    // digits): digit positions 1..4, the count no more than the digits from m1 down and from n
    // down.
    OperandSpec digitPosition{K::Count};
    digitPosition.lowest = 1;
    digitPosition.highest = 4;
    digitPosition.name = QT_TRANSLATE_NOOP("rung::model::Target", "digit position");
    InstructionSpec smov = apply(
        "SMOV", ApplyFunction::ShiftDigits, {src, digitPosition, digits, dst, digitPosition}, 11,
        QT_TRANSLATE_NOOP("rung::model::Target",
                          "Move m2 digits of S from digit m1 to D from digit n"),
        "S m1 m2 D n");
    smov.functionCode = 13;
    in.push_back(smov);
    // DDIV D12 K255 D14 (Vigor M/VB/VH communication manual, B-3-6, the MBUS example's slaves:
    // "D10x99/255"): DIV's 32-bit form; the quotient into D, D+1, the remainder into D+2, D+3.
    InstructionSpec ddiv =
        apply("DDIV", ApplyFunction::Div, {src, src, dst}, 13,
              QT_TRANSLATE_NOOP("rung::model::Target",
                                "32 bits: D, D+1 = (S1, S1+1) / (S2, S2+1), D+2, D+3 = remainder"),
              "S1 S2 D");
    ddiv.functionCode = 23;
    ddiv.doubleWord = true;
    for (OperandSpec &o : ddiv.operands)
        o.wholeWords = true;
    ddiv.operands[0].words = 2;
    ddiv.operands[1].words = 2;
    ddiv.operands[2].words = 4;
    in.push_back(ddiv);
    // ALTP M0 (Vigor M/VB/VH communication manual, B-3-9: the read and write periods): M0 changes
    // state at each rising edge of the input, ALT's pulse form (FNC 66).
    OperandSpec alternated{K::BitDest};
    InstructionSpec altp =
        apply("ALTP", ApplyFunction::Toggle, {alternated}, 3,
              QT_TRANSLATE_NOOP("rung::model::Target",
                                "Alternate: D changes state at each rising edge of the input"),
              "D");
    altp.functionCode = 66;
    in.push_back(altp);

    t.limits.programSteps = 16000;
    t.limits.stackDepth = 8;
    t.limits.contactsPerRow = 11;
    t.limits.maxBlocksInRow = 8;
    t.limits.allowsStack = true;
    t.limits.duplicateCoilIsError = false;
    t.limits.outputNeedsCondition = true;

    // PLC concepts (WPLSoft family): K10 decimal, H1F hexadecimal; a bare number is no
    // constant. K1..K4 before a bit device: 4 to 16 bits as a word (K4Y0; TO K1 K1 K1M20 K1 in
    // the Vigor M/VB/VH communication manual).
    t.constants.prefixed = true;
    t.constants.digitGroups = 4;

    // The manuals give one device map for the whole family; the models differ in program size.
    t.models = {
        ModelVariant{QStringLiteral("M"), {}, 8000, {}},
        ModelVariant{QStringLiteral("VB"), {}, 16000, {}},
        ModelVariant{QStringLiteral("VH"), {}, 16000, {}},
    };
    // The manuals give no model's I/O count: the panel's strip is 16 inputs X0..X17 and 16
    // outputs Y0..Y17 in eights (octal), and it adds the further X / Y the program uses.
    for (ModelVariant &v : t.models) {
        addTerminals(v, "X", 0, 16);
        addTerminals(v, "Y", 0, 16);
    }
    t.protocolMaps = vigorProtocolMaps();
    t.ports = vigorPorts();
    // The device types of the LINK / MBUS tables (B-3-3, B-3-6).
    t.linkDeviceCodes = {
        {1, "X", true},   {2, "Y", true},       {3, "M", true},
        {4, "S", true},   {5, "T", true},       {6, "C", true},
        {10, "T", false}, {11, "C", false, 16}, {12, "C", false, 32, false},
        {13, "D", false},
    };
    // The VB's front (Vigor M/VB/VH communication manual, B-3: the display programs). The
    // 4-digit display: "MOV K3 D9080 Set the display screen to display mode 3 (displays a
    // 4-digits numeric value)", D9081 naming the D register shown; mode 4 "displays two
    // 2-digits numeric values", D[D9081] on the right and the next register on the left. The
    // manual names no other mode. The variable resistors VR1, VR2 (0..255) that VRRD reads.
    // The manual does not describe the lamps: RUN and ERROR show the run state and a program
    // error the simulation stopped on.
    t.panel.display.kind = DisplayKind::Digits;
    t.panel.display.modeDevice = QStringLiteral("D9080");
    t.panel.display.registerDevice = QStringLiteral("D9081");
    t.panel.display.registerArea = QStringLiteral("D");
    t.panel.display.digits = 4;
    t.panel.display.singleValueMode = 3;
    t.panel.display.pairMode = 4;
    for (const char *vr : {"VR1", "VR2"})
        t.panel.knobs.push_back(
            {QString::fromLatin1(vr), QString::fromLatin1(vr), 0, 255, false,
             QT_TRANSLATE_NOOP("rung::model::Target", "variable resistor read by VRRD, 0..255")});
    t.panel.lamps = {
        {QStringLiteral("RUN"),
         LampColour::Green,
         LampSignal::Running,
         {},
         0,
         QT_TRANSLATE_NOOP("rung::model::Target", "lit while the program runs")},
        {QStringLiteral("ERROR"),
         LampColour::Red,
         LampSignal::Fault,
         {},
         0,
         QT_TRANSLATE_NOOP("rung::model::Target", "lit when a program error stopped the PLC")},
    };
    return t;
}

} // namespace rung::model::detail
