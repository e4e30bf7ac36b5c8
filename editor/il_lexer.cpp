#include "il_lexer.h"

#include "model/convert/typed_listing.h"
#include "model/listing/il.h"
#include "model/target/address.h"

#include <Qsci/qsciabstractapis.h>
#include <Qsci/qsciscintilla.h>

#include <QCoreApplication>
#include <QFontDatabase>

namespace rung::editor {

IlLexer::IlLexer(const model::Target &target, QObject *parent)
    : QsciLexerCustom(parent)
    , m_target(target) {}

QString IlLexer::description(int style) const {
    switch (style) {
    case Default:
        return tr("Default");
    case Mnemonic:
        return tr("Instruction");
    case Device:
        return tr("Device");
    case Constant:
        return tr("Constant");
    case Comment:
        return tr("Comment");
    case StepNumber:
        return tr("Step number");
    case Error:
        return tr("Unknown word");
    case Placeholder:
        return tr("Rung not in the list");
    default:
        return {};
    }
}

QColor IlLexer::defaultColor(int style) const {
    switch (style) {
    case Mnemonic:
        return QColor(0x1f, 0x4e, 0xa8);
    case Device:
        return QColor(0x20, 0x24, 0x2a);
    case Constant:
        return QColor(0x9c, 0x4d, 0x00);
    case Comment:
        return QColor(0x2e, 0x7d, 0x32);
    case StepNumber:
        return QColor(0x8a, 0x8f, 0x98);
    case Error:
        return QColor(0xc6, 0x28, 0x28);
    case Placeholder:
        return QColor(0x8a, 0x3b, 0x00);
    default:
        return QColor(0x20, 0x24, 0x2a);
    }
}

QColor IlLexer::defaultPaper(int style) const {
    // A placeholder stands out from the comments around it: the rung it names is missing here.
    return style == Placeholder ? QColor(0xff, 0xf1, 0xd6) : QsciLexerCustom::defaultPaper(style);
}

QFont IlLexer::defaultFont(int style) const {
    QFont f = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    f.setPointSize(10);
    if (style == Mnemonic)
        f.setBold(true);
    if (style == Comment || style == Placeholder)
        f.setItalic(true);
    if (style == Placeholder)
        f.setBold(true);
    return f;
}

std::vector<int> IlLexer::styleLine(const QString &line) const {
    if (!model::placeholderKey(line).isEmpty())
        return std::vector<int>(static_cast<std::size_t>(line.size()), Placeholder);
    std::vector<int> styles(static_cast<std::size_t>(line.size()), Default);
    qsizetype cut = line.indexOf(QLatin1Char(';'));
    const qsizetype slashes = line.indexOf(QLatin1String("//"));
    if (slashes >= 0 && (cut < 0 || slashes < cut))
        cut = slashes;
    const qsizetype codeEnd = cut >= 0 ? cut : line.size();
    for (qsizetype i = codeEnd; i < line.size(); ++i)
        styles[static_cast<std::size_t>(i)] = Comment;
    // Words: the first (after an optional step number) is the mnemonic, possibly two words
    // ("LD NOT", "AND LD"); the rest are operands.
    struct Word {
        qsizetype start, length;
    };
    std::vector<Word> words;
    for (qsizetype i = 0; i < codeEnd;) {
        while (i < codeEnd && line[i].isSpace())
            ++i;
        const qsizetype start = i;
        while (i < codeEnd && !line[i].isSpace())
            ++i;
        if (i > start)
            words.push_back({start, i - start});
    }
    auto paint = [&](const Word &w, int style) {
        for (qsizetype k = w.start; k < w.start + w.length; ++k)
            styles[static_cast<std::size_t>(k)] = style;
    };
    std::size_t next = 0;
    if (words.size() > 1) {
        const QString first = line.mid(words[0].start, words[0].length);
        bool digits = !first.isEmpty();
        for (QChar c : first)
            digits = digits && c.isDigit();
        if (digits) {
            paint(words[0], StepNumber);
            next = 1;
        }
    }
    if (next < words.size()) {
        const QString one = line.mid(words[next].start, words[next].length);
        const QString two =
            next + 1 < words.size()
                ? line.mid(words[next].start,
                           words[next + 1].start + words[next + 1].length - words[next].start)
                : QString();
        if (!two.isEmpty() && m_target.findInstruction(two)) {
            paint({words[next].start,
                   words[next + 1].start + words[next + 1].length - words[next].start},
                  Mnemonic);
            next += 2;
        } else {
            qsizetype letters = 0;
            while (letters < one.size() && one[letters].isLetter())
                ++letters;
            const bool known = m_target.findInstruction(one) ||
                               (letters > 0 && m_target.findInstruction(one.left(letters)) &&
                                m_target.findInstruction(one.left(letters))->fusedOperand);
            paint(words[next], known ? Mnemonic : Error);
            ++next;
        }
    }
    for (; next < words.size(); ++next) {
        const QString w = line.mid(words[next].start, words[next].length);
        const bool constant =
            std::holds_alternative<model::Constant>(model::parseConstant(m_target, w));
        paint(words[next], constant ? Constant : Device);
    }
    return styles;
}

void IlLexer::styleText(int start, int end) {
    if (!editor() || end <= start)
        return;
    // bytes() may carry a terminating NUL: style exactly end - start bytes.
    const QByteArray bytes = editor()->bytes(start, end).left(end - start);
    const QString text = QString::fromUtf8(bytes.constData(), bytes.size());
    startStyling(start);
    int styled = 0;
    const QStringList lines = text.split(QLatin1Char('\n'));
    for (qsizetype n = 0; n < lines.size(); ++n) {
        const QString &line = lines[n];
        const std::vector<int> styles = styleLine(line);
        // Scintilla styles bytes: each character takes its UTF-8 length.
        for (qsizetype i = 0; i < line.size(); ++i) {
            int length = 0;
            if (line[i].isHighSurrogate())
                length = 4;
            else if (!line[i].isLowSurrogate())
                length = static_cast<int>(QString(line[i]).toUtf8().size());
            if (length > 0 && styled + length <= bytes.size()) {
                setStyling(length, styles[static_cast<std::size_t>(i)]);
                styled += length;
            }
        }
        if (n + 1 < lines.size() && styled < bytes.size()) {
            setStyling(1, Default); // the newline
            ++styled;
        }
    }
}

IlLexer::~IlLexer() {
    // QsciAPIs prepares its word list on a worker thread that calls back into this lexer;
    // it has to finish while the lexer is still whole, not when QObject deletes children.
    if (QsciAbstractAPIs *a = apis()) {
        setAPIs(nullptr);
        delete a;
    }
}

} // namespace rung::editor
