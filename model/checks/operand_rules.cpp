#include "model/checks/operand_rules.h"

#include "model/target/address.h"
#include "model/tr.h"

#include <QCoreApplication>

#include <algorithm>

namespace rung::model {

namespace {

QString slotName(const OperandSpec &spec, std::size_t k) {
    if (spec.name)
        return QCoreApplication::translate("rung::model::Target", spec.name);
    return ChecksTr::tr("operand %1").arg(k + 1);
}

const InstructionSpec *writerOf(const Target &target, ApplyFunction function) {
    for (const InstructionSpec &s : target.instructions)
        if (s.function == function)
            return &s;
    return nullptr;
}

int areaByKey(const Target &target, const char *key) {
    for (std::size_t i = 0; i < target.areas.size(); ++i)
        if (target.areas[i].key == QLatin1String(key))
            return static_cast<int>(i);
    return -1;
}

qint64 bcdWord(qint64 value) {
    qint64 word = 0;
    for (int shift = 0; value > 0; value /= 10, shift += 4)
        word |= (value % 10) << shift;
    return word;
}

bool isDestination(OperandKind kind) {
    return kind == OperandKind::BitDest || kind == OperandKind::WordDest;
}

} // namespace

bool controlWordFits(ControlWord control, qint64 word) {
    const auto digit = [word](int n) { return (word >> (4 * n)) & 0xF; };
    switch (control) {
    case ControlWord::None:
        return true;
    case ControlWord::BitPair:
        // W353 MOVB(82): "Bi must be BCD and specify bits 00 to 15".
        return word >= 0 && word <= 0xFFFF && digit(0) <= 9 && digit(1) <= 9 && digit(2) <= 9 &&
               digit(3) <= 9 && digit(1) * 10 + digit(0) <= 15 && digit(3) * 10 + digit(2) <= 15;
    case ControlWord::Digits:
        // W353 MOVD(83): "the rightmost three digits of Di must each be 0 to 3".
        return word >= 0 && word <= 0xFFFF && digit(0) <= 3 && digit(1) <= 3 && digit(2) <= 3 &&
               digit(3) == 0;
    }
    return true;
}

namespace {

QString controlWordMessage(const Target &target, const OperandSpec &rule, std::size_t k,
                           const InstructionSpec &spec, const Constant &value) {
    const QString shown = formatConstant(target, value);
    if (rule.control == ControlWord::BitPair)
        return ChecksTr::tr("the %1 of %2 must be #DDSS with bits DD and SS from 00 to 15, not %3")
            .arg(slotName(rule, k), spec.mnemonic, shown);
    return ChecksTr::tr("the %1 of %2 must be #0DNS with digits D, N and S from 0 to 3, not %3")
        .arg(slotName(rule, k), spec.mnemonic, shown);
}

// "BMOV uses D8190..D8199, but D8192 does not exist": a run of `count` elements from
// `first` that model::runBreaks finds broken; empty when it is whole.
QString brokenRun(const Target &target, const InstructionSpec &spec, const Address &first,
                  qint64 count, bool wordBlock = false) {
    const std::optional<Address> missing = runBreaks(target, first, count, wordBlock);
    if (!missing)
        return {};
    Address last = first;
    last.index = static_cast<int>(std::min<qint64>(qint64{first.index} + count - 1, INT_MAX));
    const Address there = offsetAddress(target, first, qint64{missing->index} - first.index);
    if (there.valid() && there.area != missing->area) {
        // A block of timer or counter values: T199 and T200 are no neighbours in memory.
        return ChecksTr::tr("%1 uses %2..%3, which runs from %4 into %5: a block stays in one")
            .arg(spec.mnemonic, formatAddress(target, first), formatAddress(target, last),
                 QCoreApplication::translate("rung::model::Target",
                                             target.area(missing->area).description),
                 QCoreApplication::translate("rung::model::Target",
                                             target.area(there.area).description));
    }
    return ChecksTr::tr("%1 uses %2..%3, but %4 does not exist")
        .arg(spec.mnemonic, formatAddress(target, first), formatAddress(target, last),
             formatAddress(target, *missing));
}

// "D" for the keys D and DL: the prefixes of the areas, each once.
QString areaPrefixes(const Target &target, const std::vector<const char *> &keys) {
    QStringList prefixes;
    for (const char *key : keys)
        if (const int a = areaByKey(target, key);
            a >= 0 && !prefixes.contains(target.area(a).prefix))
            prefixes << target.area(a).prefix;
    return prefixes.join(QStringLiteral(", "));
}

// A text's destination and how many characters a word holds (OperandSpec::storedFrom,
// charactersPerWord); no destination when operand storedFrom is no device.
struct StoredText {
    const Operand *dest = nullptr;
    int perWord = 1;
};

StoredText storedTextOf(const Instruction &ins, const OperandSpec &rule) {
    StoredText t;
    const auto operandAt = [&ins](int k) -> const Operand * {
        return k >= 0 && static_cast<std::size_t>(k) < ins.operands.size()
                   ? &ins.operands[static_cast<std::size_t>(k)]
                   : nullptr;
    };
    if (const Operand *d = operandAt(rule.storedFrom);
        d && d->kind == Operand::Kind::Device && d->address.valid() && !d->modified())
        t.dest = d;
    if (const Operand *n = operandAt(rule.charactersPerWord);
        n && n->kind == Operand::Kind::Constant && n->constant.value == 2)
        t.perWord = 2;
    return t;
}

// One character of a text as a message shows it: itself, or its code when it has no glyph.
QString shownCharacter(const QString &text, qsizetype i) {
    const QChar c = text[i];
    if (c.unicode() < 32 || (c.unicode() >= 127 && c.unicode() < 160))
        return QStringLiteral("\\x%1").arg(c.unicode(), 2, 16, QLatin1Char('0'));
    return QLatin1Char('\'') + text.mid(i, c.isHighSurrogate() ? 2 : 1) + QLatin1Char('\'');
}

// A text that does not fit where it is stored: a character of more than a byte, two
// characters a word into words of 8 bits, more words than its area has from D.
QString storedTextBreach(const Target &target, const Instruction &ins, std::size_t k) {
    const InstructionSpec &spec = *ins.spec;
    const OperandSpec &rule = spec.operands[k];
    const QString &text = ins.operands[k].text;
    for (qsizetype i = 0; i < text.size(); ++i)
        if (text[i].unicode() > 255)
            return ChecksTr::tr("the %1 of %2 holds %3 (character %4), which does not fit a "
                                "byte: a character is stored as its Latin-1 code, 0..255")
                .arg(slotName(rule, k), spec.mnemonic, shownCharacter(text, i))
                .arg(i + 1);
    const StoredText s = storedTextOf(ins, rule);
    if (!s.dest)
        return {};
    const Address &first = s.dest->address;
    const Area &area = target.area(first.area);
    if (s.perWord == 2 && area.wordBits < 16)
        return ChecksTr::tr("%1 stores two characters a word, but %2 holds %3 bits a word: "
                            "write 1 character per word")
            .arg(spec.mnemonic, formatAddress(target, first))
            .arg(area.wordBits);
    const qint64 words = s.perWord == 2 ? (text.size() + 1) / 2 : text.size();
    if (words < 1)
        return {};
    if (const std::optional<Address> missing = runBreaks(target, first, words, true)) {
        Address last = first;
        last.index = static_cast<int>(std::min<qint64>(qint64{first.index} + words - 1, INT_MAX));
        return ChecksTr::tr("the %1 of %2 (length %3) is stored in %4..%5, but %6 does not "
                            "exist: the text is too long for its place")
            .arg(slotName(rule, k), spec.mnemonic)
            .arg(text.size())
            .arg(formatAddress(target, first), formatAddress(target, last),
                 formatAddress(target, *missing));
    }
    return {};
}

QString choiceList(const QStringList &all) {
    QStringList values = all;
    const QString last = values.takeLast();
    return values.isEmpty() ? last
                            : ChecksTr::tr("%1 or %2").arg(values.join(QStringLiteral(", ")), last);
}

} // namespace

std::vector<OperandBreach> operandBreaches(const Target &target, const Instruction &ins) {
    std::vector<OperandBreach> found;
    if (!ins.spec)
        return found;
    const InstructionSpec &spec = *ins.spec;
    for (std::size_t k = 0; k < ins.operands.size() && k < spec.operands.size(); ++k) {
        const Operand &o = ins.operands[k];
        const OperandSpec &rule = spec.operands[k];
        const int at = static_cast<int>(k);
        if (!rule.allowedTexts.empty()) {
            // A word from a list (PL110 FM's operators): a number or another word is none.
            QStringList texts;
            for (const char *text : rule.allowedTexts)
                texts << QString::fromLatin1(text);
            const QString written = o.kind == Operand::Kind::Constant
                                        ? formatConstant(target, o.constant)
                                    : o.kind == Operand::Kind::Device ? formatOperand(target, o)
                                                                      : o.text.trimmed();
            if (o.kind != Operand::Kind::Text || !texts.contains(written))
                found.push_back(
                    {at, ChecksTr::tr("the %1 of %2 must be %3, not %4")
                             .arg(slotName(rule, k), spec.mnemonic, choiceList(texts), written)});
            continue;
        }
        if (o.kind == Operand::Kind::Constant && rule.deviceOnly && !rule.sourceAreas.empty()) {
            found.push_back({at, ChecksTr::tr("%1 takes its %2 from %3 only, not %4")
                                     .arg(spec.mnemonic, slotName(rule, k),
                                          areaPrefixes(target, rule.sourceAreas),
                                          formatConstant(target, o.constant))});
            continue;
        }
        if (o.kind == Operand::Kind::Constant && rule.deviceOnly) {
            // CCD S: a block of words to read, not a value.
            found.push_back({at, ChecksTr::tr("the %1 of %2 must be a device, not %3")
                                     .arg(slotName(rule, k), spec.mnemonic,
                                          formatConstant(target, o.constant))});
            continue;
        }
        if (o.kind == Operand::Kind::Constant) {
            const qint64 v = o.constant.value;
            if (rule.bcd && o.constant.style != Constant::Style::Bcd) {
                found.push_back({at, ChecksTr::tr("the %1 of %2 must be BCD (#0000..#9999), not %3")
                                         .arg(slotName(rule, k), spec.mnemonic,
                                              formatConstant(target, o.constant))});
                continue;
            }
            // A # constant is the word its digits spell (#1503 = 1503h).
            if (rule.control != ControlWord::None && !controlWordFits(rule.control, bcdWord(v))) {
                found.push_back({at, controlWordMessage(target, rule, k, spec, o.constant)});
                continue;
            }
            if (!rule.allowedValues.empty() &&
                std::find(rule.allowedValues.begin(), rule.allowedValues.end(), v) ==
                    rule.allowedValues.end()) {
                QStringList values;
                for (int a : rule.allowedValues)
                    values << QString::number(a);
                const QString choices = choiceList(values);
                found.push_back({at, ChecksTr::tr("the %1 of %2 must be %3, not %4")
                                         .arg(slotName(rule, k), spec.mnemonic, choices)
                                         .arg(v)});
            } else if (rule.highest == INT_MAX && rule.lowest != INT_MIN && v < rule.lowest) {
                found.push_back({at, ChecksTr::tr("the %1 of %2 must be at least %3, not %4")
                                         .arg(slotName(rule, k), spec.mnemonic)
                                         .arg(rule.lowest)
                                         .arg(v)});
            } else if ((rule.lowest != INT_MIN || rule.highest != INT_MAX) &&
                       (v < rule.lowest || v > rule.highest)) {
                found.push_back({at, ChecksTr::tr("the %1 of %2 must be from %3 to %4, not %5")
                                         .arg(slotName(rule, k), spec.mnemonic)
                                         .arg(rule.lowest)
                                         .arg(rule.highest)
                                         .arg(v)});
            }
            continue;
        }
        if (o.kind == Operand::Kind::Text &&
            (rule.lowest != INT_MIN || rule.highest != INT_MAX || !rule.allowedValues.empty())) {
            // PL110 keeps a word in a constant slot verbatim; a slot with a range wants a number.
            found.push_back({at, ChecksTr::tr("the %1 of %2 must be a number, not %3")
                                     .arg(slotName(rule, k), spec.mnemonic, o.text.trimmed())});
            continue;
        }
        if (o.kind == Operand::Kind::String) {
            if (const QString why = storedTextBreach(target, ins, k); !why.isEmpty())
                found.push_back({at, why});
            continue;
        }
        if (o.kind != Operand::Kind::Device || !o.address.valid() ||
            o.address.area >= static_cast<int>(target.areas.size()))
            continue;
        const Area &area = target.area(o.address.area);
        if (rule.wholeWords && (o.digits > 0 || area.doubleWordsOf)) {
            // A block counts words: K4M0 or VD0 would make its length mean something else.
            found.push_back(
                {at, ChecksTr::tr("%1 moves whole words: %2 cannot be its %3")
                         .arg(spec.mnemonic, formatOperand(target, o), slotName(rule, k))});
            continue;
        }
        if (!rule.sourceAreas.empty() &&
            std::none_of(rule.sourceAreas.begin(), rule.sourceAreas.end(),
                         [&](const char *key) { return area.key == QLatin1String(key); })) {
            const QString prefixes = areaPrefixes(target, rule.sourceAreas);
            found.push_back(
                {at, rule.deviceOnly
                         ? ChecksTr::tr("%1 takes its %2 from %3 only, not %4")
                               .arg(spec.mnemonic, slotName(rule, k), prefixes,
                                    formatOperand(target, o))
                         : ChecksTr::tr("%1 takes its %2 from a constant or from %3, not %4")
                               .arg(spec.mnemonic, slotName(rule, k), prefixes,
                                    formatOperand(target, o))});
            continue;
        }
        const bool wrongArea = rule.area && area.key != QLatin1String(rule.area);
        if (wrongArea ||
            (rule.area && (o.address.index < rule.lowest || o.address.index > rule.highest))) {
            // "OUTQI writes only Q1..Q8, not Q9": the range as the listing writes it.
            const int ruleArea = rule.area ? areaByKey(target, rule.area) : o.address.area;
            if (ruleArea >= 0) {
                const Area &a = target.area(ruleArea);
                const QString first =
                    formatAddress(target, Address{ruleArea, std::max(a.first, rule.lowest), -1});
                const QString last =
                    formatAddress(target, Address{ruleArea, std::min(a.last, rule.highest), -1});
                found.push_back(
                    {at, ChecksTr::tr("%1 takes only %2..%3, not %4")
                             .arg(spec.mnemonic, first, last, formatAddress(target, o.address))});
            }
            continue;
        }
        const bool wordSlot = rule.kind == OperandKind::WordSource ||
                              rule.kind == OperandKind::WordDest ||
                              rule.kind == OperandKind::SetValue;
        // SBIT / RBIT name a word and a bit number, or a bit device itself (PL110 SBIT Q1);
        // with a bit number, Q1 is the word Q1..Q16 and must start one (SBIT Q1 3 sets Q4).
        const bool bitItself =
            (spec.function == ApplyFunction::SetBit || spec.function == ApplyFunction::ResetBit) &&
            ins.operands.size() < 2;
        if (wordSlot && area.kind == AreaKind::Bit && o.digits == 0 && !bitItself) {
            // A plain bit device is a word only where the table reads 16 bits as one
            // (Area::bitsAsWords, PL110 I1 = I1..I16); the Vigor writes K4M0 for that.
            if (!area.bitsAsWords) {
                found.push_back(
                    {at, ChecksTr::tr("the %1 of %2 is a word: %3 is a single bit")
                             .arg(slotName(rule, k), spec.mnemonic, formatOperand(target, o))});
                continue;
            }
            const int offset = o.address.index - area.first;
            if (!o.modified() && offset % 16 != 0) {
                Address below = o.address;
                below.index = area.first + offset / 16 * 16;
                Address above = below;
                above.index += 16;
                found.push_back(
                    {at, ChecksTr::tr("the %1 of %2 is a word: %3 starts no word of 16 bits "
                                      "(%4 and %5 do)")
                             .arg(slotName(rule, k), spec.mnemonic, formatOperand(target, o),
                                  formatAddress(target, below), formatAddress(target, above))});
                continue;
            }
        }
        const bool bitSlot =
            rule.kind == OperandKind::BitSource || rule.kind == OperandKind::BitDest;
        // A whole word or channel where a bit belongs: the simulator has no bit to read or
        // write. Coils on a word are OP002's ("cannot drive"); a channel of bits is refused
        // everywhere (CPM1 LD 011, SNXT(09) 011: write 011.00), and so is a word of bits read
        // as a contact (PL110 LD V1: V1.0 is its first bit). A reset clears words too (RST D0,
        // ZRST D0 D9).
        const bool clearsWords = spec.op == Op::Reset || spec.function == ApplyFunction::ZoneReset;
        if (bitSlot && !clearsWords && o.address.bit < 0 && o.digits == 0 &&
            (area.kind == AreaKind::Channel ||
             (area.kind == AreaKind::Word &&
              (spec.op == Op::Apply || rule.kind == OperandKind::BitSource)))) {
            if (area.numbering == Numbering::ChannelBit) {
                Address firstBit = o.address;
                firstBit.bit = 0;
                found.push_back(
                    {at, area.kind == AreaKind::Channel
                             ? ChecksTr::tr("the %1 of %2 is a bit: %3 is a whole channel (%4 is "
                                            "its first bit)")
                                   .arg(slotName(rule, k), spec.mnemonic,
                                        formatAddress(target, o.address),
                                        formatAddress(target, firstBit))
                             : ChecksTr::tr("the %1 of %2 is a bit: %3 is a whole word (%4 is its "
                                            "first bit)")
                                   .arg(slotName(rule, k), spec.mnemonic,
                                        formatAddress(target, o.address),
                                        formatAddress(target, firstBit))});
            } else {
                found.push_back({at, ChecksTr::tr("the %1 of %2 is a bit: %3 is a whole word")
                                         .arg(slotName(rule, k), spec.mnemonic,
                                              formatAddress(target, o.address))});
            }
            continue;
        }
        if (rule.bitWords && (area.numbering != Numbering::ChannelBit || o.address.bit >= 0)) {
            found.push_back(
                {at, ChecksTr::tr("the %1 of %2 must be a channel with bits (IR, HR, LR), "
                                  "not %3")
                         .arg(slotName(rule, k), spec.mnemonic, formatAddress(target, o.address))});
            continue;
        }
        if (rule.rangeFrom >= 0 && static_cast<std::size_t>(rule.rangeFrom) < ins.operands.size()) {
            const Operand &first = ins.operands[static_cast<std::size_t>(rule.rangeFrom)];
            if (first.kind == Operand::Kind::Device && first.address.valid() &&
                first.address.area < static_cast<int>(target.areas.size())) {
                const Area &from = target.area(first.address.area);
                if (from.prefix != area.prefix || from.kind != area.kind ||
                    first.address.index > o.address.index) {
                    found.push_back(
                        {at,
                         ChecksTr::tr("%1 %2 %3: the last device must be of the kind of the first "
                                      "and not before it")
                             .arg(spec.mnemonic, formatAddress(target, first.address),
                                  formatAddress(target, o.address))});
                    continue;
                }
                const QString broken = brokenRun(target, spec, first.address,
                                                 qint64{o.address.index} - first.address.index + 1);
                if (!broken.isEmpty()) {
                    found.push_back({at, broken});
                    continue;
                }
            }
        }
        // A modified operand (K4M0, D0Z0) is resolved where it lands, each time it runs.
        // A 32-bit form reads a 32-bit device, and a timer or counter source, as one (Vigor
        // DMOV C200 D0, DMOV T0 D0 sign-extended); other words as a pair.
        const bool single =
            spec.doubleWord && (area.wordBits >= 32 ||
                                (!isDestination(rule.kind) &&
                                 (area.kind == AreaKind::Timer || area.kind == AreaKind::Counter)));
        if (rule.words > 1 && o.address.bit < 0 && !o.modified() && !single) {
            if (const QString broken = brokenRun(target, spec, o.address, rule.words);
                !broken.isEmpty()) {
                found.push_back({at, broken});
                continue;
            }
        }
        if (rule.countFrom >= 0 && static_cast<std::size_t>(rule.countFrom) < ins.operands.size() &&
            !o.modified()) {
            const Operand &n = ins.operands[static_cast<std::size_t>(rule.countFrom)];
            if (n.kind == Operand::Kind::Constant && n.constant.value >= 1) {
                // A bit area read as words gives 16 bits a word (PL110 I1 = I1..I16).
                const qint64 span =
                    area.kind == AreaKind::Bit ? n.constant.value * 16 : n.constant.value;
                if (const QString broken = brokenRun(target, spec, o.address, span, true);
                    !broken.isEmpty()) {
                    found.push_back({at, broken});
                    continue;
                }
            }
        }
        // PL110 manual 4.2.3: a bistable relay changes only on its own coil.
        if (isDestination(rule.kind) && area.onlyWrittenBy != ApplyFunction::None &&
            spec.function != area.onlyWrittenBy) {
            const InstructionSpec *writer = writerOf(target, area.onlyWrittenBy);
            found.push_back(
                {at, ChecksTr::tr("%1 cannot write %2: %3 are written only by %4")
                         .arg(spec.mnemonic, formatAddress(target, o.address),
                              QCoreApplication::translate("rung::model::Target", area.description),
                              writer ? writer->mnemonic : QString())});
        }
    }
    return found;
}

QString notSimulatedMessage(const InstructionSpec &spec) {
    return ChecksTr::tr("%1 is not simulated: it does nothing in the simulator").arg(spec.mnemonic);
}

} // namespace rung::model

namespace rung::model {

std::vector<std::int32_t> textWords(const QString &text, int charactersPerWord) {
    std::vector<std::int32_t> words;
    const auto code = [&text](qsizetype i) -> std::int32_t {
        return i < text.size() && text[i].unicode() <= 255 ? text[i].unicode() : 0;
    };
    if (charactersPerWord == 2) {
        for (qsizetype i = 0; i < text.size(); i += 2)
            words.push_back(code(i) << 8 | code(i + 1));
    } else {
        for (qsizetype i = 0; i < text.size(); ++i)
            words.push_back(code(i));
    }
    return words;
}

QString undisplayedCharacters(const Target &target, const Instruction &ins, std::size_t k) {
    if (!ins.spec || k >= ins.operands.size() || k >= ins.spec->operands.size())
        return {};
    const Operand &o = ins.operands[k];
    const PanelDisplay &d = target.panel.display;
    if (o.kind != Operand::Kind::String || d.charArea.isEmpty())
        return {};
    const StoredText s = storedTextOf(ins, ins.spec->operands[k]);
    if (!s.dest || target.area(s.dest->address.area).key != d.charArea)
        return {};
    QStringList missed;
    for (qsizetype i = 0; i < o.text.size(); ++i) {
        const char16_t c = o.text[i].unicode();
        if (c > 255 || d.shows(c))
            continue; // beyond a byte: OP005 says it
        const QString shown = shownCharacter(o.text, i);
        if (!missed.contains(shown))
            missed << shown;
    }
    if (missed.isEmpty())
        return {};
    QStringList codes;
    for (const auto &[low, high] : d.shownCodes)
        codes << QStringLiteral("%1..%2").arg(low).arg(high);
    return ChecksTr::tr("the display shows %1 of the %2 of %3 as a space: it draws the "
                        "character codes %4")
        .arg(missed.join(QStringLiteral(", ")), slotName(ins.spec->operands[k], k),
             ins.spec->mnemonic, codes.join(QStringLiteral(", ")));
}

} // namespace rung::model
