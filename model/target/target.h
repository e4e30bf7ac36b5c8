#pragma once

// A target family's description as data: device areas, system devices, the instruction
// table and the limits. Every room reads these tables; no address or mnemonic rule is
// written anywhere else.

#include "model/comm/port_spec.h"
#include "model/target/front_panel.h"
#include "model/target/op.h"
#include "model/target/protocol_map.h"

#include <QMultiHash>
#include <QString>
#include <QStringList>

#include <climits>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace rung::model {

enum class Family : std::uint8_t { Vpc, Vigor, Cpm1, Pl110 };

enum class ApplyFunction : std::uint8_t; // below, with the instructions
enum class TimerMode : std::uint8_t;     // below, with the instructions

// How the element numbers of an area are written.
enum class Numbering : std::uint8_t {
    Decimal,    // X0, M100, i00 (with Area::digits for zero padding)
    Octal,      // Vigor X/Y: X7 is followed by X10
    ChannelBit, // CPM1: channel and bit, 010.00 (bit), 010 (channel as a word)
};

enum class AreaKind : std::uint8_t {
    Bit,     // a bit device: X, Y, M, S, i, o, r, PL110 I/Q/M/B
    Word,    // a word device: D, p, a, d, V
    Timer,   // contact bit + current value + set value
    Counter, // contact bit + current value + set value
    Channel, // CPM1 style: a 16-bit word whose bits are devices too (000.00 .. 255.15, HR, DM)
};

struct Area {
    QString key;    // stable name, unique per target, used by models and files: "X", "IN"
    QString prefix; // as written in listings: "X", "i", "HR", "" for CPM1 IR/SR
    QStringList prefixAliases; // other accepted spellings, printed as prefix: PL110 "VW" for "V"
    AreaKind kind = AreaKind::Bit;
    int first = 0; // first element number (PL110 areas start at 1)
    int last = 0;  // last element number, inclusive
    Numbering numbering = Numbering::Decimal;
    int digits = 0;       // minimum printed digits (VPC: 2, CPM1 channels: 3)
    bool writable = true; // may be the destination of an output / transfer
    bool retentive = false;
    bool system = false;   // system area (special relays / registers)
    bool physical = false; // mapped to terminals: inputs are refreshed from the I/O image
    int bank = -1;         // areas with the same bank share element numbers (VPC t/c, CPM1 TIM/CNT)
    int wordBits = 16;     // value width for Word/Timer/Counter/Channel areas (Vigor C200+: 32)
    // A data word or a channel: addressed and transferred by whole words (a word of a timer
    // or counter area is its value, which the protocols move apart).
    bool holdsWords() const { return kind == AreaKind::Word || kind == AreaKind::Channel; }
    const char *description = nullptr; // QT_TRANSLATE_NOOP("rung::model::Target", ...)
    // Only instructions of this function may write the area (PL110 B: its bistable coil OUTB,
    // PL110 manual 4.2.3); None: any instruction that writes.
    ApplyFunction onlyWrittenBy{}; // ApplyFunction::None
    // The words of this area are the set values of the timer/counter area with this key,
    // element for element (PL110 PT1 = preset of T1, PV1 of C1; PL110 manual 2.1.9, 2.1.11).
    const char *presetsOf = nullptr;
    // Timer areas: the time base of their timers (Vigor T200..T245 10 ms, T246..T249 1 ms),
    // 0: the instruction's or the target's; and how they time (Vigor T246..T255 accumulate:
    // the time is kept while the coil is OFF, RST clears it).
    double timerBaseMs = 0;
    TimerMode timerMode{}; // TimerMode::OnDelay
    // An index register (Vigor Z / V; E / F in PLC concepts (WPLSoft family) 1.4): a word
    // that, written after an operand of an application instruction, adds its value to the
    // element number (D0E0 = D(0 + E0)) or to a constant (K10F0 = 10 + F0); a plain word
    // otherwise.
    bool indexRegister = false;
    // Element n of this area is the double word of words n (high) and n + 1 (low) of the
    // word area with this key (PL110 VD / SMD, PL110 manual 2.1.1: "il numero della doppia
    // word fa sempre riferimento all'organizzazione in word"; SMD20 = SM20 high, SM21 low).
    const char *doubleWordsOf = nullptr;
    // Timer / counter areas that run only while a system bit is ON (enabledWhenOn) or OFF:
    // PL110 SM0.13 "disabilita la gestione dei contatori C[1..16] ed abilita invece la
    // gestione dei timer T[49..64]" (PL110 manual 2.1.2). A box that does not run keeps its
    // value and its bit. nullptr: always runs.
    const char *enabledBy = nullptr;
    bool enabledWhenOn = true;
    // Its prefixAliases name the whole bank (CPM1 "TC 005", Omron CPM1 guide 3.5): the parser
    // makes such an operand the timer or the counter, whichever the program defines with that
    // number.
    bool bankAlias = false;
    // Holds a branch point's condition within a rung (CPM1 TR, W353): driven in many rungs,
    // so a second OUT is no duplicate coil.
    bool branchMemory = false;
    // A bit area a word operand may name: the 16 bits from an element first + 16k are one word
    // (PL110 I1 = I1..I16, I17 = I17..I32; docs/targets.md). Without it a plain bit device is
    // no word operand (Vigor: the Operand Devices tables of the Vigor M/VB/VH communication
    // manual mark X, Y, M, S apart from KnX, KnY, KnM, KnS; CPM1 TR: W353 uses it in LD and OUT
    // only). model::operandBreaches.
    bool bitsAsWords = false;
    // Sub-ranges with other properties (read-only system bits inside a channel area,
    // retentive M ranges on Vigor) are separate Area entries; the parser picks the one that
    // contains the number.
};

// A device address resolved against a target: the area, the element number as written
// (octal areas keep their numeric value, e.g. X10 -> 8) and, for bit access to a word or a
// channel, the bit number.
struct Address {
    int area = -1;
    int index = 0;
    int bit = -1;

    bool valid() const { return area >= 0; }
    friend bool operator==(const Address &, const Address &) = default;
    friend auto operator<=>(const Address &, const Address &) = default;
};

enum class SystemRole : std::uint8_t {
    AlwaysOn,
    FirstScan,
    ScanToggle,
    Clock10ms,
    Clock100ms,
    Clock1s,
    Clock1min,
    Run,
    Error,
    Connected,
    ScanTimeCurrent,
    ScanTimeMin,
    ScanTimeMax,
    // TEST mode (PL110 SM0.5, PL110 manual 2.1.2): while this bit is ON the first
    // SystemDevice::inputs physical inputs read the bits of the InputTestImage word.
    InputTest,
    InputTestImage, // PL110 SM37: bit 0 -> I1 ... bit 7 -> I8
    // The flags the application instructions set (Omron W353 appendix B: ER 25503, CY 25504,
    // GR 25505, EQ 25506, LE 25507); all five go OFF at END. A target that lists them gets
    // them set by every instruction the manual gives an arrow in their column.
    InstructionError,
    Carry,
    Greater,
    Equal,
    Less,
    StepStart, // ON for one cycle when a STEP(08) step starts (W353: SR 25407)
    // The word whose low byte holds the number of the last non-fatal error as two BCD digits
    // (W353 FAL(06): the FAL number in SR 253.00..253.07), 00 when there is none.
    AlarmNumber,
    // The program's choice of 8-bit data (Vigor M9161, Vigor M/VB/VH communication manual,
    // B-3-9: "16-bit mode (M9161=OFF) and 8-bit mode (M9161=ON)"): while ON, CCD and the RS
    // family take one byte, the low one, from each word; OFF, both bytes, low first.
    ByteMode,
    // SMOV moves hexadecimal digits instead of BCD ones while ON (Vigor M9168, set by the
    // program: Vigor M/VB/VH communication manual, B-4-5 "M9168 SMOV hexadecimal").
    HexDigits,
    // Communication (Vigor M/VB/VH communication manual, B-3-3 .. B-3-9; docs/network.md). Driven
    // by the PLC unless the manual says the program writes them (SystemDevice::programWrites).
    LinkCycleDone, // Vigor M9199: ON for one scan when LINK / MBUS completed its table
    RsSendRequest, // Vigor M9122: the program sets it to send, the PLC resets it when sent
    RsReceiveDone, // Vigor M9123: reception ended (n data, end code or time-out)
    RsTimeout,     // Vigor M9129: the reception timed out (reset by the program)
    CommError,     // Vigor M9063: parallel link or RS communication error
    CommErrorCode, // Vigor D9063: RS error code
    RsSendLeft,    // Vigor D9122: data still to send
    RsReceived,    // Vigor D9123: data received
    CommTimeout,   // Vigor D9129: time-out of RS, LINK and MBUS, x 10 ms (0: 100 ms)
    // Vigor CPU Link (B-3-4). SystemDevice::count consecutive devices from the one named.
    CpuLinkFailed,     // M9183 (master), M9184..M9190 (slaves 1..7): communication failed
    CpuLinkTimeout,    // D9172: time-out, x 10 ms
    CpuLinkSlaves,     // D9177: number of slave stations
    CpuLinkRange,      // D9178: transfer range mode
    CpuLinkRetries,    // D9179: retries
    NetworkScanTime,   // D9201: current network scan time (ms)
    NetworkScanMax,    // D9202: maximum network scan time (ms)
    CpuLinkErrorCount, // D9203 (master), D9204..D9210 (slaves 1..7): communication errors
    CpuLinkErrorCode,  // D9212..D9218 (slaves 1..7): 00H none, 01H time-out, 05H sum error
    // Vigor Parallel Link (B-3-5).
    ParallelMaster,    // M9070: this unit is the master
    ParallelSlave,     // M9071: this unit is the slave
    ParallelNormal,    // M9072: parallel operation normal
    ParallelHighSpeed, // M9162: high-speed transfer (the master's decides)
    Other,
};

struct SystemDevice {
    QString device; // as written: "r88", "M9000", "253.13", "SM0.0"
    SystemRole role = SystemRole::Other;
    const char *description = nullptr; // QT_TRANSLATE_NOOP("rung::model::Target", ...)
    // A scan-time word counts in this many microseconds (100: Vigor D9010, PL110 SM6); the
    // one default of the scan-time unit, 1 ms, is here.
    int unitUs = 1000;
    // The manual lets the program write it as well (VPC: drop r88 RUN to stop, raise r89 ERR).
    bool programWrites = false;
    int inputs = 0; // InputTestImage: how many inputs, from the first, the word stands for
    int count = 1;  // consecutive devices of the role from `device` (CpuLinkFailed: 8)
};

// Whether the PLC drives the device so that the program cannot write it (OP002): every role
// but Other (the Vigor M/VB/VH communication manual's programs drive M9100), the status flags
// Error and Connected, and what the manual lets the program write.
bool drivenByPlc(const SystemDevice &device);

enum class ContactMode : std::uint8_t { Normal, Negated, Rising, Falling };

enum class CompareOp : std::uint8_t { None, Eq, Ne, Lt, Le, Gt, Ge };

// The six operators in the order the manuals list their compare contacts (LD=, LD<>, LD<,
// LD<=, LD>, LD>=): the targets' tables make one instruction of each.
inline constexpr CompareOp kCompareOps[] = {CompareOp::Eq, CompareOp::Ne, CompareOp::Lt,
                                            CompareOp::Le, CompareOp::Gt, CompareOp::Ge};

// The operator as listings and the ladder write it: "=", "<>", "<", "<=", ">", ">=".
const char *compareSymbol(CompareOp op);

// An operator written between two operands ("D0<=K5", "D10 > 100"): where it stands and how
// many characters it takes. "=<" and "=>" read as "<=" and ">=" (VPC listings write both).
struct CompareAt {
    CompareOp op = CompareOp::None;
    qsizetype at = 0;
    qsizetype length = 0;
};
// The operator in `text`, the longest symbol first (so "<=" is not read as "<"); never at
// the start, where no operand stands before it. Empty when the text holds none.
std::optional<CompareAt> findCompare(QStringView text);

// Whether "a op b" holds (None never does): the simulator, the monitor's power flow and
// the timing chart's trigger all compare here.
constexpr bool compareHolds(CompareOp op, qint64 a, qint64 b) {
    switch (op) {
    case CompareOp::Eq:
        return a == b;
    case CompareOp::Ne:
        return a != b;
    case CompareOp::Lt:
        return a < b;
    case CompareOp::Le:
        return a <= b;
    case CompareOp::Gt:
        return a > b;
    case CompareOp::Ge:
        return a >= b;
    case CompareOp::None:
        break;
    }
    return false;
}

enum class TransferOp : std::uint8_t { None, Assign, Add, Subtract };

// What may stand in an operand slot.
enum class OperandKind : std::uint8_t {
    BitSource,   // any readable bit device
    BitDest,     // a writable bit device
    WordSource,  // a word device, a timer/counter current value, or a constant
    WordDest,    // a writable word device (timer/counter = its set value on VPC)
    Constant,    // a constant only (K/H, #BCD, plain number)
    TimerNumber, // a timer element
    CounterNumber,
    StepRelay, // Vigor S
    Label,     // jump label number (CPM1 JMP 00..49)
    SetValue,  // timer/counter preset: constant or word device
    Count,     // a repetition count n (ZRST range end is a device, so this is for n only)
    Text,      // a text in double quotes (PL110 MOVTXT, PL110 manual 4.2.10): Operand::Kind::String
};

// A control word whose digits say what an instruction does (W353): checked when it is a
// constant, decoded at run time when it is a channel.
enum class ControlWord : std::uint8_t {
    None,
    BitPair, // MOVB(82) Bi: BCD, digits 1-0 the source bit, digits 3-2 the destination bit, 00..15
    Digits,  // MOVD(83) Di: BCD, digit 0 first source digit, 1 digits - 1, 2 first destination
             // digit (each 0..3), digit 3 zero
};

struct OperandSpec {
    OperandKind kind = OperandKind::BitSource;
    bool optional = false;
    // Narrower rules the manual gives for this slot, checked by model::operandBreaches for
    // `check` and the simulator alike. A constant's value from lowest to highest (PL110 SBIT
    // bit 0..15, Vigor RS m 0..256), and a device's element number when `area` names its area
    // (OUTQI Q1..Q8, II I1..I8).
    int lowest = INT_MIN;
    int highest = INT_MAX;
    std::vector<int> allowedValues; // a constant must be one of these (PL110 time base)
    const char *area = nullptr;     // a device must be of this Area::key ("Q" for OUTQI)
    // A constant that numbers an element of this area (Area::key): Vigor VRRD K1 reads VR1.
    const char *elementOf = nullptr;
    const char *name = nullptr; // QT_TRANSLATE_NOOP("rung::model::Target", "time base")
    // A device in this slot must be of one of these areas (Area::key); constants are free
    // (PL110 presets PT / PV: "da una variabile dell'area VW, SMW, AI e TR", 4.2.4, 4.2.5).
    std::vector<const char *> sourceAreas;
    // A device, no constant: with sourceAreas, of those areas only (Vigor M/VB/VH communication
    // manual, RS S and D, LINK S1 and S2: only the D column is marked); without, any (Vigor CCD
    // S, a block to read).
    bool deviceOnly = false;
    // The slot takes plain words only: no digit-designated bits (K4M0) and no double words
    // (VD0) - block moves count words (Vigor BMOV, PL110 BLKMOV / MOVIND).
    bool wholeWords = false;
    // A constant must be BCD (#0000..#9999): W353 instructions that read BCD (ADD(30) ...).
    bool bcd = false;
    // The last element of a range that starts at operand `rangeFrom`: the same prefix and
    // kind, not before it, every element between them there (model::runBreaks) (SFT(10) /
    // WSFT(16) St E, Vigor ZRST D1 D2); -1: none.
    int rangeFrom = -1;
    // A word whose bits are devices (CPM1 IR, HR, LR channels; not DM): SFT(10).
    bool bitWords = false;
    // Elements from this one the instruction uses, one after another (model::runBreaks):
    // words (MUL(32) / DIV(33): R, R+1; Vigor MUL D, D+1) or bits (Vigor CMP D, D+1, D+2).
    int words = 1;
    // The block from this operand has as many words as the constant of operand `countFrom`
    // (Vigor BMOV S D n, PL110 BLKMOV S D n), every one of them there; -1: none.
    int countFrom = -1;
    // A word operand (Operand::Kind::Text) must be one of these (PL110 FM's operators, 4.2.10).
    std::vector<const char *> allowedTexts;
    ControlWord control = ControlWord::None;
    // OperandKind::Text: its characters are stored one or two to a word (high byte first)
    // from the word of operand `storedFrom`, as many to a word as the constant of operand
    // `charactersPerWord` says (PL110 MOVTXT D n "TEXT", PL110 manual 4.2.10); -1: none.
    int storedFrom = -1;
    int charactersPerWord = -1;
};

// Application-instruction semantics the simulator implements (Op::Apply).
enum class ApplyFunction : std::uint8_t {
    None,
    Mov,
    BlockMove,
    IndirectMove,
    Compare, // Vigor CMP S1 S2 D: D, D+1, D+2 = >, =, <
    ZoneReset,
    Add,
    Sub,
    Mul,
    Div,
    Inc,
    Dec,
    Math, // PL110 FM: operator is the second operand's text
    SetBit,
    ResetBit,
    Toggle, // PL110 bistable relay coil B: each activation (rising edge) flips the bit
    // Word logic, D = S1 op S2 (Vigor WAND/WOR/WXOR S1 S2 D; CPM1 ANDW/ORW/XORW) and
    // D = NOT S (CPM1 COM D, Vigor CML S D).
    AndWord,
    OrWord,
    XorWord,
    Complement,
    ToBcd,   // D = the BCD digits of S (Vigor BCD, CPM1 BCD)
    FromBcd, // D = the value of the BCD digits of S (Vigor BIN, CPM1 BIN)
    NotSimulated,
    // Omron CPM1 (W353), with the arithmetic flags (SystemRole::Carry ...):
    CompareToFlags, // CMP(20) Cp1 Cp2: GR / EQ / LE, unsigned
    ShiftRegister,  // SFT(10) St E: inputs data, shift pulse, reset
    WordShift,      // WSFT(16) St E: St..E one word up, 0000 into St
    MoveNot,        // MVN(22) S D: D = NOT S
    MoveBit,        // MOVB(82) S Bi D: one bit, Bi = BCD dest bit / source bit
    MoveDigit,      // MOVD(83) S Di D: digits, Di = BCD dest digit / count / source digit
    BcdIncrement,   // INC(38) Wd: BCD + 1, 9999 -> 0000
    BcdDecrement,   // DEC(39) Wd: BCD - 1, 0000 -> 9999
    BcdAdd,         // ADD(30) Au Ad R: R = Au + Ad + CY in BCD, CY on a carry
    BcdSubtract,    // SUB(31) Mi Su R: R = Mi - Su - CY, the 10's complement and CY if < 0
    BcdMultiply,    // MUL(32) Md Mr R: R, R+1 = the 8-digit product
    BcdDivide,      // DIV(33) Dd Dr R: R = quotient, R+1 = remainder
    BinaryAdd,      // ADB(50) Au Ad R: R = Au + Ad + CY, CY above FFFF
    BinarySubtract, // SBB(51) Mi Su R: R = Mi - Su - CY, the 2's complement and CY if < 0
    SetCarry,       // STC(40)
    ClearCarry,     // CLC(41)
    SubroutineCall, // SBS(91) N: run subroutine N (SBN(92) N .. RET(93)) and come back
    StepNext,       // SNXT(09) B: end the current step, start the step of control bit B
    // FAL(06) N: a non-fatal error N (01..99) into the SystemRole::AlarmNumber byte, the
    // program goes on; FAL 00 clears it.
    FailureAlarm,
    // Vigor CCD S D n (FX / Delta FNC 84): the sum of n bytes from S into D, their parity
    // (XOR) into D+1; bytes as SystemRole::ByteMode says.
    CheckCode,
    // Vigor instructions of the Vigor M/VB/VH communication manual's communication programs
    // (docs/simulator.md):
    Swap,        // SWAP D: the two bytes of D exchanged
    ToAscii,     // ASCI S D n: the last n hex digits of S as ASCII characters
    FromAscii,   // HEX S D n: n ASCII hex characters from S as a number in D
    ShiftDigits, // SMOV S m1 m2 D n: m2 digits of S from digit m1 into D from digit n
    ReadVolume,  // VRRD K D: the variable resistor VRk (a panel input word) into D
    // Communication instructions: they drive the port InstructionSpec::port names.
    EasyLink,     // Vigor LINK S1 S2 (B-3-3): the master of Computer Link
    ModbusMaster, // Vigor MBUS S1 S2 (B-3-6): the master of MODBUS
    SerialData,   // Vigor RS S m D n (B-3-9): non-protocol send and receive
    ModuleRead,   // Vigor FROM m1 m2 D n: a special module's buffer memory into D
    ModuleWrite,  // Vigor TO / TOP m1 m2 S n: S into a special module's buffer memory
    FreePortSend, // PL110 SEND port n (4.2.19): send n characters of the port's buffer
    MasterQuery,  // PL110 COM / EXP (4.2.21): one interrogation of the port's master
    MoveText,     // PL110 MOVTXT D n "TEXT" (4.2.10): the text's characters from D
    // PL110 SetPAR / FormatPAR / PosPAR (4.2.26..4.2.28): the words of a display field
    // (PanelDisplay::fields, 2.1.2 from SM118) from the instruction's operands.
    PanelFieldSet,
    PanelFieldFormat,
    PanelFieldPosition,
};

// Timer behaviours beyond the plain on-delay (PL110 TOFF / TONR).
enum class TimerMode : std::uint8_t { OnDelay, OffDelay, Accumulating };

// Counter direction where one family has both (PL110 MUP counts up to PV, MDOWN down to 0).
enum class CounterMode : std::uint8_t { Up, Down };

struct InstructionSpec {
    QString mnemonic;      // canonical spelling as the printer writes it: "LD NOT", "LDI"
    QStringList aliases;   // other accepted spellings: "LD*", "KEEP(11)", "AND LD"
    int functionCode = -1; // CPM1 function code, accepted as MNEMONIC(NN)
    Op op = Op::Nop;
    ContactMode mode = ContactMode::Normal; // for contacts
    CompareOp compare = CompareOp::None;    // compare contacts
    bool negated = false;                   // OUT NOT, OUT*, LD NOT (with mode = Negated)
    TransferOp transfer = TransferOp::None;
    ApplyFunction function = ApplyFunction::None;
    int inputs = 1;            // blocks consumed by an output instruction (LR/KEEP: 2, CNTR: 3)
    bool fusedOperand = false; // VPC TIM00, CNT05: the element number is part of the mnemonic
    std::vector<OperandSpec> operands;
    const char *summary = nullptr; // QT_TRANSLATE_NOOP("rung::model::Target", ...) for call tips
    const char *operandHelp = nullptr; // e.g. "T0..T255 K1..K32767"; untranslated syntax
    int steps = 1;                     // program memory the instruction occupies (words / steps)
    double timerBaseMs = 0; // Op::Timer: its own time base (CPM1 TIMH(15): 10 ms); 0: the target's
    TimerMode timerMode = TimerMode::OnDelay;  // Op::Timer
    CounterMode counterMode = CounterMode::Up; // Op::UpDownCounter
    // The differentiated form ("@MOV(21)", W353): runs once when its condition turns ON.
    bool differentiated = false;
    // The 32-bit form (the FX family's D prefix, Vigor DMOV): each word operand is the pair
    // D (low word), D+1 (high word), or one 32-bit device; constants are 32-bit.
    bool doubleWord = false;
    // A communication instruction: the port it drives (Target::ports; PL110 SEND names it in
    // its first operand: null) and the applications that port must run for it.
    const char *port = nullptr;
    std::vector<const char *> portApplications;
    // The operand that numbers or names the port: a constant appended to `port` (Vigor FROM K1:
    // MODULE1), or a word that is the port's name (PL110 SEND COM1 n); -1: `port` alone.
    int portOperand = -1;
    // The manual allows it once in a program (Vigor M/VB/VH communication manual, B-3-3, B-3-6:
    // LINK, MBUS "can be used once only in the program"): model::onceOnlyBreaches.
    bool oncePerProgram = false;
};

struct Limits {
    int programSteps = 0;             // program length in steps / lines / words
    int stackDepth = 8;               // MPS levels
    int contactsPerRow = 11;          // ladder row width (contacts before the output column)
    int maxBlocksInRow = 8;           // consecutive ANB/ORB allowed (0 = no limit)
    int jumpLabels = 0;               // JMP N range (CPM1: 50)
    bool allowsStack = false;         // MPS/MRD/MPP exist
    bool duplicateCoilIsError = true; // VPC/CPM1 error, Vigor warning
    bool outputNeedsCondition = true;
    // Word values are decimal numbers of this many digits (VPC registers, timers and counters
    // hold 0000..9999, VPC user's manual, III); 0: binary words of Area::wordBits.
    int decimalDigits = 0;
    // A timer's current value stops here (PL110 manual 4.2.4: saturates at 32767).
    std::int64_t timerMax = 32767;
    // Where saturating up/down counters stop (Semantics::upDownCountersSaturate; PL110 MUP /
    // MDOWN, PL110 manual 4.2.5: the C word's -32768..32767; MDOWN stops at 0 besides).
    std::int64_t counterMin = -32768;
    std::int64_t counterMax = 32767;
    // The scan-time system words (SystemRole::ScanTime*) stop here: one 16-bit word.
    std::int64_t scanTimeMax = 32767;
};

// How a target writes constants; parseConstant / formatConstant (address.cpp) and the listing
// parser read these rules and nothing else. A target accepts every form it sets.
struct ConstantNotation {
    bool prefixed = false;  // K10 decimal, H1F hexadecimal (Vigor; PLC concepts (WPLSoft family))
    bool bcd = false;       // #0150 four BCD digits, #00FF a hexadecimal word (Omron CPM1 guide)
    bool plain = false;     // a bare number: 150, -3 (VPC, PL110)
    bool hashPlain = false; // '#' only marks a plain number (PL110: PLProg writes "MOV(Tx = #0)")
    // Timer/counter set values are BCD: a # constant or a channel holding BCD digits (CPM1
    // TIM/CNT, Omron CPM1 guide); the simulator decodes the channel, the parser refuses other
    // forms.
    bool bcdSetValues = false;
    // A constant slot that holds no number keeps the word verbatim (PL110 FM operators and
    // time bases); otherwise it is a constant error.
    bool wordsInConstantSlots = false;
    // Kn before a bit device is a word of n groups of 4 bits from it (K4Y0 = Y0..Y17 on an
    // octal area, K1M20 = M20..M23), n = 1..digitGroups in word operands (Vigor 4: its
    // instructions are 16-bit; as in PLC concepts (WPLSoft family)). 0: the target has none.
    int digitGroups = 0;
};

// A register whose value appears bit by bit on a run of bit devices, or the other way round
// (VPC p76 -> o00..o11, i00..i11 -> p77, VPC user's manual, III). Device texts are parsed with
// the target's own address rules.
struct ParallelPort {
    QString word;     // "p76"; empty: the target has no such port
    QString firstBit; // the least significant bit: "o00"
    int bits = 0;     // how many bits follow it (12); the word's value is taken modulo 2^bits
};

// Execution facts the simulator reads (docs/simulator.md), one field per difference a
// manual describes.
struct Semantics {
    // Coils write an image that contacts see from the next scan on (VPC user's manual).
    bool deferredBitWrites = false;
    // Timers / counters with a lower element number count down from the set value
    // (VPC TIM00..15 / CNT00..15; every CPM1 TIM / CNT).
    int downTimersBelow = 0;
    int downCountersBelow = 0;
    // The timer's current value is the count of time-base units kept in its word, so a write
    // to the word changes the timing (PL110 TON / TOFF / TONR, PL110 manual 4.2.4: MOV(Tx = #0)
    // resets a TONR); the time base may be named as the timer's third operand (its
    // OperandSpec::allowedValues). Otherwise the elapsed time is the timer's own state.
    bool timerCountsInWord = false;
    // Up/down counters saturate at the limits of their word (PL110 MUP / MDOWN, PL110 manual
    // 4.2.5) instead of wrapping around (CPM1 CNTR(12)).
    bool upDownCountersSaturate = false;
    ParallelPort parallelOut; // VPC p76
    ParallelPort parallelIn;  // VPC p77
};

// Devices the program reads and writes as memory while the PLC does more with them than the
// simulator models (PL110 SM100..SM185: the display's pages and parameters, SM110 the keys;
// PL110 manual 2.1.2): `check` warns (SIM101) at each use, naming the device and `what`.
struct UnmodelledDevices {
    QString first;              // the first device of the range, as written: "SM100"
    QString last;               // the last one, inclusive: "SM109"
    const char *what = nullptr; // QT_TRANSLATE_NOOP("rung::model::Target", ...): what is missed
};

// A block of a model's terminals as its terminal strip groups them (Vigor X0..X7, CPM1
// channel 000 bits 00..11, PL110 I1..I8, VPC a00..a03): the simulator's I/O panel draws one
// group per block. An area the program cannot write (Area::writable false) is an input,
// else an output.
struct TerminalBlock {
    QString area;  // Area::key
    int first = 0; // first element; a channel area with bit terminals: the channel
    int count = 0; // elements; a channel area with bit terminals: its bits from bit 0
    // Word terminals (analog inputs and outputs, the CPM1's analog setting pots): the values
    // a terminal takes, and whether the word holds them as BCD digits (CPM1 0..200). Bit
    // terminals leave both 0.
    int lowest = 0;
    int highest = 0;
    bool bcd = false;
    // QT_TRANSLATE_NOOP("rung::model::Target", ...): what the block is when its devices do
    // not say it ("analog settings"); null: the devices' range names it.
    const char *label = nullptr;
    bool words() const { return highest > lowest; }
};

// A model (hardware variant) narrows the areas: I/O counts, analog channels.
struct ModelVariant {
    QString name; // "VPC2416", "VB", "CPM1-20CDR", "PL110-1A"
    struct Override {
        QString area; // Area::key of the area it narrows
        int first = 0;
        int last = -1; // last < first: the area does not exist on this model
    };
    std::vector<Override> overrides;
    int programSteps = 0; // 0 = the family's limit
    // The base unit's terminals, in strip order (inputs, outputs, analog), as the manual
    // lists them for this model.
    std::vector<TerminalBlock> terminals;
};

// The PLC's own words for a class of program error (VPC user's manual, VI, the VPC console:
// "IL (JMP) missing", "IL-JMP interlace", "Oper duplication"), quoted after the product's
// message so the user recognises the console's text; nullptr where the family's manual gives
// none.
struct ConsoleTexts {
    const char *blockMissing = nullptr; // ILC / JPE without IL / JMP
    const char *interlace = nullptr;    // IL and JMP closed out of order
    const char *duplicate = nullptr;    // a coil driven twice
};

class Target {
public:
    Family family;
    QString id;          // "vpc", "vigor", "cpm1", "pl110" (command-line and file key)
    QString displayName; // "VPC", "Vigor M/VB/VH", "Omron CPM1", "PL110"
    std::vector<Area> areas;
    std::vector<SystemDevice> systemDevices;
    std::vector<UnmodelledDevices> unmodelled; // what the simulator leaves as plain memory
    std::vector<InstructionSpec> instructions;
    std::vector<ModelVariant> models;
    Limits limits;
    double defaultTimerBaseMs = 100.0; // Vigor TMR default resolution
    ConstantNotation constants;
    Semantics semantics;
    std::vector<ProtocolMap> protocolMaps;       // protocol_map.h: where devices sit on the wire
    std::vector<PortSpec> ports;                 // port_spec.h: the serial ports and what they run
    std::vector<LinkDeviceCode> linkDeviceCodes; // port_spec.h: LINK / MBUS device types
    ConsoleTexts console;
    FrontPanel panel; // front_panel.h: lamps, display, knobs, keys as the manual shows them

    // The four families, built once.
    static const Target &get(Family family);
    // The target a new, empty document starts with.
    static const Target &defaultTarget();
    static const Target *byId(const QString &id); // nullptr when unknown
    static std::span<const Family> families();

    const ModelVariant *model(const QString &name) const; // nullptr when unknown
    const ModelVariant &defaultModel() const;

    // Instruction lookup by spelling (case-insensitive, aliases and "NAME(NN)" accepted).
    const InstructionSpec *findInstruction(const QString &mnemonic) const;
    // The canonical instruction for an operation, as the converter emits it.
    const InstructionSpec *findInstruction(Op op, ContactMode mode = ContactMode::Normal,
                                           CompareOp compare = CompareOp::None,
                                           bool negated = false) const;
    int indexOf(const InstructionSpec *spec) const;

    const Area &area(int index) const { return areas[static_cast<std::size_t>(index)]; }
    // Every spelling of every area's prefix (Area::prefix and prefixAliases) as parseAddress
    // compares it: without spaces, upper case. Built by buildIndex (again after a change of
    // the areas); parseAddress computes them itself for a table not yet indexed.
    struct PrefixSpelling {
        QString text;
        int area = 0;
    };
    const std::vector<PrefixSpelling> &prefixSpellings() const { return m_prefixes; }
    std::vector<PrefixSpelling> makePrefixSpellings() const;
    // Effective range of an area on a model (after the model's overrides); nullopt = absent.
    std::optional<std::pair<int, int>> range(int areaIndex, const ModelVariant *model) const;
    const SystemDevice *systemDevice(SystemRole role) const;
    // The port named (case-insensitive), nullptr when the target has none of that name.
    const PortSpec *port(QStringView name) const;

    // Builds the spelling index findInstruction(text) uses; the registry calls it once.
    void buildIndex();

private:
    QMultiHash<QString, int> m_spellings; // normalized mnemonic or alias -> instruction index
    std::vector<PrefixSpelling> m_prefixes;
};

} // namespace rung::model
