#pragma once

// The executable form of an instruction list: one Step per instruction with every operand
// resolved to an index into the flat memory of a MemoryLayout. Built once by compileProgram()
// (compiler.h) and scanned by the Engine (engine.h) without looking at text or the target.

#include "model/checks/diagnostic.h"
#include "model/image/bcd.h"
#include "model/image/memory_layout.h"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

namespace rung::simulator {

// The memory image belongs to the model (comms fills the same one from a real PLC); the
// simulator names its parts without the prefix.
using model::AreaLayout;
using model::BitRef;
using model::MemoryLayout;
using model::wrapToWidth;

enum class Code : std::uint8_t {
    // contacts; Load* at a rung start do not push (Step::flags & kRungStart)
    Load,
    And,
    Or,
    LoadEdge,
    AndEdge,
    OrEdge,
    LoadCompare,
    AndCompare,
    OrCompare,
    AndBlock,
    OrBlock,
    Push,
    ReadStack,
    Pop,
    Invert,
    EdgeFlow, // PL110 P / N: the power flow for one scan on its rising (falling) edge
    // outputs
    Out,
    Set,
    SetStep, // SET of a step relay inside an STL block: the current step is reset
    Reset,   // resets a list of targets (bits, words, timer/counter elements)
    Pulse,
    Toggle, // PL110 OUTB: each rising edge of the condition flips the bit
    Keep,
    Timer,
    Counter,
    UpDownCounter,
    PlTimer,   // PL110 TON / TOFF / TONR (op = PlTimerMode); current value = time base units
    PlCounter, // PL110 MUP / MDOWN (kDown): UP, DOWN, RESET; current value saturates; the
               // bit is compared at END (Program::endOfScanCounters)
    Transfer,
    Move,
    Compare,
    Add,
    Sub,
    Mul,
    Div,
    Inc,
    Dec,
    Math,         // PL110 FM: op = MathOp
    WordLogic,    // dest = x op y (op = WordOp): WAND/ANDW ..., CML/COM, BCD, BIN
    BlockMove,    // x = first source word (or a constant to fill), dest = first word, count
    IndirectMove, // PL110 MOVIND: dest + value of y := x; count = words from dest to area end
    // Vigor DMOV (32 bits): x = the source, y = its high word (index < 0: x is a 32-bit word
    // or a constant); dest = the low word, slot = the high word (-1: dest is 32-bit).
    DoubleMove,
    // Vigor CCD: x = the first source word, count = bytes, bit = the 8-bit mode flag (invalid:
    // always 16-bit), dest = the sum, slot = the parity, y.constant = the words from x to the
    // end of its area (engine_words.cpp).
    CheckCode,
    // Vigor SWAP D (dest), ASCI S D n / HEX S D n (x, dest, count = n; bit = the 8-bit mode
    // flag; y.constant = words from dest (ASCI) or x (HEX) to the end of its area), SMOV
    // S m1 m2 D n (x, dest; op = m1, count = m2, width-independent slot = n; bit = M9168's
    // hexadecimal mode); engine_text.cpp.
    Swap,
    ToAscii,
    FromAscii,
    ShiftDigits,
    // DDIV S1 S2 D (32 bits): Program::wordLists from slot: S1 low, S1 high (or -1 with
    // x.constant), S2 low, S2 high (or -1 with y.constant), D, D+1, D+2, D+3.
    DoubleDivide,
    // A communication instruction (LINK, MBUS, RS, FROM, TO, SEND, COM / EXP): count =
    // Program::comms index (slot is TOP's edge); FROM / TO of a digit group: the word in dest
    // / x; engine_comm.cpp. Runs every scan, ON or OFF.
    Communicate,
    // PL110 MOVTXT (4.2.10): count words from Program::constants[slot] into dest and on.
    MoveConstants,
    // Omron CPM1 (W353), with the arithmetic flags (Program::flags): op = ArithOp; engine_cpm1.cpp
    Arithmetic,
    ShiftRegister, // SFT(10): data, shift pulse (edge slot), reset; dest = St, count = words
    // control
    SubroutineCall,   // SBS(91): count = the SBN(92) to run
    SubroutineStart,  // SBN(92): the main program ends here; slot = END (or the list's end)
    SubroutineReturn, // RET(93): back after the SBS(91) that called
    StepDefine,       // STEP(08) B: bit = B (invalid: the end of the steps); slot = edge slot
    StepNext,         // SNXT(09) B: bit = B; slot = bitLists index of the current step's bit
    Interlock,
    InterlockClear,
    Jump,
    JumpEnd,
    StepLadder,
    Return,
    End,
    Nop,
};

enum StepFlag : std::uint16_t {
    kNegated = 1, // NOT contacts, OUT NOT, OUT* transfers (run while the condition is OFF)
    kFalling = 2, // falling-edge contacts, PLF / DIFD, PL110 N
    kDown = 4,    // timers / counters that count down from the set value
    kBcd = 8,     // set value read from a word holds BCD digits (CPM1)
    kRungStart = 16,
    kOneInput = 32, // counter reset only by RST (Vigor)
    kDecimal4 = 64, // VPC transfer: the result is a four-digit decimal 0..9999 (VPC user's manual)
    kResolve = 128, // an operand is an OperandRef (x, y, dest or slot <= kRefBase): see below
    // The differentiated form (W353 "@MOV(21)"): runs once when its condition turns ON; the
    // edge memory is `slot`, which no code that can be differentiated uses otherwise.
    kDifferentiated = 256,
};

// Code::Arithmetic (W353): what the step does. x, y: sources; dest: result; count: the
// result's second word (MUL / DIV) or the words of a range (WSFT).
enum class ArithOp : std::uint8_t {
    Compare,   // CMP(20): GR / EQ / LE from x, y unsigned
    MoveNot,   // MVN(22)
    MoveBit,   // MOVB(82): y = control word
    MoveDigit, // MOVD(83): y = control word
    WordShift, // WSFT(16): dest .. dest + count - 1
    BcdIncrement,
    BcdDecrement,
    BcdAdd,
    BcdSubtract,
    BcdMultiply,
    BcdDivide,
    BinaryAdd,
    BinarySubtract,
    SetCarry,
    ClearCarry,
    FailureAlarm, // FAL(06) N: x = N, dest = the SystemRole::AlarmNumber word (-1: none)
};

// The bits the application instructions set (model::SystemRole::InstructionError ...); an
// invalid BitRef where the target has none.
struct ArithmeticFlags {
    BitRef error, carry, greater, equal, less, stepStart;
    bool any() const { return error.valid() || carry.valid() || equal.valid(); }
};

enum class TransferKind : std::uint8_t { Assign, Add, Subtract };

enum class PlTimerMode : std::uint8_t { OnDelay, OffDelay, Accumulating };

// Code::Timer's op: the timer keeps its time while its coil is OFF (Vigor T246..T255).
constexpr std::uint8_t kTimerAccumulates = 1;

enum class WordOp : std::uint8_t { And, Or, Xor, Not, ToBcd, FromBcd };

// CPM1 #0150 constants, Vigor / CPM1 BCD (model/image/bcd.h).
using model::toBcd;

enum class MathOp : std::uint8_t { Add, Sub, Mul, Div, Or, And, Xor, Shl, Shr };

// An operand the compiler cannot reduce to one word of the image (docs/simulator.md,
// "Operands resolved at run time"): a digit-designated group of bits (Vigor K4Y0), an operand
// modified by an index register (D0E0, K4M0E1, K10F0), a double word (PL110 VD0 = V0 high,
// V1 low). A step holding one has kResolve; the engine resolves its operands into a copy of
// the step before running it (engine_operands.cpp).
struct OperandRef {
    enum class Kind : std::uint8_t { Word, Bits, Constant, DoubleWord };
    Kind kind = Kind::Word;
    std::int32_t area = -1;      // model area of the base (names it in a runtime error)
    std::int32_t element = 0;    // element number of the base; Constant: the value
    std::int32_t index = -1;     // the index register's word, -1: none
    std::int32_t indexArea = -1; // the index register's model area and element (messages)
    std::int32_t indexElement = 0;
    std::int32_t bits = 0;         // Bits: how many, from the element on
    std::int32_t word = -1;        // DoubleWord: the high word (the low word follows it)
    std::int32_t firstSegment = 0; // Program::segments of the areas sharing the base's prefix
    std::int32_t segmentCount = 0;
    std::int32_t operand = 0; // index of the operand in its instruction (for messages)
};

// The elements first..last of an area and where they sit in the image: packed bits from
// word `base` (bits) or one word each from `base`.
struct Segment {
    std::int32_t first = 0;
    std::int32_t last = -1;
    std::int32_t base = -1;
    std::uint8_t wordBits = 16;
    bool bits = false;
};

// x.index, y.index, dest and (MUL / DIV) slot hold -2 - k for OperandRef k.
constexpr std::int32_t kRefBase = -2;
constexpr std::int32_t refCode(std::size_t ref) {
    return kRefBase - static_cast<std::int32_t>(ref);
}
constexpr std::size_t refOf(std::int32_t code) {
    return static_cast<std::size_t>(kRefBase - code);
}

// A word operand: a memory word, or a constant when index < 0.
struct WordOperand {
    std::int32_t index = -1;
    std::int32_t constant = 0;
};

// What RST / ZRST clear.
struct ResetTarget {
    BitRef bit;              // bit device or a timer/counter done bit
    std::int32_t word = -1;  // word device or a timer/counter current value
    std::int32_t state = -1; // timer/counter element state
};

struct Step {
    Code code = Code::Nop;
    std::uint16_t flags = 0;
    std::uint8_t op = 0;     // CompareOp / TransferKind
    std::uint8_t width = 16; // destination width in bits
    BitRef bit;              // contact, coil, done bit
    WordOperand x, y;        // sources (timers/counters: x = set value)
    std::int32_t dest = -1;  // destination word (timers/counters: current value)
    std::int32_t slot = -1;  // edge slot, element state, jump target, list start
    std::int32_t count = 0;  // list length; timers: time base in ms
};

// The plain scan's form of a step (Engine::runFast, engine_fast.cpp): one per Step, same
// index, 16 bytes (and a Stop after the last), so that the loop a whole scan runs reads a quarter
// of the Step array and tests no flag at run time. What the fast loop does not run itself (Slow)
// goes to the full interpreter for that one step; the other ops read anything beyond a bit from the
// Step.
enum class FastOp : std::uint8_t {
    Slow,
    LoadStart, // LD at a rung start: the block and push stacks empty
    LoadStartNot,
    Load, // LD inside a rung: the accumulator goes onto the block stack
    LoadNot,
    And,
    AndNot,
    Or,
    OrNot,
    LoadEdge, // LDP / LDF ..., the edge memory in the Step's slot
    AndEdge,
    OrEdge,
    AndBlock,
    OrBlock,
    Push,
    ReadStack,
    Pop,
    Invert,
    Out,
    OutNot,
    Set,
    Reset,
    Timer,
    Counter, // Code::Counter, either form
    Move,
    Add,
    Sub,
    Inc,
    Dec,
    Nop, // NOP, JPE / JME
    End,
    // Runs of steps as one (the first step's op; the others keep theirs, so a jump may still
    // land inside). A contact's `flip` says whether it is negated.
    SeriesStart2, // LD / LDI a, AND / ANI b
    SeriesAnd2,   // AND / ANI a, AND / ANI b
    ParallelAnd,  // LD / LDI a, OR / ORI b, ANB: a two-contact branch in series
    SeriesOr,     // LD / LDI a, AND / ANI b, ORB: a two-contact series in parallel
    BranchOut,    // MPS, AND / ANI a, OUT y, MPP: an output branch with a contact
    BranchOutNot, // the same with OUTN y
    // A timer or counter with a BCD set value or on a gated element (Area::enabledBy): the
    // full body (engine_timers.h). Timer and Counter are the others.
    TimerFull,
    CounterFull,
    // 16-bit word moves and sums without the W353 flags, operands in the fast step (word =
    // the destination, mask = x, flip = y; a K operand is its value): no Step read.
    MoveWord16,
    MoveConst16,
    AddWordConst16,
    AddWordWord16,
    SubWordConst16,
    SubWordWord16,
    // Control that only changes the interpreter's registers (the interlock, the step ladder)
    // or the next step: word = the bit (STL), the target step (JMP / CJ).
    StepLadder,
    Return,
    Interlock,
    InterlockClear,
    SetStep,
    Jump,
    // A timer counting up (not retentive) and a one-input 16-bit counter counting up, each
    // with a K set value in binary on an ungated element: FastStep::element(), all it needs.
    TimerK,
    CounterK,
    // A rung's first contact (LD / LDI, `flip`) and the step after it, which keeps its op: a
    // timer, a counter, a 16-bit move or a coil on one contact.
    LoadStartTimerK,
    LoadStartCounterK,
    LoadStartMoveWord16,
    LoadStartMoveConst16,
    LoadStartOut,
    SeriesStartOr, // LD / LDI a, AND / ANI b, OR / ORI c: a rung's start with a holding contact
    // The runs above whose contacts are none negated (LD, AND, OR): no negation to apply.
    SeriesStart2P,
    SeriesAnd2P,
    ParallelAndP,
    SeriesOrP,
    BranchOutP,
    BranchOutNotP,
    SeriesStartOrP,
    Stop, // after the last step: the list ended without END
};

struct FastElement;

struct FastStep {
    FastOp op = FastOp::Slow;
    // Contacts and coils: the bit (Step::bit). Ops that read their Step: its byte offset in
    // Program::steps. TimerK / CounterK: the element's index in Program::fastElements.
    std::int32_t word = -1;
    std::uint32_t mask = 0;
    // Negated contacts: the mask, so that ((word ^ flip) & mask) is the contact's value;
    // other contacts 0. Coils (OUT, OUTN, SET): ~mask, what a write keeps of the word.
    std::uint32_t flip = 0;

    // FastOp::TimerK / CounterK: their element in Program::fastElements, held in the bytes of
    // mask and flip. A pointer rather than an offset: the loop keeps no base for the elements
    // in a register (callgrind: 20,017 -> 19,503 instructions a scan of the benchmark).
    const FastElement *element() const {
        const FastElement *e = nullptr;
        std::memcpy(&e, reinterpret_cast<const unsigned char *>(this) + kElementAt, sizeof e);
        return e;
    }
    void setElement(const FastElement *e) {
        std::memcpy(reinterpret_cast<unsigned char *>(this) + kElementAt, &e, sizeof e);
    }
    static constexpr std::size_t kElementAt = 8; // where mask starts, flip after it
};
static_assert(offsetof(FastStep, mask) == FastStep::kElementAt &&
              offsetof(FastStep, flip) == FastStep::kElementAt + 4 &&
              sizeof(FastStep) == FastStep::kElementAt + sizeof(const FastElement *));

// What FastOp::TimerK / CounterK read (Program::fastElements): the Step's operands with the set
// value and what follows from it worked out when the program is compiled.
struct FastElement {
    std::int32_t state = 0;    // the element's state: its byte offset in the engine's states
    std::int32_t dest = -1;    // the current value's word
    std::int32_t setWord = -1; // the word the set value is copied to (Step::y; else dest)
    std::int32_t bitWord = 0;  // the done bit
    std::uint32_t bitMask = 0;
    std::uint32_t bitKeep = ~0u; // ~bitMask (Engine::writeBit)
    std::int32_t set = 0;        // the K value, not below 0
    std::int32_t base = 1;       // timers: the time base in ms
    std::int64_t limitMs = 0;    // timers: set * base, where the accumulated time stops
    // Timers: accumulated ms / base as (ms * magic) >> kFastDivShift, exact while the ms stay
    // below 2^25 (buildFastSteps keeps the others on FastOp::Timer).
    std::uint64_t magic = 0;
};
inline constexpr int kFastDivShift = 38;
// The size of the engine's state of a timer or counter (Engine::ElementState, checked there).
inline constexpr std::size_t kElementStateBytes = 16;

// A system device the engine drives at the start of every scan.
struct SystemBinding {
    model::SystemRole role = model::SystemRole::Other;
    BitRef bit;
    std::int32_t word = -1;
    int unitUs = 0; // scan-time words: microseconds per count, SystemDevice::unitUs
};

// A timer / counter element that runs only while a bit is ON (whenOn) or OFF
// (Area::enabledBy; PL110 SM0.13 for T49..T64 and C1..C16).
struct ElementGate {
    BitRef bit; // invalid: always runs
    bool whenOn = true;
};

// What a communication instruction does (Code::Communicate's op).
enum class CommKind : std::uint8_t {
    EasyLink,     // Vigor LINK S1 S2
    ModbusMaster, // Vigor MBUS S1 S2
    SerialData,   // Vigor RS S m D n
    ModuleRead,   // Vigor FROM m1 m2 D n
    ModuleWrite,  // Vigor TO / TOP m1 m2 S n
    FreePortSend, // PL110 SEND port n
    MasterQuery,  // PL110 COM / EXP index op slave type number area count
};

// A communication instruction's operands (Program::comms; docs/network.md).
struct CommStep {
    CommKind kind = CommKind::EasyLink;
    QString port;          // the port it drives (Target::ports)
    std::int32_t step = 0; // its instruction
    // Its table entry: the mnemonic and the applications its port must run (the network's
    // wiring and check read them).
    const model::InstructionSpec *spec = nullptr;
    std::int32_t first = -1;  // LINK / MBUS S1, RS S, FROM D, TO S (-1: a digit group, in the
                              // step), COM's area
    std::int32_t second = -1; // LINK / MBUS S2 (4 words), RS D
    // Words from first / second to the end of their area: a block must stay inside.
    std::int32_t firstWords = 0;
    std::int32_t secondWords = 0;
    WordOperand m, n;        // RS m, n; FROM / TO: m = the buffer memory word, n = the words;
                             // SEND: n = the characters
    std::int32_t module = 0; // FROM / TO: the module number m1
    // PL110 COM / EXP (4.2.21): index 1..16, operation 0 read / 1 write / 2 read-write,
    // slave, 1 = bits, data number, count; the area is `first` (words) or `bits`.
    std::int32_t index = 0;
    std::int32_t operation = 0;
    std::int32_t slave = 0;
    bool bitData = false;
    std::int32_t number = 0;
    std::int32_t count = 0;
    std::vector<BitRef> bits;
    std::vector<std::int32_t> words; // COM / EXP of words: the area's words, in order
    std::int32_t portIndex = -1;     // SEND, COM / EXP: Program::ports index (-1: none)
};

// A port's special markers and byte buffers (model::PortMarkers, PL110 manual 2.1.2, 2.1.14,
// 2.1.15), resolved: word indices, -1 / invalid where the target has none.
struct PortDevices {
    QString port;
    const model::PortMarkers *markers = nullptr; // the codes of SM78
    std::int32_t status = -1;
    std::int32_t replyTimeout = -1;
    std::int32_t requestGap = -1;
    std::int32_t errorLimit = -1;
    std::int32_t timeouts = -1;
    std::int32_t errors = -1;
    std::int32_t freePort = -1;
    std::int32_t received = -1;
    BitRef sending;
    std::int32_t transmit = -1; // the first byte's word, and the bytes
    std::int32_t transmitSize = 0;
    std::int32_t receive = -1;
    std::int32_t receiveSize = 0;
};

// The system devices communication drives or reads (model::SystemRole), invalid / -1 where
// the target has none.
struct CommDevices {
    BitRef cycleDone;   // LinkCycleDone
    BitRef sendRequest; // RsSendRequest
    BitRef receiveDone; // RsReceiveDone
    BitRef timeout;     // RsTimeout
    BitRef error;       // CommError
    BitRef byteMode;    // ByteMode
    std::int32_t errorCode = -1;
    std::int32_t sendLeft = -1;
    std::int32_t received = -1;
    std::int32_t timeoutWord = -1;
};

struct Program {
    Program() = default;
    // Program::fast points into fastElements (FastStep::element): a copy would point into the
    // original's.
    Program(const Program &) = delete;
    Program &operator=(const Program &) = delete;

    std::shared_ptr<const MemoryLayout> layout;
    std::vector<Step> steps;    // index = instruction index in the list
    std::vector<FastStep> fast; // one per step and a Stop (buildFastSteps, compile_fast.cpp)
    std::vector<FastElement> fastElements; // FastOp::TimerK / CounterK
    // The fast loop's guarded form (buildFastSteps): some step may turn the gate OFF (STL,
    // STEP(08), MC / IL and what ends them), so every contact reads it; or a step may move
    // the scan elsewhere (a jump, a subroutine) or a rung hold more LDs or MPSs than the
    // stacks, so the stacks' bounds are tested. Without, the steps' order bounds the stacks.
    bool guarded = false;
    std::vector<int> lines; // source line of each step
    std::vector<BitRef> bitLists;
    std::vector<ResetTarget> resets;
    std::vector<OperandRef> refs; // operands resolved at run time (kResolve)
    std::vector<Segment> segments;
    std::vector<SystemBinding> system;
    int edgeSlots = 0;
    int maxBlockDepth = 0;
    int maxPushDepth = 0;
    // VPC: bit writes land in a write image that becomes visible at END (docs/simulator.md).
    bool deferredBitWrites = false;
    // Some step has kResolve or kDifferentiated: without one, a scan runs a loop that never
    // tests for them (Engine::execute's Special).
    bool specialSteps = false;
    std::int64_t timerMax = 0;   // a timer's current value saturates here (Limits::timerMax)
    std::int32_t counterMin = 0; // saturating up/down counters (Limits::counterMin / Max)
    std::int32_t counterMax = 0;
    std::int64_t scanTimeMax = 0; // the scan-time words stop here (Limits::scanTimeMax)
    std::vector<std::pair<int, int>> bitWordRanges; // [begin, end) words holding bits
    // Semantics::parallelOut / parallelIn (VPC p76 / p77); -1: none.
    std::int32_t parallelOutWord = -1;
    bool writesParallelOut = false;
    std::int32_t parallelInWord = -1;
    std::vector<BitRef> parallelOutBits; // LSB first
    std::vector<BitRef> parallelInBits;
    // PL110 MUP / MDOWN steps whose count bit is compared at END (PL110 manual 4.2.5).
    std::vector<std::int32_t> endOfScanCounters;
    // Per timer / counter element state slot; empty when no area has Area::enabledBy.
    std::vector<ElementGate> gates;
    // Constant presets the program may read and write (PL110 PT/PV): (set-value word, value),
    // loaded when the engine starts and at each power cycle.
    std::vector<std::pair<std::int32_t, std::int32_t>> presetLoads;
    // The PL110-2A's terminal (model::PanelDisplay, PL110 manual 2.1.2 SM102..SM106, SM110):
    // between scans the page request is shown and reset, the SWAP key steps through the pages
    // enabled, the page shown is kept in its word. pageShown -1: no terminal.
    struct TerminalPages {
        std::int32_t systemPages = -1, userPages = -1, startPage = -1, pageShown = -1,
                     pageRequest = -1;
        // The note of the last variable stored from the keys (SM107, SM108): cleared at the
        // end of every scan, so a program sees it in the one scan after the store.
        std::int32_t lastArea = -1, lastNumber = -1;
        BitRef swap;
        int systemCount = 0, firstUser = 0, userCount = 0;
    } terminal;
    // TEST mode (PL110 SM0.5 / SM37): while inputTest is ON the inputs inputTestBits read
    // the bits of inputTestWord instead of the terminals.
    BitRef inputTest;
    std::int32_t inputTestWord = -1;
    std::vector<BitRef> inputTestBits; // the inputs, bit 0 of the word first
    ArithmeticFlags flags;             // turned OFF at END (W353 appendix B)
    // physical inputs refreshed from the stimulus image: [begin, end) words
    std::vector<std::pair<int, int>> inputWordRanges;
    // Word indices a step reads from a list (DDIV's eight words).
    std::vector<std::int32_t> wordLists;
    // Values a step writes from a list (MOVTXT's characters, Code::MoveConstants).
    std::vector<std::int32_t> constants;
    // Communication instructions; empty: the scan's END does no communication work.
    std::vector<CommStep> comms;
    CommDevices commDevices;
    // The ports the program drives through their markers (PL110 free-port, COM / EXP);
    // empty: none. The scan's END serves them.
    std::vector<PortDevices> ports;
};

struct CompileResult {
    std::shared_ptr<const Program> program;     // null when there are errors
    std::vector<model::Diagnostic> diagnostics; // errors, and "not simulated" warnings
    bool ok() const { return program != nullptr; }
};

} // namespace rung::simulator
