#include "model/target/target_data.h"

#include <QCoreApplication>

// The CPM1's application instructions (the Omron CPM1 guide names the categories:
// "Összehasonlító utasítások, Adatmozgató parancsok, Léptető parancsok, Adatátalakító
// parancsok, BCD aritmetikai parancsok, Bineáris aritmetikai utasítások, Logikai parancsok,
// Szubrutinkezelő utasítások, STEP (lépés) parancsok"; Omron's CPM1 programming manual W353
// gives each one's function code, operands and flags). Every one with an "@" form in W353
// gets its differentiated twin ("@MOV(21)"), which runs once when its condition turns ON.

namespace rung::model::detail {

namespace {

using K = OperandKind;
using F = ApplyFunction;

struct Row {
    const char *name = nullptr;
    int code = 0;
    Op op = Op::Apply;
    F function = F::None;
    std::vector<OperandSpec> operands;
    const char *summary = nullptr;
    const char *help = nullptr;
    bool twin = true; // W353 has the @ form
    int inputs = 1;
};

// A word source W353 reads as BCD: a constant with a hexadecimal digit is an error of check.
OperandSpec bcd(const char *name = nullptr) {
    OperandSpec s{K::WordSource};
    s.bcd = true;
    s.name = name;
    return s;
}

OperandSpec word(K kind, const char *name = nullptr) {
    OperandSpec s{kind};
    s.name = name;
    return s;
}

void add(Target &t, const Row &row) {
    const QByteArray spelled =
        QByteArray(row.name) + '(' + QByteArray::number(row.code).rightJustified(2, '0') + ')';
    InstructionSpec &s =
        addSpec(t, spelled.constData(), row.op, row.operands, row.summary, row.help);
    s.functionCode = row.code;
    s.aliases.append(QString::fromLatin1(row.name));
    s.function = row.function;
    s.inputs = row.inputs;
    if (!row.twin)
        return;
    InstructionSpec twin = s; // a copy: addSpec may move the table
    twin.mnemonic = QLatin1Char('@') + twin.mnemonic;
    twin.aliases = {QLatin1Char('@') + QString::fromLatin1(row.name)};
    twin.differentiated = true;
    t.instructions.push_back(std::move(twin));
}

} // namespace

void addCpm1ApplicationInstructions(Target &t) {
    // The subroutine number (W353: SBS(91) / SBN(92) 00..49 on the CPM1).
    OperandSpec subroutine{K::Label};
    subroutine.lowest = 0;
    subroutine.highest = 49;
    subroutine.name = QT_TRANSLATE_NOOP("rung::model::Target", "subroutine number");
    // The FAL number (W353 FAL(06): 00..99).
    OperandSpec failureNumber{K::Label};
    failureNumber.lowest = 0;
    failureNumber.highest = 99;
    failureNumber.name = QT_TRANSLATE_NOOP("rung::model::Target", "FAL number");
    // SFT(10) / WSFT(16) St E: E in St's area, not before it (W353 "Limitations").
    OperandSpec start = word(K::WordDest, QT_TRANSLATE_NOOP("rung::model::Target", "start word"));
    OperandSpec end = word(K::WordDest, QT_TRANSLATE_NOOP("rung::model::Target", "end word"));
    end.rangeFrom = 0;
    OperandSpec shiftStart = start;
    shiftStart.bitWords = true; // SFT shifts bits: channels with bit addresses (IR, HR, LR)
    OperandSpec shiftEnd = end;
    shiftEnd.bitWords = true;
    // MUL(32) / DIV(33) write R and R+1.
    OperandSpec twoWords = word(K::WordDest, QT_TRANSLATE_NOOP("rung::model::Target", "result"));
    twoWords.words = 2;
    OperandSpec bitControl = bcd(QT_TRANSLATE_NOOP("rung::model::Target", "bit designator"));
    bitControl.control = ControlWord::BitPair;
    OperandSpec digitControl = bcd(QT_TRANSLATE_NOOP("rung::model::Target", "digit designator"));
    digitControl.control = ControlWord::Digits;
    OperandSpec controlBit =
        word(K::BitDest, QT_TRANSLATE_NOOP("rung::model::Target", "control bit"));
    OperandSpec stepBit =
        word(K::BitSource, QT_TRANSLATE_NOOP("rung::model::Target", "control bit"));
    stepBit.optional = true;
    const OperandSpec source{K::WordSource};
    const OperandSpec dest{K::WordDest};

    const Row rows[] = {
        // Data movement (W353 "Data Movement").
        {"MOV",
         21,
         Op::Apply,
         F::Mov,
         {source, dest},
         QT_TRANSLATE_NOOP("rung::model::Target", "Move a channel or a constant"),
         "S D"},
        {"MVN",
         22,
         Op::Apply,
         F::MoveNot,
         {source, dest},
         QT_TRANSLATE_NOOP("rung::model::Target", "Move the inverse of S to D"),
         "S D"},
        {"MOVB",
         82,
         Op::Apply,
         F::MoveBit,
         {source, bitControl, dest},
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "Move one bit: Bi = #DDSS, destination bit DD, source bit SS"),
         "S Bi D"},
        {"MOVD",
         83,
         Op::Apply,
         F::MoveDigit,
         {source, digitControl, dest},
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "Move digits: Di = #0DNS, first destination digit D, N+1 digits, "
                           "first source digit S"),
         "S Di D"},
        // Data shift (W353 "Data Shift").
        {"SFT",
         10,
         Op::Apply,
         F::ShiftRegister,
         {shiftStart, shiftEnd},
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "Shift register: data, shift pulse and reset inputs; St..E"),
         "St E",
         false,
         3},
        {"WSFT",
         16,
         Op::Apply,
         F::WordShift,
         {start, end},
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "Shift the words St..E up by one word, #0000 into St"),
         "St E"},
        // Comparison (W353 "Comparison"): no @ form.
        {"CMP",
         20,
         Op::Apply,
         F::CompareToFlags,
         {source, source},
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "Compare two words: GR 255.05, EQ 255.06, LE 255.07"),
         "Cp1 Cp2",
         false},
        // Data conversion and logic (W353 "Data Conversion", "Logic Instructions").
        {"BIN",
         23,
         Op::Apply,
         F::FromBcd,
         {bcd(), dest},
         QT_TRANSLATE_NOOP("rung::model::Target", "R = the value of the BCD digits of S"),
         "S R"},
        {"BCD",
         24,
         Op::Apply,
         F::ToBcd,
         {source, dest},
         QT_TRANSLATE_NOOP("rung::model::Target", "R = S as BCD digits"),
         "S R"},
        {"COM",
         29,
         Op::Apply,
         F::Complement,
         {dest},
         QT_TRANSLATE_NOOP("rung::model::Target", "Invert every bit of a channel"),
         "Wd"},
        {"ANDW",
         34,
         Op::Apply,
         F::AndWord,
         {source, source, dest},
         QT_TRANSLATE_NOOP("rung::model::Target", "R = I1 AND I2, bit by bit"),
         "I1 I2 R"},
        {"ORW",
         35,
         Op::Apply,
         F::OrWord,
         {source, source, dest},
         QT_TRANSLATE_NOOP("rung::model::Target", "R = I1 OR I2, bit by bit"),
         "I1 I2 R"},
        {"XORW",
         36,
         Op::Apply,
         F::XorWord,
         {source, source, dest},
         QT_TRANSLATE_NOOP("rung::model::Target", "R = I1 XOR I2, bit by bit"),
         "I1 I2 R"},
        // Increment / decrement (W353 "Increment/Decrement"): BCD.
        {"INC",
         38,
         Op::Apply,
         F::BcdIncrement,
         {dest},
         QT_TRANSLATE_NOOP("rung::model::Target", "Add 1 to a BCD channel (9999 -> 0000)"),
         "Wd"},
        {"DEC",
         39,
         Op::Apply,
         F::BcdDecrement,
         {dest},
         QT_TRANSLATE_NOOP("rung::model::Target", "Subtract 1 from a BCD channel (0000 -> 9999)"),
         "Wd"},
        // BCD arithmetic (W353 "BCD Calculations").
        {"STC",
         40,
         Op::Apply,
         F::SetCarry,
         {},
         QT_TRANSLATE_NOOP("rung::model::Target", "Set the carry flag CY (255.04)")},
        {"CLC",
         41,
         Op::Apply,
         F::ClearCarry,
         {},
         QT_TRANSLATE_NOOP("rung::model::Target", "Clear the carry flag CY (255.04)")},
        {"ADD",
         30,
         Op::Apply,
         F::BcdAdd,
         {bcd(), bcd(), dest},
         QT_TRANSLATE_NOOP("rung::model::Target", "R = Au + Ad + CY in BCD; CY on a carry"),
         "Au Ad R"},
        {"SUB",
         31,
         Op::Apply,
         F::BcdSubtract,
         {bcd(), bcd(), dest},
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "R = Mi - Su - CY in BCD; below zero: the 10's complement and CY"),
         "Mi Su R"},
        {"MUL",
         32,
         Op::Apply,
         F::BcdMultiply,
         {bcd(), bcd(), twoWords},
         QT_TRANSLATE_NOOP("rung::model::Target", "R+1, R = Md x Mr in BCD (8 digits)"),
         "Md Mr R"},
        {"DIV",
         33,
         Op::Apply,
         F::BcdDivide,
         {bcd(), bcd(), twoWords},
         QT_TRANSLATE_NOOP("rung::model::Target", "R = Dd / Dr in BCD, R+1 = the remainder"),
         "Dd Dr R"},
        // Binary arithmetic (W353 "Binary Calculations").
        {"ADB",
         50,
         Op::Apply,
         F::BinaryAdd,
         {source, source, dest},
         QT_TRANSLATE_NOOP("rung::model::Target", "R = Au + Ad + CY in binary; CY above FFFF"),
         "Au Ad R"},
        {"SBB",
         51,
         Op::Apply,
         F::BinarySubtract,
         {source, source, dest},
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "R = Mi - Su - CY in binary; below zero: the 2's complement and CY"),
         "Mi Su R"},
        // Subroutines (W353 "Subroutines"): SBN and RET stand alone after the main program.
        {"SBS",
         91,
         Op::Apply,
         F::SubroutineCall,
         {subroutine},
         QT_TRANSLATE_NOOP("rung::model::Target", "Run subroutine N, then go on after SBS"),
         "00..49"},
        {"SBN",
         92,
         Op::SubroutineStart,
         F::None,
         {subroutine},
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "Start of subroutine N (after the main program; ends the main program)"),
         "00..49",
         false},
        {"RET",
         93,
         Op::SubroutineReturn,
         F::None,
         {},
         QT_TRANSLATE_NOOP("rung::model::Target", "End of the subroutine: back after its SBS"),
         nullptr,
         false},
        // A non-fatal error (W353 FAL(06)): N 01..99 into SR 253.00..253.07, the program goes
        // on and ERROR/ALARM blinks (Omron CPM1 guide 2.1); FAL 00 clears it. FALS(07), the
        // fatal error that stops the CPU, is not in the table.
        {"FAL",
         6,
         Op::Apply,
         F::FailureAlarm,
         {failureNumber},
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "Non-fatal error N: N into 253.00..253.07, the program goes on; FAL "
                           "00 clears it"),
         "00..99",
         false},
        // Step instructions (W353 "Step Instructions").
        {"STEP",
         8,
         Op::StepDefine,
         F::None,
         {stepBit},
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "Start of the step of control bit B; without B: end of the steps"),
         "[B]",
         false},
        {"SNXT",
         9,
         Op::Apply,
         F::StepNext,
         {controlBit},
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "End the current step and start the step of control bit B"),
         "B",
         false},
    };
    for (const Row &row : rows)
        add(t, row);
}

} // namespace rung::model::detail
