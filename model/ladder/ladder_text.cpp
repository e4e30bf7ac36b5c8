#include "model/ladder/ladder_text.h"

#include "model/target/address.h"
#include "model/target/target_lists.h"
#include "model/tr.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QStringList>

// The plain-text ladder (docs/ladder-text.md):
//
//   LADDER vigor WIDTH 10
//   RUNG 1 ROWS 2 COLUMNS 2
//   ; comment line
//   |-[ X0    ]-+-[/X1    ]--(OUT Y0)
//   |           |
//   |-[ M0    ]-+
//
// Cells are WIDTH characters wide with one node character between them; a connector line
// under each row but the last marks the vertical links with '|'.

namespace rung::model {

namespace {

QChar markOf(const Contact &c) {
    if (c.invert)
        return QLatin1Char('~');
    switch (c.mode) {
    case ContactMode::Normal:
        return QLatin1Char(' ');
    case ContactMode::Negated:
        return QLatin1Char('/');
    case ContactMode::Rising:
        return QLatin1Char('P');
    case ContactMode::Falling:
        return QLatin1Char('N');
    }
    return QLatin1Char(' ');
}

QString contactText(const Target &t, const Contact &c) {
    if (c.invert)
        return invertText(c);
    if (c.operands.empty())
        return {};
    if (c.compare != CompareOp::None && c.operands.size() >= 2)
        return formatOperand(t, c.operands[0]) + QLatin1String(compareSymbol(c.compare)) +
               formatOperand(t, c.operands[1]);
    return formatOperand(t, c.operands[0]);
}

} // namespace

QString invertText(const Contact &c) {
    return c.mode == ContactMode::Rising    ? QStringLiteral("P")
           : c.mode == ContactMode::Falling ? QStringLiteral("N")
                                            : QString();
}

QString printLadderText(const LadderProgram &ladder) {
    if (!ladder.target)
        return {};
    const Target &t = *ladder.target;
    qsizetype longest = 3;
    for (const Rung &rung : ladder.rungs)
        for (const Cell &cell : rung.cells)
            if (cell.kind == CellKind::Contact)
                longest = std::max(longest, contactText(t, cell.contact).size());
    const int width = static_cast<int>(longest) + 5;
    QString out = QStringLiteral("LADDER %1 WIDTH %2\n").arg(t.id).arg(width);
    for (std::size_t n = 0; n < ladder.rungs.size(); ++n) {
        const Rung &rung = ladder.rungs[n];
        out += QStringLiteral("RUNG %1 ROWS %2 COLUMNS %3\n")
                   .arg(n + 1)
                   .arg(rung.rows)
                   .arg(rung.columns);
        if (!rung.comment.isEmpty())
            for (const QString &line : rung.comment.split(QLatin1Char('\n')))
                out += QLatin1String("; ") + line + QLatin1Char('\n');
        std::vector<int> extraInputs(static_cast<std::size_t>(rung.rows), 0);
        for (int r = 0; r < rung.rows; ++r)
            if (rung.outputs[static_cast<std::size_t>(r)])
                for (int in : rung.boxInputRows(r))
                    if (in != r)
                        extraInputs[static_cast<std::size_t>(in)] = 1;
        for (int r = 0; r < rung.rows; ++r) {
            QString line = QStringLiteral("|");
            for (int c = 0; c < rung.columns; ++c) {
                const Cell &cell = rung.cell(r, c);
                switch (cell.kind) {
                case CellKind::Empty:
                    line += QString(width, QLatin1Char(' '));
                    break;
                case CellKind::Wire:
                    line += QString(width, QLatin1Char('-'));
                    break;
                case CellKind::Contact: {
                    QString text =
                        QLatin1String("-[") + markOf(cell.contact) + contactText(t, cell.contact);
                    text = text.leftJustified(width - 2, QLatin1Char(' ')) + QLatin1String("]-");
                    line += text;
                    break;
                }
                }
                const bool linked = rung.link(r, c + 1) || (r > 0 && rung.link(r - 1, c + 1));
                const bool left = cell.kind != CellKind::Empty;
                const bool right = c + 1 < rung.columns
                                       ? rung.cell(r, c + 1).kind != CellKind::Empty
                                       : rung.outputs[static_cast<std::size_t>(r)].has_value();
                line += linked            ? QLatin1Char('+')
                        : (left || right) ? QLatin1Char('-')
                                          : QLatin1Char(' ');
            }
            if (rung.columns == 0)
                line += rung.link(r, 0) ? QLatin1Char('+') : QLatin1Char('-');
            const auto &o = rung.outputs[static_cast<std::size_t>(r)];
            if (o)
                line += QLatin1Char('(') + printInstruction(t, *o) + QLatin1Char(')');
            else if (extraInputs[static_cast<std::size_t>(r)])
                line += QLatin1String("(^)");
            out += line + QLatin1Char('\n');
            if (r + 1 < rung.rows) {
                // A link drawn on the rail (the editor allows it) shows as '+' on the rail.
                QString connector =
                    rung.columns > 0 && rung.link(r, 0) ? QStringLiteral("+") : QStringLiteral("|");
                for (int c = 0; c < rung.columns; ++c)
                    connector += QString(width, QLatin1Char(' ')) +
                                 (rung.link(r, c + 1) ? QLatin1Char('|') : QLatin1Char(' '));
                while (connector.endsWith(QLatin1Char(' ')))
                    connector.chop(1);
                out += connector + QLatin1Char('\n');
            }
        }
        out += QLatin1Char('\n');
    }
    return out;
}

namespace {

class TextReader {
public:
    TextReader(const Target &target, const ModelVariant *model, const QString &text)
        : m_target(target)
        , m_model(model)
        , m_lines(text.split(QLatin1Char('\n'))) {
        for (QString &l : m_lines)
            if (l.endsWith(QLatin1Char('\r')))
                l.chop(1);
        m_result.ladder.target = &target;
    }

    LadderTextResult run() {
        skipBlank();
        if (m_at >= m_lines.size() || !readHeader())
            return std::move(m_result);
        while (true) {
            skipBlank();
            if (m_at >= m_lines.size())
                break;
            if (!readRung())
                break;
        }
        return std::move(m_result);
    }

    // One cell's contact as a project holds it (contactFromText): read as the drawing's cells
    // are, without a drawing around it.
    std::optional<Contact> oneContact(const QString &inside, QString *why) {
        Contact contact;
        if (readContact(inside, 0, &contact))
            return contact;
        if (why)
            *why = m_result.errors.empty() ? QString() : m_result.errors.front().message;
        return std::nullopt;
    }

private:
    void error(qsizetype line, int column, const QString &message) {
        m_result.errors.push_back({static_cast<int>(line) + 1, column + 1, message});
    }

    void skipBlank() {
        while (m_at < m_lines.size() && m_lines[m_at].trimmed().isEmpty())
            ++m_at;
    }

    bool readHeader() {
        const QStringList parts = m_lines[m_at].simplified().split(QLatin1Char(' '));
        if (parts.size() != 4 || parts[0] != QLatin1String("LADDER") ||
            parts[2] != QLatin1String("WIDTH")) {
            error(m_at, 0,
                  LadderTextTr::tr("A ladder text starts with \"LADDER <target> WIDTH <n>\""));
            return false;
        }
        if (parts[1].compare(m_target.id, Qt::CaseInsensitive) != 0) {
            error(m_at, 7,
                  LadderTextTr::tr("This ladder is for %1, not %2").arg(parts[1], m_target.id));
            return false;
        }
        bool ok = false;
        m_width = parts[3].toInt(&ok);
        if (!ok || m_width < 5 || m_width > 200) {
            error(m_at, 0, LadderTextTr::tr("The cell width must be a number from 5 to 200"));
            return false;
        }
        ++m_at;
        return true;
    }

    bool readRung() {
        const qsizetype headerLine = m_at;
        const QStringList parts = m_lines[m_at].simplified().split(QLatin1Char(' '));
        bool okRows = false;
        bool okColumns = false;
        const int rows = parts.size() == 6 ? parts[3].toInt(&okRows) : 0;
        const int columns = parts.size() == 6 ? parts[5].toInt(&okColumns) : 0;
        if (parts.size() != 6 || parts[0] != QLatin1String("RUNG") ||
            parts[2] != QLatin1String("ROWS") || parts[4] != QLatin1String("COLUMNS") || !okRows ||
            !okColumns || rows < 1 || rows > 1000 || columns < 0 || columns > 1000) {
            error(m_at, 0, LadderTextTr::tr("Expected \"RUNG <n> ROWS <rows> COLUMNS <columns>\""));
            return false;
        }
        ++m_at;
        Rung rung(rows, columns);
        QStringList comment;
        while (m_at < m_lines.size() && m_lines[m_at].startsWith(QLatin1Char(';'))) {
            QString c = m_lines[m_at].mid(1);
            if (c.startsWith(QLatin1Char(' ')))
                c.remove(0, 1);
            comment << c;
            ++m_at;
        }
        rung.comment = comment.join(QLatin1Char('\n'));
        int boxRow = -1;
        for (int r = 0; r < rows; ++r) {
            if (m_at >= m_lines.size()) {
                error(headerLine, 0,
                      LadderTextTr::tr("The rung has fewer rows than its header says"));
                return false;
            }
            if (!readRow(rung, r, &boxRow))
                return false;
            ++m_at;
            if (r + 1 < rows) {
                if (m_at >= m_lines.size()) {
                    error(headerLine, 0,
                          LadderTextTr::tr("The rung has fewer rows than its header says"));
                    return false;
                }
                readConnector(rung, r);
                ++m_at;
            }
        }
        m_result.ladder.rungs.push_back(std::move(rung));
        return true;
    }

    bool readRow(Rung &rung, int r, int *boxRow) {
        const QString &line = m_lines[m_at];
        if (!line.startsWith(QLatin1Char('|'))) {
            error(m_at, 0, LadderTextTr::tr("A row starts with the left rail '|'"));
            return false;
        }
        const int stride = m_width + 1;
        for (int c = 0; c < rung.columns; ++c) {
            const int at = 1 + c * stride;
            const QString cell = line.mid(at, m_width).leftJustified(m_width, QLatin1Char(' '));
            if (cell.trimmed().isEmpty())
                continue;
            if (cell == QString(m_width, QLatin1Char('-'))) {
                rung.cell(r, c).kind = CellKind::Wire;
                continue;
            }
            if (!cell.startsWith(QLatin1String("-[")) || !cell.endsWith(QLatin1String("]-"))) {
                error(m_at, at,
                      LadderTextTr::tr("A cell is empty, a wire, or a contact \"-[ %1 ]-\"")
                          .arg(exampleDevice(m_target)));
                return false;
            }
            Contact contact;
            if (!readContact(cell.mid(2, m_width - 4), at + 2, &contact))
                return false;
            rung.cell(r, c).kind = CellKind::Contact;
            rung.cell(r, c).contact = contact;
        }
        const int outputAt = 1 + rung.columns * stride + (rung.columns == 0 ? 1 : 0);
        const QString output = line.mid(outputAt).trimmed();
        if (rung.columns == 0 && line.mid(1, 1) == QLatin1String("+"))
            rung.setLink(r, 0, true);
        if (output.isEmpty())
            return true;
        if (!output.startsWith(QLatin1Char('(')) || !output.endsWith(QLatin1Char(')'))) {
            const InstructionSpec *coil = m_target.findInstruction(Op::Out);
            error(m_at, outputAt,
                  LadderTextTr::tr("An output is written in parentheses: (%1 %2)")
                      .arg(coil ? coil->mnemonic : QString(), exampleDevice(m_target, true)));
            return false;
        }
        const QString inner = output.mid(1, output.size() - 2);
        if (inner == QLatin1String("^")) {
            if (*boxRow < 0) {
                error(m_at, outputAt,
                      LadderTextTr::tr("(^) marks a further input of a box above it"));
                return false;
            }
            rung.inputRows.push_back(r);
            return true;
        }
        ParseResult parsed = parseInstructionList(m_target, inner, m_model);
        if (!parsed.ok() || parsed.list.instructions.size() != 1) {
            const ParseError e =
                parsed.errors.empty()
                    ? ParseError{1, 1, LadderTextTr::tr("One output instruction is expected")}
                    : parsed.errors.front();
            error(m_at, outputAt + e.column, e.message);
            return false;
        }
        Instruction ins = parsed.list.instructions.front();
        ins.line = 0;
        ins.column = 0;
        ins.step = 0;
        rung.outputs[static_cast<std::size_t>(r)] = ins;
        if (ins.spec->inputs > 1) {
            *boxRow = r;
            rung.inputRows = {r};
        }
        return true;
    }

    bool readOperand(const QString &text, int column, Operand *out) {
        auto o = parseOperand(m_target, text, m_model);
        if (auto *operand = std::get_if<Operand>(&o)) {
            *out = *operand;
            return true;
        }
        const AddressError &e = std::get<AddressError>(o);
        error(m_at, column + e.column, e.message);
        return false;
    }

    bool readContact(const QString &inside, int column, Contact *contact) {
        const QChar mark = inside.isEmpty() ? QLatin1Char(' ') : inside[0];
        const QString body = inside.mid(1).trimmed();
        if (mark == QLatin1Char('~')) {
            contact->invert = true;
            if (body == QLatin1String("P"))
                contact->mode = ContactMode::Rising;
            else if (body == QLatin1String("N"))
                contact->mode = ContactMode::Falling;
            else if (!body.isEmpty()) {
                error(m_at, column + 1,
                      LadderTextTr::tr("'~%1': a power-flow element is ~, ~P or ~N").arg(body));
                return false;
            }
            return true;
        }
        if (mark == QLatin1Char('/'))
            contact->mode = ContactMode::Negated;
        else if (mark == QLatin1Char('P'))
            contact->mode = ContactMode::Rising;
        else if (mark == QLatin1Char('N'))
            contact->mode = ContactMode::Falling;
        else if (mark != QLatin1Char(' ')) {
            error(
                m_at, column,
                LadderTextTr::tr("'%1' is not a contact mark (' ', '/', 'P', 'N', '~')").arg(mark));
            return false;
        }
        if (body.isEmpty()) {
            error(m_at, column, LadderTextTr::tr("The contact has no device"));
            return false;
        }
        if (const std::optional<CompareAt> c = findCompare(body)) {
            Operand a;
            Operand b;
            if (!readOperand(body.left(c->at), column + 1, &a) ||
                !readOperand(body.mid(c->at + c->length), column + 1 + static_cast<int>(c->at), &b))
                return false;
            contact->compare = c->op;
            contact->operands = {a, b};
            return true;
        }
        Operand o;
        if (!readOperand(body, column + 1, &o))
            return false;
        if (o.modified()) {
            // A contact reads one bit: K4M0 is a word, an index modifies words only.
            error(m_at, column + 1,
                  LadderTextTr::tr("%1 is a word; a contact takes a bit device").arg(body));
            return false;
        }
        contact->operands = {o};
        return true;
    }

    void readConnector(Rung &rung, int r) {
        const QString &line = m_lines[m_at];
        const int stride = m_width + 1;
        if (rung.columns > 0 && line.startsWith(QLatin1Char('+')))
            rung.setLink(r, 0, true);
        for (int c = 0; c < rung.columns; ++c) {
            const int at = 1 + c * stride + m_width;
            if (at < line.size() && line[at] == QLatin1Char('|'))
                rung.setLink(r, c + 1, true);
        }
    }

    const Target &m_target;
    const ModelVariant *m_model;
    QStringList m_lines;
    qsizetype m_at = 0;
    int m_width = 10;
    LadderTextResult m_result;
};

} // namespace

QString contactToText(const Target &target, const Contact &contact) {
    if (contact.invert)
        return QLatin1Char('~') + invertText(contact);
    QString mark;
    switch (contact.mode) {
    case ContactMode::Normal:
        break;
    case ContactMode::Negated:
        mark = QStringLiteral("/");
        break;
    case ContactMode::Rising:
        mark = QStringLiteral("^");
        break;
    case ContactMode::Falling:
        mark = QStringLiteral("_");
        break;
    }
    return mark + contactText(target, contact);
}

std::optional<Contact> contactFromText(const Target &target, const QString &text, QString *error,
                                       const ModelVariant *model) {
    QString body = text.trimmed();
    QChar mark = QLatin1Char(' ');
    if (body == QLatin1String("~") || body == QLatin1String("~P") || body == QLatin1String("~N"))
        mark = QLatin1Char('~');
    else if (body.startsWith(QLatin1Char('/')))
        mark = QLatin1Char('/');
    else if (body.startsWith(QLatin1Char('^')))
        mark = QLatin1Char('P');
    else if (body.startsWith(QLatin1Char('_')))
        mark = QLatin1Char('N');
    if (mark != QLatin1Char(' '))
        body.remove(0, 1);
    // The ladder text's reader of a cell, without a one-cell drawing to parse around it (that
    // was a fifth of File > Open's work for a large project).
    QString why;
    std::optional<Contact> contact =
        TextReader(target, model, QString()).oneContact(QString(mark) + body, &why);
    if (!contact && error)
        *error = why.isEmpty() ? LadderTextTr::tr("'%1' is not a contact").arg(text) : why;
    return contact;
}

QString ladderTextTarget(const QString &text) {
    static const QRegularExpression re(QStringLiteral("^\\s*LADDER\\s+(\\w+)"));
    const QRegularExpressionMatch m = re.match(text);
    return m.hasMatch() ? m.captured(1) : QString();
}

LadderTextResult parseLadderText(const Target &target, const QString &text,
                                 const ModelVariant *model) {
    return TextReader(target, model, text).run();
}

} // namespace rung::model
