#pragma once

// An instruction list: the parsed form of a target's listing. Instructions refer to the
// target's instruction table; operands are resolved addresses or constants.

#include "model/target/address.h"
#include "model/target/target.h"

#include <QString>

#include <vector>

namespace rung::model {

struct Operand {
    enum class Kind : std::uint8_t { Device, Constant, Text, String } kind = Kind::Device;
    Address address;   // Kind::Device
    Constant constant; // Kind::Constant
    // Kind::Text: PL110 FM operator, labels kept verbatim. Kind::String: a text written in
    // double quotes (PL110 MOVTXT's "TESTO DISPLAY"), held here without its quotes; a quote
    // inside it is written twice in a listing.
    QString text;
    // Vigor, as in PLC concepts (WPLSoft family): a Device with digits n > 0 is the word of the
    // n x 4 bits from `address` (K4Y0 = Y0..Y17, K1M20 = M20..M23,
    // ConstantNotation::digitGroups).
    int digits = 0;
    // An index register (Area::indexRegister) that modifies a Device or a decimal Constant:
    // D0E0 = D(0 + E0), K10F0 = 10 + F0, K4M0E1 = K4M(0 + E1). Invalid when none.
    Address index;
    bool modified() const { return digits > 0 || index.valid(); }
    friend bool operator==(const Operand &, const Operand &) = default;
};

struct Instruction {
    const InstructionSpec *spec = nullptr; // entry of the target's instruction table
    std::vector<Operand> operands;
    int line = 0;    // 1-based source line, 0 when generated
    int column = 0;  // 1-based source column of the mnemonic
    int step = 0;    // step address (0-based), assigned by the printer / parser
    QString comment; // comment after the instruction on its line ("LD X0 ; start"), no marker

    Op op() const { return spec ? spec->op : Op::Nop; }
    bool sameAs(const Instruction &other) const // equal ignoring the source position
    {
        return spec == other.spec && operands == other.operands;
    }
};

struct InstructionList {
    const Target *target = nullptr;
    std::vector<Instruction> instructions;
    // Comments in the source keyed by the index of the instruction they precede; kept so a
    // rung comment can travel IL -> ladder -> IL.
    std::vector<std::pair<int, QString>> comments;
};

struct ParseError {
    int line = 0;    // 1-based
    int column = 0;  // 1-based
    QString message; // translated
};

struct ParseResult {
    InstructionList list;
    std::vector<ParseError> errors; // the list holds every line that parsed
    bool ok() const { return errors.empty(); }
};

// Parse a listing: comments (';' or '//' to end of line), blank lines and optional step
// numbers ("0002 LD p01<p00") are accepted. Every error has a line and a column.
// What a slot of `kind` needs when `address` cannot stand in it ("a timer", "a bit device";
// translated), empty when it can. The parser and Replace Device ask the same question.
QString expectedDevice(const Target &target, const Address &address, OperandKind kind);

ParseResult parseInstructionList(const Target &target, const QString &text,
                                 const ModelVariant *model = nullptr);

// The target a listing names on its first line ("; target: vigor", also "// target: cpm1"),
// empty when it names none; the command-line tool and the IDE both read it.
QString declaredTarget(const QString &text);

// The target to open a listing for: the one it declares, else `fallback` when it reads the
// text without an error, else the first family that does, else `fallback`.
QString listingTarget(const QString &text, const QString &fallback);

// Print in the target's canonical listing form, one instruction a line.
struct PrintOptions {
    bool stepNumbers = false; // "0002 LD  p01<p00" as the VPC console shows
    bool comments = true;
};
QString printInstructionList(const InstructionList &list, const PrintOptions &options = {});

// The printed text with its line map, so nothing has to count comment lines to find an
// instruction: lines are 1-based, as the editor and the diagnostics number them.
struct PrintedListing {
    QString text;
    std::vector<int> instructionLine; // the line of each instruction
    // The first line of each instruction with the comment lines printed before it (a rung's
    // first line is its first instruction's), and one more entry for the comments after the
    // last instruction (the line after the text when there are none).
    std::vector<int> firstLine;
    std::vector<int> instructionOfLine; // line - 1 -> instruction index, -1 for a comment line
    int instructionAt(int line) const;  // -1 for a comment line or beyond the text
};
PrintedListing printListing(const InstructionList &list, const PrintOptions &options = {});
// The list's instructions with `comments` in place of its own (the document adds its
// placeholder lines so), without a copy of the instructions.
PrintedListing printListing(const InstructionList &list,
                            const std::vector<std::pair<int, QString>> &comments,
                            const PrintOptions &options = {});
QString printInstruction(const Target &target, const Instruction &instruction);
// One operand alone, as the drawing and its tooltips show it (X0, K10, #0150, a PL110 text).
QString formatOperand(const Target &target, const Operand &operand);
// One operand alone as written in a listing or a ladder cell: a device, a constant, and on
// targets that have them digit-designated operands (K4M0) and index registers (D0E0, K10F0).
// The column of an error is 0-based within `text`. The listing parser adds what the slot
// allows (operand_text.cpp).
std::variant<Operand, AddressError> parseOperand(const Target &target, QStringView text,
                                                 const ModelVariant *model = nullptr);
// Whether `text` carries a digit designation or an index register on this target.
bool hasOperandModifiers(const Target &target, QStringView text);

// Steps an instruction occupies in the PLC's program memory (1 for most).
int instructionSteps(const Target &target, const Instruction &instruction);

// A timer instruction's time base in ms: its own (CPM1 TIMH(15): 10 ms), the one a PL110 timer
// names as its third operand (TON T1 50 10), its timer area's (Vigor T200.. 10 ms), else the
// target's default; 0 for no timer. The simulator times with it and the monitor shows a
// timer's units with it.
double timerBaseMs(const Target &target, const Instruction &instruction);
// Whether a timer's current value counts down from the set value (VPC t00..t15, every CPM1
// TIM: Semantics::downTimersBelow), so that the time elapsed is set value - current value.
bool timerCountsDown(const Target &target, const Address &timer);

} // namespace rung::model
