#include "model/exchange/plcopen_import.h"
#include "model/tr.h"

#include "model/convert/convert.h"
#include "model/target/address.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <cmath>

// Reading a PLCopen TC6 XML 2.01 LD body into a target's ladder (docs/plcopen.md "Import").
// The graph is read from the outputs back to the left rail: the power at an element's input is
// a chain of factors, a contact or the OR of the chains that meet at the input (with their
// common start taken out first), so two coils fed from one branch point share the chain up to
// it. Outputs in the file's order whose chains start alike form one rung, drawn by the
// converter's own layout; its branch points are where their chains part. Every element that
// no output reaches, every block, variable and body the target cannot take is an issue with
// its line.

namespace rung::model::plcopen {

QString describe(const Element &e) {
    if (!e.typeName.isEmpty())
        return QStringLiteral("block %1").arg(e.typeName);
    if (!e.variable.isEmpty() &&
        (e.kind == QLatin1String("contact") || e.kind == QLatin1String("coil") ||
         e.kind == QLatin1String("inVariable") || e.kind == QLatin1String("outVariable")))
        return QStringLiteral("%1 %2").arg(e.kind, e.variable);
    if (!e.name.isEmpty() &&
        (e.kind == QLatin1String("connector") || e.kind == QLatin1String("continuation")))
        return QStringLiteral("%1 %2").arg(e.kind, e.name);
    return e.kind;
}

bool isTimerType(const QString &t) {
    return t == QLatin1String("TON") || t == QLatin1String("TOF") || t == QLatin1String("TP");
}
bool isCounterType(const QString &t) {
    return !counterKind(t).isEmpty();
}

std::optional<bool> boolLiteral(const QString &text) {
    const QString t = text.trimmed();
    if (t.compare(QLatin1String("TRUE"), Qt::CaseInsensitive) == 0 ||
        t.compare(QLatin1String("BOOL#TRUE"), Qt::CaseInsensitive) == 0 || t == QLatin1String("1"))
        return true;
    if (t.compare(QLatin1String("FALSE"), Qt::CaseInsensitive) == 0 ||
        t.compare(QLatin1String("BOOL#FALSE"), Qt::CaseInsensitive) == 0 || t == QLatin1String("0"))
        return false;
    return std::nullopt;
}

std::optional<CompareOp> compareOf(const QString &t) {
    static const std::pair<const char *, CompareOp> ops[] = {
        {"EQ", CompareOp::Eq}, {"NE", CompareOp::Ne}, {"LT", CompareOp::Lt},
        {"LE", CompareOp::Le}, {"GT", CompareOp::Gt}, {"GE", CompareOp::Ge}};
    for (const auto &[name, op] : ops)
        if (t.compare(QLatin1String(name), Qt::CaseInsensitive) == 0)
            return op;
    return std::nullopt;
}

// An IEC TIME literal in milliseconds: T#1s, TIME#1m30s, t#1.5s, T#250ms.
std::optional<qint64> timeLiteral(const QString &text) {
    static const QRegularExpression prefix(QStringLiteral("^(?:T|TIME)#(.+)$"),
                                           QRegularExpression::CaseInsensitiveOption);
    static const QRegularExpression part(QStringLiteral("(\\d+(?:\\.\\d+)?)(ms|d|h|m|s)"),
                                         QRegularExpression::CaseInsensitiveOption);
    const auto m = prefix.match(text.trimmed());
    if (!m.hasMatch())
        return std::nullopt;
    QString rest = m.captured(1);
    rest.remove(QLatin1Char('_'));
    double ms = 0;
    qsizetype at = 0;
    auto it = part.globalMatch(rest);
    while (it.hasNext()) {
        const auto p = it.next();
        if (p.capturedStart() != at)
            return std::nullopt;
        at = p.capturedEnd();
        const QString unit = p.captured(2).toLower();
        const double factor = unit == QLatin1String("ms")  ? 1
                              : unit == QLatin1String("s") ? 1000
                              : unit == QLatin1String("m") ? 60000
                              : unit == QLatin1String("h") ? 3600000
                                                           : 86400000;
        ms += p.captured(1).toDouble() * factor;
    }
    if (at != rest.size() || at == 0 || ms != std::floor(ms))
        return std::nullopt;
    return static_cast<qint64>(ms);
}

// An IEC integer literal: 10, -5, 16#1F, 2#1010, 8#17, INT#5.
std::optional<qint64> integerLiteral(const QString &text) {
    QString t = text.trimmed();
    if (const qsizetype hash = t.indexOf(QLatin1Char('#')); hash > 0 && !t.at(0).isDigit())
        t = t.mid(hash + 1); // a typed literal: INT#5
    t.remove(QLatin1Char('_'));
    bool ok = false;
    qint64 v = 0;
    if (t.startsWith(QLatin1String("16#")))
        v = t.mid(3).toLongLong(&ok, 16);
    else if (t.startsWith(QLatin1String("8#")))
        v = t.mid(2).toLongLong(&ok, 8);
    else if (t.startsWith(QLatin1String("2#")))
        v = t.mid(2).toLongLong(&ok, 2);
    else if (t.compare(QLatin1String("TRUE"), Qt::CaseInsensitive) == 0)
        return 1;
    else if (t.compare(QLatin1String("FALSE"), Qt::CaseInsensitive) == 0)
        return 0;
    else
        v = t.toLongLong(&ok, 10);
    return ok ? std::optional<qint64>(v) : std::nullopt;
}

PlcopenImport Importer::run(const QByteArray &bytes) {
    QString error;
    const auto root = readXmlTree(bytes, &error);
    if (!root) {
        issue(0, QStringLiteral("XML"), error);
        return finish();
    }
    if (root->name != QLatin1String("project") || root->namespaceUri != QLatin1String(kPlcopenNs)) {
        issue(root->line, root->name,
              PlcopenTr::tr("not a PLCopen TC6 XML 2.01 project (the root is <%1> in \"%2\", "
                            "<project> in \"%3\" is expected)")
                  .arg(root->name, root->namespaceUri, QLatin1String(kPlcopenNs)));
        return finish();
    }
    readHeader(*root);
    // The program: the one the configuration's task runs, else the first.
    std::vector<const XmlNode *> pous;
    if (const XmlNode *types = root->child("types"))
        if (const XmlNode *list = types->child("pous"))
            pous = list->all("pou");
    const QStringList running = runningPous(*root);
    const XmlNode *program = nullptr;
    for (const bool run : {true, false})
        for (const XmlNode *pou : pous)
            if (!program && pou->attribute("pouType") == QLatin1String("program") &&
                (!run || running.contains(pou->attribute("name"))))
                program = pou;
    for (const XmlNode *pou : pous) {
        if (pou == program)
            continue;
        const QString kind = pou->attribute("pouType");
        issue(pou->line, QStringLiteral("pou %1").arg(pou->attribute("name")),
              kind == QLatin1String("program")
                  ? PlcopenTr::tr("a second program is not imported: a project is one ladder "
                                  "(the program %1 is)")
                        .arg(program->attribute("name"))
                  : PlcopenTr::tr("a %1 is not imported: %2 runs one ladder, with no user "
                                  "functions or function blocks")
                        .arg(kind, m_t.displayName));
    }
    if (!program) {
        issue(root->line, QStringLiteral("project"), PlcopenTr::tr("the file has no program"));
        return finish();
    }
    readVariables(*program);
    if (const XmlNode *instances = root->child("instances"))
        readGlobals(*instances);
    const XmlNode *ld = nullptr;
    for (const XmlNode *body : program->all("body")) {
        for (const XmlNode &language : body->children) {
            if (language.name == QLatin1String("LD") && !ld) {
                ld = &language;
            } else if (language.name != QLatin1String("addData") &&
                       language.name != QLatin1String("documentation")) {
                issue(language.line, QStringLiteral("body %1").arg(language.name),
                      PlcopenTr::tr("a body in %1 is not imported: only ladder (LD) is")
                          .arg(language.name));
            }
        }
    }
    if (!ld) {
        issue(program->line, QStringLiteral("pou %1").arg(program->attribute("name")),
              PlcopenTr::tr("the program has no ladder (LD) body"));
        return finish();
    }
    if (const XmlNode *listing = ourData(*program, "instructionList"))
        m_listing = listing->text;
    readElements(*ld);
    buildProgram();
    if (const XmlNode *data = root->child("addData"))
        readProjectData(*data);
    return finish();
}

QStringList Importer::runningPous(const XmlNode &root) {
    QStringList out;
    const XmlNode *instances = root.child("instances");
    const XmlNode *configurations = instances ? instances->child("configurations") : nullptr;
    if (!configurations)
        return out;
    for (const XmlNode *c : configurations->all("configuration"))
        for (const XmlNode *r : c->all("resource")) {
            for (const XmlNode *i : r->all("pouInstance"))
                out << i->attribute("typeName");
            for (const XmlNode *t : r->all("task"))
                for (const XmlNode *i : t->all("pouInstance"))
                    out << i->attribute("typeName");
        }
    return out;
}

void Importer::issue(int line, const QString &element, const QString &message) {
    m_result.issues.push_back({line, element, message});
}

PlcopenImport Importer::finish() {
    std::stable_sort(m_result.issues.begin(), m_result.issues.end(),
                     [](const ImportIssue &a, const ImportIssue &b) { return a.line < b.line; });
    return std::move(m_result);
}

const XmlNode *Importer::ourData(const XmlNode &node, const char *what) {
    const XmlNode *add = node.name == QLatin1String("addData") ? &node : node.child("addData");
    if (!add)
        return nullptr;
    const QString name = QLatin1String(kRungNs) + QLatin1Char(':') + QLatin1String(what);
    for (const XmlNode *d : add->all("data"))
        if (d->attribute("name") == name && !d->children.empty())
            return &d->children.front();
    return nullptr;
}

void Importer::readHeader(const XmlNode &root) {
    const XmlNode *header = root.child("contentHeader");
    if (!header)
        return;
    if (const XmlNode *t = ourData(*header, "target")) {
        m_result.fileTarget = t->attribute("id");
        m_own = true;
        if (m_result.fileTarget == m_t.id)
            m_fileModel = t->attribute("model");
    }
}

void Importer::readVarList(const XmlNode &list) {
    const bool constants = list.attribute("constant") == QLatin1String("true") ||
                           list.attribute("constant") == QLatin1String("1");
    for (const XmlNode *v : list.all("variable")) {
        VariableInfo info;
        if (const XmlNode *initial = v->child("initialValue"); constants && initial)
            if (const XmlNode *simple = initial->child("simpleValue"))
                info.constant = simple->attribute("value").trimmed();
        info.name = v->attribute("name");
        info.line = v->line;
        info.location = v->attribute("address");
        if (const XmlNode *type = v->child("type"); type && !type->children.empty()) {
            const XmlNode &t = type->children.front();
            info.type = t.name == QLatin1String("derived") ? t.attribute("name") : t.name;
        }
        if (const XmlNode *doc = v->child("documentation"))
            info.documentation = doc->allText().trimmed();
        if (const XmlNode *d = ourData(*v, "device")) {
            info.device = d->attribute("name");
            info.symbol = d->attribute("symbol");
            info.symbolComment = d->attribute("comment");
            if (d->has("setValue"))
                info.setValue = d->attribute("setValue").toLongLong();
        }
        if (!m_vars.contains(info.name))
            m_varOrder << info.name;
        // A global the POU declares external: the global's declaration says what it is.
        if (m_vars.contains(info.name) && info.constant.isEmpty() &&
            !m_vars[info.name].constant.isEmpty())
            continue;
        m_vars.insert(info.name, info);
    }
}

void Importer::readVariables(const XmlNode &pou) {
    if (const XmlNode *iface = pou.child("interface"))
        for (const XmlNode &list : iface->children)
            if (list.name.endsWith(QLatin1String("Vars")))
                readVarList(list);
}

void Importer::readGlobals(const XmlNode &instances) {
    const XmlNode *configurations = instances.child("configurations");
    if (!configurations)
        return;
    for (const XmlNode *c : configurations->all("configuration")) {
        for (const XmlNode *g : c->all("globalVars"))
            readVarList(*g);
        for (const XmlNode *r : c->all("resource"))
            for (const XmlNode *g : r->all("globalVars"))
                readVarList(*g);
    }
}

void Importer::readProjectData(const XmlNode &add) {
    if (!m_result.project)
        return;
    Project &p = *m_result.project;
    for (const XmlNode *d : add.all("data")) {
        if (d->children.empty())
            continue;
        const XmlNode &inner = d->children.front();
        if (d->attribute("name") == QLatin1String(kRungNs) + QStringLiteral(":watchList")) {
            WatchList w;
            w.name = inner.attribute("name");
            for (const XmlNode *row : inner.all("row")) {
                const QString device = row->attribute("device");
                w.devices << device;
                if (row->has("format"))
                    if (const auto f = valueFormatFromKey(row->attribute("format")))
                        w.formats[device] = *f;
            }
            p.watchLists.push_back(w);
        } else if (d->attribute("name") ==
                   QLatin1String(kRungNs) + QStringLiteral(":pendingSymbols")) {
            for (const XmlNode *row : inner.all("row"))
                p.pendingSymbols.push_back(
                    {row->attribute("device"), row->attribute("name"), row->attribute("comment")});
        }
    }
}

// The device a variable names: the mapping file, Rung Studio's own note of it, its
// located address, a name that is a device of the target. nullopt: none (it is listed as
// unmapped, with a free device proposed, once).
std::optional<Address> Importer::resolve(const QString &name, int line, const QString &wantedType) {
    const QString trimmed = name.trimmed();
    if (const auto cached = m_resolved.find(trimmed); cached != m_resolved.end())
        return cached->second;
    std::optional<Address> found;
    VariableInfo *info = m_vars.contains(trimmed) ? &m_vars[trimmed] : nullptr;
    if (info)
        info->used = true;
    if (const auto it = m_mapping.devices.find(trimmed); it != m_mapping.devices.end()) {
        const auto parsed = parseAddress(m_t, it->second, m_model);
        if (const auto *e = std::get_if<AddressError>(&parsed))
            issue(info ? info->line : line, QStringLiteral("variable %1").arg(trimmed),
                  PlcopenTr::tr("the mapping file gives %1: %2").arg(it->second, e->message));
        else
            found = std::get<Address>(parsed);
    }
    if (!found && info && !info->device.isEmpty())
        if (const auto parsed = parseAddress(m_t, info->device, m_model);
            std::holds_alternative<Address>(parsed))
            found = std::get<Address>(parsed);
    if (!found && info && !info->location.isEmpty()) {
        found = deviceOfLocation(m_t, info->location, m_model);
        if (!found)
            issue(info->line, QStringLiteral("variable %1").arg(trimmed),
                  PlcopenTr::tr("%1 at %2: %3 has no such device (docs/plcopen.md, located "
                                "variables); give one in a mapping file")
                      .arg(trimmed, info->location, m_t.displayName));
    }
    if (!found)
        found = deviceOfIecName(m_t, trimmed, m_model);
    if (!found) {
        UnmappedVariable u;
        u.name = trimmed;
        u.line = info ? info->line : line;
        u.type = info && !info->type.isEmpty() ? info->type : wantedType;
        m_result.unmapped.push_back(u);
    }
    m_resolved[trimmed] = found;
    if (found)
        m_usedDevices.insert(*found);
    return found;
}

QString Importer::constantValue(const QString &expression) {
    const auto it = m_vars.find(expression.trimmed());
    if (it == m_vars.end() || it->constant.isEmpty())
        return expression;
    it->used = true;
    return it->constant;
}

// An operand written as an expression: a variable (a device) or a literal.
std::optional<Operand> Importer::operandOf(const QString &named, int line, bool timeAllowed) {
    const QString expression = constantValue(named);
    Operand o;
    if (const auto v = integerLiteral(expression)) {
        o.kind = Operand::Kind::Constant;
        QString text;
        if (m_t.constants.prefixed)
            text = QStringLiteral("K%1").arg(*v);
        else if (m_t.constants.bcd)
            text = QStringLiteral("#%1").arg(*v, 4, 16, QLatin1Char('0')).toUpper();
        else
            text = QString::number(*v);
        const auto c = parseConstant(m_t, text);
        if (const auto *e = std::get_if<AddressError>(&c)) {
            issue(line, expression, e->message);
            return std::nullopt;
        }
        o.constant = std::get<Constant>(c);
        return o;
    }
    if (timeAllowed && timeLiteral(expression))
        return std::nullopt;
    // A counter's present value: CTU0.CV.
    if (expression.trimmed().endsWith(QLatin1String(".CV"), Qt::CaseInsensitive)) {
        if (m_t.constants.bcdSetValues) {
            issue(line, expression,
                  PlcopenTr::tr("%1 is not imported: %2 keeps a counter's present value as BCD "
                                "digits")
                      .arg(expression.trimmed(), m_t.displayName));
            return std::nullopt;
        }
        return counterValue(expression.trimmed().chopped(3), line);
    }
    const auto device = resolve(expression, line);
    if (!device)
        return std::nullopt;
    o.kind = Operand::Kind::Device;
    o.address = *device;
    return o;
}

std::vector<Connection> Importer::connectionsOf(const XmlNode &point) {
    std::vector<Connection> out;
    for (const XmlNode *c : point.all("connection"))
        out.push_back({c->attribute("refLocalId").toInt(), c->attribute("formalParameter")});
    return out;
}

void Importer::readElements(const XmlNode &ld) {
    int index = 0;
    for (const XmlNode &node : ld.children) {
        Element e;
        e.kind = node.name;
        e.line = node.line;
        e.index = index++;
        e.id = node.attribute("localId").toInt();
        e.order = node.attribute("executionOrderId").toLong();
        if (const XmlNode *pos = node.child("position")) {
            e.x = pos->attribute("x").toDouble();
            e.y = pos->attribute("y").toDouble();
        }
        e.negated = node.attribute("negated") == QLatin1String("true") ||
                    node.attribute("negated") == QLatin1String("1");
        e.edge = node.attribute("edge");
        e.storage = node.attribute("storage");
        e.typeName = node.attribute("typeName");
        e.instanceName = node.attribute("instanceName");
        e.name = node.attribute("name");
        if (const XmlNode *v = node.child("variable"))
            e.variable = v->text.trimmed();
        if (const XmlNode *v = node.child("expression"))
            e.variable = v->text.trimmed();
        if (const XmlNode *content = node.child("content"))
            e.comment = content->allText().trimmed();
        for (const XmlNode *in : node.all("connectionPointIn")) {
            Pin p;
            p.connections = connectionsOf(*in);
            if (const XmlNode *x = in->child("expression"))
                p.expression = x->text.trimmed();
            e.inputs.push_back(p);
        }
        if (const XmlNode *vars = node.child("inputVariables"))
            for (const XmlNode *v : vars->all("variable")) {
                Pin p;
                p.formal = v->attribute("formalParameter");
                p.negated = v->attribute("negated") == QLatin1String("true") ||
                            v->attribute("negated") == QLatin1String("1");
                p.edge = v->attribute("edge");
                if (p.edge == QLatin1String("none"))
                    p.edge.clear();
                if (const XmlNode *in = v->child("connectionPointIn")) {
                    p.connections = connectionsOf(*in);
                    if (const XmlNode *x = in->child("expression"))
                        p.expression = x->text.trimmed();
                }
                e.inputs.push_back(p);
            }
        if (const XmlNode *d = ourData(node, "instruction"))
            e.instruction = d->text.trimmed();
        if (const XmlNode *d = ourData(node, "contact"))
            e.contact = d->text.trimmed();
        if (e.kind == QLatin1String("comment") && !node.has("localId"))
            e.id = -index;
        m_byId[e.id] = m_elements.size();
        m_elements.push_back(e);
    }
}

const Element *Importer::element(int id) const {
    const auto it = m_byId.find(id);
    return it == m_byId.end() ? nullptr : &m_elements[it->second];
}

const Pin *Importer::pin(const Element &e, const char *formal) const {
    for (const Pin &p : e.inputs)
        if (p.formal.compare(QLatin1String(formal), Qt::CaseInsensitive) == 0)
            return &p;
    return nullptr;
}

// The expression an operand pin carries: an inVariable connected to it, or its own.
std::optional<QString> Importer::pinExpression(const Pin &p, int line) {
    if (!p.expression.isEmpty())
        return constantValue(p.expression);
    if (p.connections.size() == 1)
        if (const Element *src = element(p.connections.front().ref);
            src && (src->kind == QLatin1String("inVariable") ||
                    src->kind == QLatin1String("inOutVariable"))) {
            m_used.insert(src->id);
            return constantValue(src->variable);
        }
    issue(line, p.formal, PlcopenTr::tr("input %1 is not a variable or a literal").arg(p.formal));
    return std::nullopt;
}

} // namespace rung::model::plcopen

namespace rung::model {

std::optional<DeviceMapping> readDeviceMapping(const QString &text, QString *error) {
    DeviceMapping m;
    const QStringList lines = text.split(QLatin1Char('\n'));
    for (qsizetype i = 0; i < lines.size(); ++i) {
        QString line = lines[i];
        if (const qsizetype hash = line.indexOf(QLatin1Char('#')); hash >= 0)
            line.truncate(hash);
        line = line.trimmed();
        if (line.isEmpty())
            continue;
        const qsizetype eq = line.indexOf(QLatin1Char('='));
        if (eq <= 0 || line.mid(eq + 1).trimmed().isEmpty()) {
            *error = PlcopenTr::tr("line %1: \"%2\" is not NAME = DEVICE").arg(i + 1).arg(line);
            return std::nullopt;
        }
        m.devices[line.left(eq).trimmed()] = line.mid(eq + 1).trimmed();
    }
    return m;
}

PlcopenImport importPlcopen(const QByteArray &xml, const Target &target, const ModelVariant *model,
                            const DeviceMapping &mapping) {
    return plcopen::Importer(target, model, mapping).run(xml);
}

} // namespace rung::model
