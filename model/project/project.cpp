#include "model/project/project.h"

#include "model/comm/port_config.h"

#include "model/ladder/ladder_text.h"
#include "model/project/file_read.h"
#include "model/tr.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>

#include <cmath>

// The project file (docs/project-format.md): one JSON object, keys in a fixed order, one rung
// per object with its cells as short strings, so a change to one contact is a one-line diff.

namespace rung::model {

namespace {

constexpr qint64 kMaxProjectBytes = 64 * 1024 * 1024;
constexpr double kMaxSetValue = 2147483647.0; // the widest set value is a 32-bit register
const char *const kFormat = "rungstudio-project";

QString deviceText(const Target &t, const Address &a) {
    return formatAddress(t, a);
}

// ---- writing ----------------------------------------------------------------------------
// Written by hand rather than by QJsonDocument, so that the layout serves a diff and a merge:
// keys in one fixed order (the order a reader wants them: what, then the rungs), a rung's
// row of cells on one line, an output on one line, a symbol on one line. A change to one
// contact changes one line, and two people's changes to two rungs touch different lines.

// A JSON string: quotes, backslashes and control characters escaped, the rest as UTF-8.
QByteArray jsonString(const QString &text) {
    QByteArray out;
    out.reserve(text.size() + 2);
    out += '"';
    for (const char c : text.toUtf8()) {
        const auto u = static_cast<unsigned char>(c);
        switch (c) {
        case '"':
            out += "\\\"";
            break;
        case '\\':
            out += "\\\\";
            break;
        case '\n':
            out += "\\n";
            break;
        case '\r':
            out += "\\r";
            break;
        case '\t':
            out += "\\t";
            break;
        case '\b':
            out += "\\b";
            break;
        case '\f':
            out += "\\f";
            break;
        default:
            if (u < 0x20)
                out += QStringLiteral("\\u%1").arg(u, 4, 16, QLatin1Char('0')).toLatin1();
            else
                out += c;
        }
    }
    out += '"';
    return out;
}

QByteArray number(qint64 value) {
    return QByteArray::number(value);
}

class Writer {
public:
    QByteArray out;

    // "key": value at this depth, with a comma before it when it is not the object's first.
    void key(int depth, const char *name) {
        separate(depth);
        out += QByteArray(4 * depth, ' ') + '"' + name + "\": ";
    }
    void open(char bracket) {
        out += bracket;
        m_first.push_back(true);
    }
    void close(int depth, char bracket) {
        const bool empty = m_first.back();
        m_first.pop_back();
        if (!empty)
            out += '\n' + QByteArray(4 * depth, ' ');
        out += bracket;
    }
    // The next element of the array open at depth - 1, on a line of its own.
    void element(int depth) {
        separate(depth);
        out += QByteArray(4 * depth, ' ');
    }

private:
    void separate(int) {
        if (!m_first.back())
            out += ',';
        out += '\n';
        m_first.back() = false;
    }
    std::vector<bool> m_first;
};

QByteArray cellText(const Target &t, const Cell &cell) {
    switch (cell.kind) {
    case CellKind::Empty:
        return jsonString(QString());
    case CellKind::Wire:
        return jsonString(QStringLiteral("-"));
    case CellKind::Contact:
        break;
    }
    return jsonString(contactToText(t, cell.contact));
}

void writeRung(Writer &w, const Target &t, const Rung &rung) {
    w.open('{');
    if (!rung.comment.isEmpty()) {
        w.key(3, "comment");
        w.out += jsonString(rung.comment);
    }
    w.key(3, "rows");
    w.out += number(rung.rows);
    w.key(3, "columns");
    w.out += number(rung.columns);
    w.key(3, "cells");
    w.open('[');
    for (int r = 0; r < rung.rows; ++r) {
        w.element(4);
        QByteArrayList row;
        for (int c = 0; c < rung.columns; ++c)
            row << cellText(t, rung.cell(r, c));
        w.out += '[' + row.join(", ") + ']';
    }
    w.close(3, ']');
    QByteArrayList links;
    for (int r = 0; r + 1 < rung.rows; ++r)
        for (int c = 0; c <= rung.columns; ++c)
            if (rung.link(r, c))
                links << '[' + number(r) + ", " + number(c) + ']';
    w.key(3, "links");
    w.out += '[' + links.join(", ") + ']';
    w.key(3, "outputs");
    w.open('[');
    for (int r = 0; r < rung.rows; ++r) {
        const auto &out = rung.outputs[static_cast<std::size_t>(r)];
        if (!out)
            continue;
        w.element(4);
        w.out += '[' + number(r) + ", " + jsonString(printInstruction(t, *out));
        // Only rows the rung names explicitly: a box without them takes r..r+k-1 on reading.
        const int k = out->spec ? out->spec->inputs : 1;
        if (k > 1 && !rung.inputRows.empty() && rung.inputRows.front() == r) {
            QByteArrayList rows;
            for (int i : rung.inputRows)
                rows << number(i);
            w.out += ", [" + rows.join(", ") + ']';
        }
        w.out += ']';
    }
    w.close(3, ']');
    w.close(2, '}');
}

// A symbol row on one line: { "device": "X0", "name": "Start", "comment": "green button" }.
QByteArray symbolLine(const QString &device, const QString &name, const QString &comment) {
    QByteArray line = "{ \"device\": " + jsonString(device) + ", \"name\": " + jsonString(name);
    if (!comment.isEmpty())
        line += ", \"comment\": " + jsonString(comment);
    return line + " }";
}

// ---- reading ----------------------------------------------------------------------------

class Reader {
public:
    explicit Reader(ProjectError *error)
        : m_error(error) {}

    std::optional<Project> read(const QByteArray &json) {
        QJsonParseError parseError;
        const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
        if (parseError.error != QJsonParseError::NoError) {
            int line = 1;
            int column = 1;
            for (qsizetype i = 0; i < std::min<qsizetype>(parseError.offset, json.size()); ++i) {
                if (json[i] == '\n') {
                    ++line;
                    column = 1;
                } else {
                    ++column;
                }
            }
            return fail(
                ProjectTr::tr("Line %1, column %2 (byte %3): the file is not valid JSON (%4)")
                    .arg(line)
                    .arg(column)
                    .arg(parseError.offset)
                    .arg(parseError.errorString()));
        }
        if (!doc.isObject())
            return fail(ProjectTr::tr(
                "The file is JSON but not a Rung Studio project (no top-level object)"));
        const QJsonObject root = doc.object();
        if (root.value(QStringLiteral("format")).toString() != QLatin1String(kFormat))
            return fail(
                ProjectTr::tr(
                    "The file is JSON but not a Rung Studio project (\"format\" is not \"%1\")")
                    .arg(QLatin1String(kFormat)));
        const int schema = root.value(QStringLiteral("schema")).toInt(-1);
        if (schema > kProjectSchemaVersion)
            return fail(
                ProjectTr::tr(
                    "The project was written by a newer Rung Studio (schema %1); this version "
                    "reads schema %2 and older")
                    .arg(schema)
                    .arg(kProjectSchemaVersion));
        if (schema < 1)
            return fail(ProjectTr::tr("\"schema\" must be a positive number"));
        if (!expect(root, "target", QJsonValue::String, QString()) ||
            !expect(root, "model", QJsonValue::String, QString()) ||
            !expect(root, "rungs", QJsonValue::Array, QString()) ||
            !expect(root, "symbols", QJsonValue::Array, QString()) ||
            !expect(root, "setValues", QJsonValue::Object, QString()) ||
            !expect(root, "watchLists", QJsonValue::Array, QString()) ||
            !expect(root, "pendingListing", QJsonValue::String, QString()) ||
            !expect(root, "pendingSymbols", QJsonValue::Array, QString()) ||
            !expect(root, "ports", QJsonValue::Object, QString()))
            return std::nullopt;
        Project p;
        const QString targetId = root.value(QStringLiteral("target")).toString();
        p.target = Target::byId(targetId);
        if (!p.target)
            return fail(ProjectTr::tr("\"target\": unknown PLC family \"%1\"").arg(targetId));
        p.model = root.value(QStringLiteral("model")).toString();
        const ModelVariant *model = p.target->model(p.model);
        if (!p.model.isEmpty() && !model)
            return fail(ProjectTr::tr("\"model\": %1 has no model \"%2\"")
                            .arg(p.target->displayName, p.model));
        if (p.model.isEmpty())
            p.model = p.target->defaultModel().name;
        p.program.target = p.target;
        const QJsonArray rungs = root.value(QStringLiteral("rungs")).toArray();
        for (qsizetype i = 0; i < rungs.size(); ++i) {
            Rung rung;
            if (!readRung(*p.target, model, rungs[i], QStringLiteral("rungs[%1]").arg(i), &rung))
                return std::nullopt;
            p.program.rungs.push_back(std::move(rung));
        }
        // The PLC's port settings (docs/network-format.md), checked against the target's ports
        // and kept as written.
        p.ports = root.value(QStringLiteral("ports")).toObject();
        QString portError;
        if (!checkPortsJson(*p.target, model, p.ports, QStringLiteral("ports"), &portError))
            return fail(portError);
        const QJsonArray symbols = root.value(QStringLiteral("symbols")).toArray();
        for (qsizetype i = 0; i < symbols.size(); ++i) {
            const QString where = QStringLiteral("symbols[%1]").arg(i);
            if (!symbols[i].isObject())
                return fail(ProjectTr::tr("%1: an object with \"device\" and \"name\" is expected")
                                .arg(where));
            const QJsonObject s = symbols[i].toObject();
            if (!expect(s, "device", QJsonValue::String, where) ||
                !expect(s, "name", QJsonValue::String, where) ||
                !expect(s, "comment", QJsonValue::String, where))
                return std::nullopt;
            Symbol symbol;
            if (!device(*p.target, s.value(QStringLiteral("device")).toString(), where,
                        &symbol.address))
                return std::nullopt;
            symbol.name = s.value(QStringLiteral("name")).toString();
            symbol.comment = s.value(QStringLiteral("comment")).toString();
            p.symbols.push_back(symbol);
        }
        const QJsonObject setValues = root.value(QStringLiteral("setValues")).toObject();
        for (auto it = setValues.begin(); it != setValues.end(); ++it) {
            Address a;
            if (!device(*p.target, it.key(), QStringLiteral("setValues"), &a))
                return std::nullopt;
            // Range-checked before the cast: converting an out-of-range double is undefined.
            const double v = it.value().toDouble();
            if (!it.value().isDouble() || v != std::floor(v) || std::fabs(v) > kMaxSetValue)
                return fail(
                    ProjectTr::tr("setValues.%1: a whole number between -%2 and %2 is expected")
                        .arg(it.key())
                        .arg(kMaxSetValue, 0, 'f', 0));
            p.setValues[a] = static_cast<qint64>(v);
        }
        const QJsonArray watch = root.value(QStringLiteral("watchLists")).toArray();
        for (qsizetype i = 0; i < watch.size(); ++i) {
            const QString where = QStringLiteral("watchLists[%1]").arg(i);
            if (!watch[i].isObject())
                return fail(ProjectTr::tr("%1: an object with \"name\" and \"devices\" is expected")
                                .arg(where));
            const QJsonObject w = watch[i].toObject();
            if (!expect(w, "name", QJsonValue::String, where) ||
                !expect(w, "devices", QJsonValue::Array, where) ||
                !expect(w, "formats", QJsonValue::Object, where))
                return std::nullopt;
            WatchList list;
            list.name = w.value(QStringLiteral("name")).toString();
            const QJsonArray devices = w.value(QStringLiteral("devices")).toArray();
            for (qsizetype d = 0; d < devices.size(); ++d) {
                if (!devices[d].isString())
                    return fail(ProjectTr::tr("%1.devices[%2]: a device name is expected")
                                    .arg(where)
                                    .arg(d));
                list.devices << devices[d].toString();
            }
            const QJsonObject formats = w.value(QStringLiteral("formats")).toObject();
            for (auto it = formats.begin(); it != formats.end(); ++it) {
                const auto format = valueFormatFromKey(it.value().toString());
                if (!format)
                    return fail(
                        ProjectTr::tr("%1.formats.%2: \"%3\" is no format (dec, signed, hex, "
                                      "bin, bcd)")
                            .arg(where, it.key(), it.value().toString()));
                list.formats[it.key()] = *format;
            }
            p.watchLists.push_back(list);
        }
        p.pendingListing = root.value(QStringLiteral("pendingListing")).toString();
        const QJsonArray pending = root.value(QStringLiteral("pendingSymbols")).toArray();
        for (qsizetype i = 0; i < pending.size(); ++i) {
            const QString where = QStringLiteral("pendingSymbols[%1]").arg(i);
            if (!pending[i].isObject())
                return fail(ProjectTr::tr("%1: an object with \"device\" and \"name\" is expected")
                                .arg(where));
            const QJsonObject s = pending[i].toObject();
            if (!expect(s, "device", QJsonValue::String, where) ||
                !expect(s, "name", QJsonValue::String, where) ||
                !expect(s, "comment", QJsonValue::String, where))
                return std::nullopt;
            // As typed: the device is whatever the user wrote, checked again when shown.
            p.pendingSymbols.push_back({s.value(QStringLiteral("device")).toString(),
                                        s.value(QStringLiteral("name")).toString(),
                                        s.value(QStringLiteral("comment")).toString()});
        }
        return p;
    }

private:
    std::nullopt_t fail(const QString &message) {
        if (m_error)
            m_error->message = message;
        return std::nullopt;
    }

    static QString typeName(QJsonValue::Type type) {
        switch (type) {
        case QJsonValue::String:
            return ProjectTr::tr("a string");
        case QJsonValue::Array:
            return ProjectTr::tr("an array");
        case QJsonValue::Object:
            return ProjectTr::tr("an object");
        case QJsonValue::Double:
            return ProjectTr::tr("a number");
        default:
            return ProjectTr::tr("another value");
        }
    }

    // A key that is absent is allowed (it takes its default); one of the wrong type is an
    // error, so a hand-edited file never loads as silently empty.
    bool expect(const QJsonObject &o, const char *key, QJsonValue::Type type,
                const QString &where) {
        const QJsonValue v = o.value(QLatin1String(key));
        if (v.isUndefined() || v.type() == type)
            return true;
        const QString path = where.isEmpty()
                                 ? QLatin1String(key)
                                 : QStringLiteral("%1.%2").arg(where, QLatin1String(key));
        fail(ProjectTr::tr("%1: %2 is expected").arg(path, typeName(type)));
        return false;
    }

    bool device(const Target &t, const QString &text, const QString &where, Address *out) {
        auto a = parseAddress(t, text);
        if (auto *e = std::get_if<AddressError>(&a)) {
            fail(QStringLiteral("%1: %2").arg(where, e->message));
            return false;
        }
        *out = std::get<Address>(a);
        return true;
    }

    bool readRung(const Target &t, const ModelVariant *model, const QJsonValue &value,
                  const QString &where, Rung *rung) {
        if (!value.isObject()) {
            fail(ProjectTr::tr("%1: a rung object is expected").arg(where));
            return false;
        }
        const QJsonObject o = value.toObject();
        if (!expect(o, "comment", QJsonValue::String, where) ||
            !expect(o, "cells", QJsonValue::Array, where) ||
            !expect(o, "links", QJsonValue::Array, where) ||
            !expect(o, "outputs", QJsonValue::Array, where))
            return false;
        const int rows = o.value(QStringLiteral("rows")).toInt(-1);
        const int columns = o.value(QStringLiteral("columns")).toInt(-1);
        if (rows < 1 || rows > 1000 || columns < 0 || columns > 1000) {
            fail(ProjectTr::tr("%1: \"rows\" must be 1..1000 and \"columns\" 0..1000").arg(where));
            return false;
        }
        *rung = Rung(rows, columns);
        rung->comment = o.value(QStringLiteral("comment")).toString();
        const QJsonArray cells = o.value(QStringLiteral("cells")).toArray();
        if (cells.size() != rows) {
            fail(ProjectTr::tr("%1.cells: %2 rows are expected, the file has %3")
                     .arg(where)
                     .arg(rows)
                     .arg(cells.size()));
            return false;
        }
        for (int r = 0; r < rows; ++r) {
            if (!cells[r].isArray()) {
                fail(
                    ProjectTr::tr("%1.cells[%2]: an array of cells is expected").arg(where).arg(r));
                return false;
            }
            const QJsonArray row = cells[r].toArray();
            if (row.size() != columns) {
                fail(ProjectTr::tr("%1.cells[%2]: %3 cells are expected, the file has %4")
                         .arg(where)
                         .arg(r)
                         .arg(columns)
                         .arg(row.size()));
                return false;
            }
            for (int c = 0; c < columns; ++c) {
                if (!row[c].isString()) {
                    fail(ProjectTr::tr("%1.cells[%2][%3]: a cell is a string (\"\", \"-\" or a "
                                       "contact)")
                             .arg(where)
                             .arg(r)
                             .arg(c));
                    return false;
                }
                const QString text = row[c].toString();
                if (text.isEmpty())
                    continue;
                if (text == QLatin1String("-")) {
                    rung->cell(r, c).kind = CellKind::Wire;
                    continue;
                }
                QString message;
                const auto contact = contactFromText(t, text, &message, model);
                if (!contact) {
                    fail(QStringLiteral("%1.cells[%2][%3]: %4")
                             .arg(where)
                             .arg(r)
                             .arg(c)
                             .arg(message));
                    return false;
                }
                rung->cell(r, c).kind = CellKind::Contact;
                rung->cell(r, c).contact = *contact;
            }
        }
        for (const QJsonValue &l : o.value(QStringLiteral("links")).toArray()) {
            const QJsonArray pair = l.toArray();
            const int r = pair.size() == 2 ? pair[0].toInt(-1) : -1;
            const int c = pair.size() == 2 ? pair[1].toInt(-1) : -1;
            if (r < 0 || r + 1 >= rows || c < 0 || c > columns) {
                fail(ProjectTr::tr("%1.links: [%2, %3] is outside the rung")
                         .arg(where)
                         .arg(r)
                         .arg(c));
                return false;
            }
            rung->setLink(r, c, true);
        }
        for (const QJsonValue &v : o.value(QStringLiteral("outputs")).toArray()) {
            const QJsonArray entry = v.toArray();
            const int r = entry.size() >= 2 ? entry[0].toInt(-1) : -1;
            if (r < 0 || r >= rows || !entry[1].isString()) {
                fail(ProjectTr::tr(
                         "%1.outputs: [row, \"instruction\"] with a row inside the rung is "
                         "expected")
                         .arg(where));
                return false;
            }
            if (rung->outputs[static_cast<std::size_t>(r)]) {
                fail(ProjectTr::tr("%1.outputs: row %2 has two outputs").arg(where).arg(r));
                return false;
            }
            const QString text = entry[1].toString();
            ParseResult parsed = parseInstructionList(t, text, model);
            if (!parsed.ok() || parsed.list.instructions.size() != 1) {
                fail(QStringLiteral("%1.outputs: \"%2\": %3")
                         .arg(where, text,
                              parsed.errors.empty() ? ProjectTr::tr("one instruction is expected")
                                                    : parsed.errors.front().message));
                return false;
            }
            Instruction ins = parsed.list.instructions.front();
            ins.line = ins.column = ins.step = 0;
            rung->outputs[static_cast<std::size_t>(r)] = ins;
            if (entry.size() >= 3) {
                // The grid keeps one box's input rows per rung (a box with several inputs
                // stands alone in its rung): first = the box's row, rows going down.
                const QJsonArray inputs = entry[2].toArray();
                const int k = std::max(1, ins.spec->inputs);
                if (!rung->inputRows.empty() || k < 2 || inputs.size() < 1 || inputs.size() > k) {
                    fail(ProjectTr::tr(
                             "%1.outputs: \"%2\" takes up to %3 input rows, one box per rung")
                             .arg(where, text)
                             .arg(k));
                    return false;
                }
                for (qsizetype i = 0; i < inputs.size(); ++i) {
                    const int row = inputs[i].toInt(-1);
                    const int previous = i == 0 ? r - 1 : rung->inputRows.back();
                    if (row <= previous || row >= rows || (i == 0 && row != r)) {
                        fail(ProjectTr::tr(
                                 "%1.outputs: the input rows of \"%2\" start at its own row "
                                 "and go down inside the rung")
                                 .arg(where, text));
                        return false;
                    }
                    rung->inputRows.push_back(row);
                }
            }
        }
        return true;
    }

    ProjectError *m_error;
};

} // namespace

const Symbol *Project::symbol(const Address &address) const {
    for (const Symbol &s : symbols)
        if (s.address == address)
            return &s;
    return nullptr;
}

QByteArray projectToJson(const Project &project) {
    const Target &t = *project.target;
    Writer w;
    w.open('{');
    w.key(1, "format");
    w.out += jsonString(QLatin1String(kFormat));
    w.key(1, "schema");
    w.out += number(kProjectSchemaVersion);
    w.key(1, "target");
    w.out += jsonString(t.id);
    w.key(1, "model");
    w.out += jsonString(project.model);
    w.key(1, "rungs");
    w.open('[');
    for (const Rung &r : project.program.rungs) {
        w.element(2);
        writeRung(w, t, r);
    }
    w.close(1, ']');
    w.key(1, "symbols");
    w.open('[');
    for (const Symbol &s : project.symbols) {
        w.element(2);
        w.out += symbolLine(deviceText(t, s.address), s.name, s.comment);
    }
    w.close(1, ']');
    // In the order of the devices (T2 before T10), one a line.
    w.key(1, "setValues");
    w.open('{');
    for (const auto &[a, v] : project.setValues) {
        w.element(2);
        w.out += jsonString(deviceText(t, a)) + ": " + number(v);
    }
    w.close(1, '}');
    w.key(1, "watchLists");
    w.open('[');
    for (const WatchList &list : project.watchLists) {
        w.element(2);
        w.open('{');
        w.key(3, "name");
        w.out += jsonString(list.name);
        QByteArrayList devices;
        for (const QString &d : list.devices)
            devices << jsonString(d);
        w.key(3, "devices");
        w.out += '[' + devices.join(", ") + ']';
        // Only the rows shown otherwise than in decimal, and only rows of the list: a file
        // without the key opens with every row in decimal.
        QByteArrayList formats;
        for (const auto &[device, format] : list.formats)
            if (format != ValueFormat::Decimal && list.devices.contains(device))
                formats << jsonString(device) + ": " + jsonString(valueFormatKey(format));
        if (!formats.isEmpty()) {
            w.key(3, "formats");
            w.out += "{ " + formats.join(", ") + " }";
        }
        w.close(2, '}');
    }
    w.close(1, ']');
    if (!project.pendingListing.isEmpty()) {
        w.key(1, "pendingListing");
        w.out += jsonString(project.pendingListing);
    }
    if (!project.pendingSymbols.empty()) {
        w.key(1, "pendingSymbols");
        w.open('[');
        for (const PendingSymbol &s : project.pendingSymbols) {
            w.element(2);
            w.out += symbolLine(s.device, s.name, s.comment);
        }
        w.close(1, ']');
    }
    if (!project.ports.isEmpty()) {
        // One port a line, its settings as written (docs/network-format.md).
        w.key(1, "ports");
        w.open('{');
        for (auto it = project.ports.begin(); it != project.ports.end(); ++it) {
            w.element(2);
            w.out += jsonString(it.key()) + ": " +
                     (it.value().isObject()
                          ? QJsonDocument(it.value().toObject()).toJson(QJsonDocument::Compact)
                          : QByteArray("null"));
        }
        w.close(1, '}');
    }
    w.close(0, '}');
    w.out += '\n';
    return w.out;
}

std::optional<Project> projectFromJson(const QByteArray &json, ProjectError *error) {
    return Reader(error).read(json);
}

std::optional<Project> loadProject(const QString &path, ProjectError *error) {
    QByteArray data;
    QString ioError;
    if (const ReadStatus status = readAtMost(path, kMaxProjectBytes, &data, &ioError);
        status != ReadStatus::Ok) {
        if (error)
            error->message = readFailure(status, path, kMaxProjectBytes, ioError);
        return std::nullopt;
    }
    ProjectError inner;
    auto project = projectFromJson(data, &inner);
    if (!project && error)
        error->message = QStringLiteral("%1: %2").arg(QFileInfo(path).fileName(), inner.message);
    return project;
}

bool saveProject(const Project &project, const QString &path, ProjectError *error) {
    // QSaveFile writes a temporary file and renames it over the old one only when every
    // byte is written: a failed save leaves the previous file as it was.
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        if (error)
            error->message =
                ProjectTr::tr("%1: cannot write the file (%2)").arg(path, file.errorString());
        return false;
    }
    const QByteArray data = projectToJson(project);
    if (file.write(data) != data.size() || !file.commit()) {
        if (error)
            error->message = ProjectTr::tr("%1: saving failed (%2); the previous file is unchanged")
                                 .arg(path, file.errorString());
        file.cancelWriting();
        return false;
    }
    return true;
}

} // namespace rung::model
