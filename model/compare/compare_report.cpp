#include "model/compare/compare.h"
#include "model/tr.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

// The comparison as a report (docs/version-control.md): a text for people, with a "+" or "-"
// and a word on every line, so it reads without colour and on paper; JSON for programs.

namespace rung::model {

namespace {

using Kind = ItemDifference::Kind;

QString statusText(RungStatus status) {
    switch (status) {
    case RungStatus::Same:
        return CompareTr::tr("the same");
    case RungStatus::Moved:
        return CompareTr::tr("moved");
    case RungStatus::Changed:
        return CompareTr::tr("changed");
    case RungStatus::MovedChanged:
        return CompareTr::tr("moved and changed");
    case RungStatus::Inserted:
        return CompareTr::tr("inserted");
    case RungStatus::Deleted:
        return CompareTr::tr("deleted");
    }
    return {};
}

QString elementText(ElementChange::Element e) {
    switch (e) {
    case ElementChange::Element::Contact:
        return CompareTr::tr("contact");
    case ElementChange::Element::Output:
        return CompareTr::tr("output");
    case ElementChange::Element::Branches:
        break;
    }
    return CompareTr::tr("branches");
}

QString elementKey(ElementChange::Element e) {
    switch (e) {
    case ElementChange::Element::Contact:
        return QStringLiteral("contact");
    case ElementChange::Element::Output:
        return QStringLiteral("output");
    case ElementChange::Element::Branches:
        break;
    }
    return QStringLiteral("branches");
}

QString kindKey(Kind k) {
    switch (k) {
    case Kind::Added:
        return QStringLiteral("added");
    case Kind::Removed:
        return QStringLiteral("removed");
    case Kind::Changed:
        break;
    }
    return QStringLiteral("changed");
}

QString elementKindKey(ElementChange::Kind k) {
    switch (k) {
    case ElementChange::Kind::Added:
        return QStringLiteral("added");
    case ElementChange::Kind::Removed:
        return QStringLiteral("removed");
    case ElementChange::Kind::Changed:
        break;
    }
    return QStringLiteral("changed");
}

QString fieldText(const QString &field) {
    if (field == QLatin1String("name"))
        return CompareTr::tr("name");
    if (field == QLatin1String("comment"))
        return CompareTr::tr("comment");
    return field;
}

QString quoted(const QString &text) {
    return QLatin1Char('"') + text + QLatin1Char('"');
}

QString rungHeading(const RungDifference &r) {
    const QString status = statusText(r.status);
    if (r.status == RungStatus::Deleted)
        //: A rung only in the first program (A): %1 its number there, %2 "deleted".
        return CompareTr::tr("- rung %1 of A: %2").arg(r.a + 1).arg(status);
    if (r.status == RungStatus::Inserted)
        //: A rung only in the second program (B): %1 its number there, %2 "inserted".
        return CompareTr::tr("+ rung %1 of B: %2").arg(r.b + 1).arg(status);
    if (r.a == r.b)
        return CompareTr::tr("rung %1: %2").arg(r.a + 1).arg(status);
    //: A rung of A (number %1) that is rung %2 of B, and what happened to it (%3).
    return CompareTr::tr("rung %1 -> %2: %3").arg(r.a + 1).arg(r.b + 1).arg(status);
}

void writeRung(const RungDifference &r, QStringList &lines) {
    lines << rungHeading(r);
    const QString indent = QStringLiteral("    ");
    if (r.status == RungStatus::Deleted || r.status == RungStatus::Inserted) {
        const QChar mark = r.status == RungStatus::Deleted ? QLatin1Char('-') : QLatin1Char('+');
        const QString &comment = r.status == RungStatus::Deleted ? r.commentA : r.commentB;
        if (!comment.isEmpty())
            lines << indent + mark + QStringLiteral(" ; ") + comment;
        for (const QString &ins : r.instructions)
            lines << indent + mark + QLatin1Char(' ') + ins;
        return;
    }
    for (const ElementChange &e : r.elements) {
        const QString what = elementText(e.element);
        switch (e.kind) {
        case ElementChange::Kind::Added:
            lines << indent + CompareTr::tr("+ %1 added: %2").arg(what, e.after);
            break;
        case ElementChange::Kind::Removed:
            lines << indent + CompareTr::tr("- %1 removed: %2").arg(what, e.before);
            break;
        case ElementChange::Kind::Changed:
            if (e.element == ElementChange::Element::Branches) {
                lines << indent + CompareTr::tr("* the branches joining the contacts changed");
                break;
            }
            QString line =
                indent + CompareTr::tr("* %1 changed: %2 -> %3").arg(what, e.before, e.after);
            QStringList operands;
            for (const ElementChange::Operand &o : e.operands)
                //: An operand that changed: %1 its number (1 = the first), %2 and %3 the old
                //: and the new operand.
                operands << CompareTr::tr("operand %1: %2 -> %3")
                                .arg(o.index + 1)
                                .arg(o.before, o.after);
            if (!operands.isEmpty())
                line += QStringLiteral(" (%1)").arg(operands.join(QStringLiteral(", ")));
            lines << line;
            break;
        }
    }
    if (r.commentChanged)
        lines << indent + CompareTr::tr("* comment changed: %1 -> %2")
                              .arg(quoted(r.commentA), quoted(r.commentB));
}

QString itemLine(const QString &what, const ItemDifference &d) {
    //: %1 what ("symbol X0", "set value T0"), %2 the field ("name", "comment", "value").
    switch (d.kind) {
    case Kind::Added:
        return CompareTr::tr("+ %1 added: %2 %3").arg(what, fieldText(d.field), quoted(d.after));
    case Kind::Removed:
        return CompareTr::tr("- %1 removed: %2 %3").arg(what, fieldText(d.field), quoted(d.before));
    case Kind::Changed:
        break;
    }
    return CompareTr::tr("* %1 changed: %2 %3 -> %4")
        .arg(what, fieldText(d.field), quoted(d.before), quoted(d.after));
}

QString watchLine(const ItemDifference &d) {
    const QString list = quoted(d.key);
    if (d.field == QLatin1String("devices"))
        return d.kind == Kind::Added
                   ? CompareTr::tr("+ watch list %1 added: %2").arg(list, d.after)
                   : CompareTr::tr("- watch list %1 removed: %2").arg(list, d.before);
    if (d.field == QLatin1String("device"))
        return d.kind == Kind::Added
                   ? CompareTr::tr("+ watch list %1: %2 added").arg(list, d.subject)
                   : CompareTr::tr("- watch list %1: %2 removed").arg(list, d.subject);
    if (d.field == QLatin1String("order"))
        return CompareTr::tr("* watch list %1: the order changed: %2 -> %3")
            .arg(list, d.before, d.after);
    //: A watch list row shown in another format: %1 the list, %2 the device, %3 and %4 the
    //: formats (dec, signed, hex, bin, bcd).
    return CompareTr::tr("* watch list %1: %2 shown as %3 -> %4")
        .arg(list, d.subject, d.before, d.after);
}

QString pendingLine(const ItemDifference &d) {
    if (d.key == QLatin1String("pendingListing")) {
        switch (d.kind) {
        case Kind::Added:
            return CompareTr::tr(
                "+ B holds an instruction list typed with errors that is not in its "
                "rungs (pendingListing)");
        case Kind::Removed:
            return CompareTr::tr(
                "- A holds an instruction list typed with errors that is not in its "
                "rungs (pendingListing)");
        case Kind::Changed:
            break;
        }
        return CompareTr::tr("* the instruction lists typed with errors that are not in the rungs "
                             "differ (pendingListing)");
    }
    return d.kind == Kind::Added ? CompareTr::tr("+ symbol row not yet a symbol: %1").arg(d.after)
                                 : CompareTr::tr("- symbol row not yet a symbol: %1").arg(d.before);
}

} // namespace

QString rungStatusKey(RungStatus status) {
    switch (status) {
    case RungStatus::Same:
        return QStringLiteral("same");
    case RungStatus::Moved:
        return QStringLiteral("moved");
    case RungStatus::Changed:
        return QStringLiteral("changed");
    case RungStatus::MovedChanged:
        return QStringLiteral("moved-changed");
    case RungStatus::Inserted:
        return QStringLiteral("inserted");
    case RungStatus::Deleted:
        return QStringLiteral("deleted");
    }
    return {};
}

QString comparisonText(const Comparison &c, const QString &nameA, const QString &nameB) {
    QStringList lines;
    lines << QStringLiteral("--- A: %1").arg(nameA) << QStringLiteral("+++ B: %1").arg(nameB);
    if (c.modelA != c.modelB)
        lines << CompareTr::tr("* model changed: %1 -> %2").arg(c.modelA, c.modelB);
    for (const RungDifference &r : c.rungs)
        if (r.status != RungStatus::Same)
            writeRung(r, lines);
    for (const ItemDifference &d : c.symbols)
        lines << itemLine(CompareTr::tr("symbol %1").arg(d.key), d);
    for (const ItemDifference &d : c.setValues)
        lines << itemLine(CompareTr::tr("set value %1").arg(d.key), d);
    for (const ItemDifference &d : c.watchLists)
        lines << watchLine(d);
    for (const ItemDifference &d : c.pending)
        lines << pendingLine(d);
    const int rungsA = static_cast<int>(std::count_if(
        c.rungs.begin(), c.rungs.end(), [](const RungDifference &r) { return r.a >= 0; }));
    const int rungsB = static_cast<int>(std::count_if(
        c.rungs.begin(), c.rungs.end(), [](const RungDifference &r) { return r.b >= 0; }));
    if (c.equal()) {
        lines << CompareTr::tr("The programs are the same (rungs: %1).").arg(rungsB);
    } else {
        //: The summary of a comparison: %1 rungs in A, %2 in B, then how many of each kind.
        lines << CompareTr::tr(
                     "Rungs: %1 in A, %2 in B; %3 the same, %4 moved, %5 changed, %6 moved "
                     "and changed, %7 inserted, %8 deleted.")
                     .arg(rungsA)
                     .arg(rungsB)
                     .arg(c.count(RungStatus::Same))
                     .arg(c.count(RungStatus::Moved))
                     .arg(c.count(RungStatus::Changed))
                     .arg(c.count(RungStatus::MovedChanged))
                     .arg(c.count(RungStatus::Inserted))
                     .arg(c.count(RungStatus::Deleted));
    }
    return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

QByteArray comparisonJson(const Comparison &c, const QString &nameA, const QString &nameB) {
    QJsonObject root;
    root.insert(QStringLiteral("a"), nameA);
    root.insert(QStringLiteral("b"), nameB);
    root.insert(QStringLiteral("target"), c.target ? c.target->id : QString());
    root.insert(QStringLiteral("equal"), c.equal());
    root.insert(QStringLiteral("model"),
                QJsonObject{{QStringLiteral("a"), c.modelA}, {QStringLiteral("b"), c.modelB}});
    QJsonObject summary;
    for (RungStatus s : {RungStatus::Same, RungStatus::Moved, RungStatus::Changed,
                         RungStatus::MovedChanged, RungStatus::Inserted, RungStatus::Deleted})
        summary.insert(rungStatusKey(s), c.count(s));
    root.insert(QStringLiteral("summary"), summary);
    QJsonArray rungs;
    for (const RungDifference &r : c.rungs) {
        QJsonObject o;
        o.insert(QStringLiteral("status"), rungStatusKey(r.status));
        // Numbers as the report and the IDE show them (1 = the first rung); null: none.
        o.insert(QStringLiteral("a"), r.a >= 0 ? QJsonValue(r.a + 1) : QJsonValue());
        o.insert(QStringLiteral("b"), r.b >= 0 ? QJsonValue(r.b + 1) : QJsonValue());
        if (r.commentChanged)
            o.insert(QStringLiteral("comment"), QJsonObject{{QStringLiteral("a"), r.commentA},
                                                            {QStringLiteral("b"), r.commentB}});
        if (!r.elements.empty()) {
            QJsonArray elements;
            for (const ElementChange &e : r.elements) {
                QJsonObject eo;
                eo.insert(QStringLiteral("element"), elementKey(e.element));
                eo.insert(QStringLiteral("change"), elementKindKey(e.kind));
                if (!e.before.isEmpty())
                    eo.insert(QStringLiteral("before"), e.before);
                if (!e.after.isEmpty())
                    eo.insert(QStringLiteral("after"), e.after);
                if (!e.operands.empty()) {
                    QJsonArray operands;
                    for (const ElementChange::Operand &op : e.operands)
                        operands.append(QJsonObject{{QStringLiteral("operand"), op.index + 1},
                                                    {QStringLiteral("before"), op.before},
                                                    {QStringLiteral("after"), op.after}});
                    eo.insert(QStringLiteral("operands"), operands);
                }
                elements.append(eo);
            }
            o.insert(QStringLiteral("elements"), elements);
        }
        if (r.status == RungStatus::Inserted || r.status == RungStatus::Deleted) {
            o.insert(QStringLiteral("instructions"), QJsonArray::fromStringList(r.instructions));
            const QString &comment = r.status == RungStatus::Deleted ? r.commentA : r.commentB;
            if (!comment.isEmpty())
                o.insert(QStringLiteral("comment"), comment);
        }
        rungs.append(o);
    }
    root.insert(QStringLiteral("rungs"), rungs);
    auto items = [](const std::vector<ItemDifference> &list, const QString &keyName) {
        QJsonArray out;
        for (const ItemDifference &d : list) {
            QJsonObject o;
            o.insert(keyName, d.key);
            o.insert(QStringLiteral("change"), kindKey(d.kind));
            o.insert(QStringLiteral("field"), d.field);
            if (!d.subject.isEmpty())
                o.insert(QStringLiteral("device"), d.subject);
            if (d.kind != Kind::Added)
                o.insert(QStringLiteral("before"), d.before);
            if (d.kind != Kind::Removed)
                o.insert(QStringLiteral("after"), d.after);
            out.append(o);
        }
        return out;
    };
    root.insert(QStringLiteral("symbols"), items(c.symbols, QStringLiteral("device")));
    root.insert(QStringLiteral("setValues"), items(c.setValues, QStringLiteral("device")));
    root.insert(QStringLiteral("watchLists"), items(c.watchLists, QStringLiteral("list")));
    root.insert(QStringLiteral("pending"), items(c.pending, QStringLiteral("key")));
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

} // namespace rung::model
