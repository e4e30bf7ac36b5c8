#include "model/exchange/plcopen_export.h"
#include "model/tr.h"

#include "model/convert/convert.h"
#include "model/exchange/plcopen_xml.h"
#include "model/ladder/ladder_text.h"
#include "model/target/address.h"

#include <QCoreApplication>
#include <QDateTime>

#include <cmath>

// The graph of elements written as PLCopen TC6 XML 2.01, in the schema's order of elements;
// each variable, block and coil with Rung Studio's addData (docs/plcopen.md).

namespace rung::model::plcopen {

PlcopenExport Exporter::write(const QString &name, const QDateTime &created) {
    PlcopenExport result;
    QXmlStreamWriter xml(&result.xml);
    xml.setAutoFormatting(true);
    xml.setAutoFormattingIndent(2);
    xml.writeStartDocument();
    xml.writeNamespace(QLatin1String(kXhtmlNs), QStringLiteral("xhtml"));
    xml.writeNamespace(QLatin1String(kRungNs), QStringLiteral("rs"));
    xml.writeDefaultNamespace(QLatin1String(kPlcopenNs));
    xml.writeStartElement(QLatin1String(kPlcopenNs), QStringLiteral("project"));
    xml.writeEmptyElement(QStringLiteral("fileHeader"));
    xml.writeAttribute(QStringLiteral("companyName"), QStringLiteral("Rung Studio"));
    xml.writeAttribute(QStringLiteral("productName"), QStringLiteral("Rung Studio"));
    xml.writeAttribute(QStringLiteral("productVersion"), QStringLiteral("1"));
    const QDateTime when = created.isValid() ? created : QDateTime::currentDateTimeUtc();
    xml.writeAttribute(QStringLiteral("creationDateTime"),
                       when.toUTC().toString(QStringLiteral("yyyy-MM-ddTHH:mm:ss")));
    xml.writeStartElement(QStringLiteral("contentHeader"));
    xml.writeAttribute(QStringLiteral("name"), name);
    xml.writeStartElement(QStringLiteral("coordinateInfo"));
    for (const char *language : {"fbd", "ld", "sfc"}) {
        xml.writeStartElement(QLatin1String(language));
        xml.writeEmptyElement(QStringLiteral("scaling"));
        xml.writeAttribute(QStringLiteral("x"), QStringLiteral("1"));
        xml.writeAttribute(QStringLiteral("y"), QStringLiteral("1"));
        xml.writeEndElement();
    }
    xml.writeEndElement();
    beginData(xml, "target");
    xml.writeEmptyElement(QLatin1String(kRungNs), QStringLiteral("target"));
    xml.writeAttribute(QStringLiteral("id"), m_t.id);
    xml.writeAttribute(QStringLiteral("model"), m_p.model);
    endData(xml);
    xml.writeEndElement(); // contentHeader

    xml.writeStartElement(QStringLiteral("types"));
    xml.writeEmptyElement(QStringLiteral("dataTypes"));
    xml.writeStartElement(QStringLiteral("pous"));
    xml.writeStartElement(QStringLiteral("pou"));
    xml.writeAttribute(QStringLiteral("name"), QStringLiteral("main"));
    xml.writeAttribute(QStringLiteral("pouType"), QStringLiteral("program"));
    writeInterface(xml);
    xml.writeStartElement(QStringLiteral("body"));
    xml.writeStartElement(QStringLiteral("LD"));
    for (const Elem &e : m_elems)
        writeElem(xml, e);
    xml.writeEndElement(); // LD
    xml.writeEndElement(); // body
    writeListing(xml, &result.notes);
    xml.writeEndElement(); // pou
    xml.writeEndElement(); // pous
    xml.writeEndElement(); // types

    xml.writeStartElement(QStringLiteral("instances"));
    xml.writeStartElement(QStringLiteral("configurations"));
    xml.writeStartElement(QStringLiteral("configuration"));
    xml.writeAttribute(QStringLiteral("name"), QStringLiteral("config"));
    xml.writeStartElement(QStringLiteral("resource"));
    xml.writeAttribute(QStringLiteral("name"), QStringLiteral("resource"));
    xml.writeStartElement(QStringLiteral("task"));
    xml.writeAttribute(QStringLiteral("name"), QStringLiteral("scan"));
    xml.writeAttribute(QStringLiteral("priority"), QStringLiteral("0"));
    xml.writeAttribute(QStringLiteral("interval"), QStringLiteral("T#10ms"));
    xml.writeEmptyElement(QStringLiteral("pouInstance"));
    xml.writeAttribute(QStringLiteral("name"), QStringLiteral("main_instance"));
    xml.writeAttribute(QStringLiteral("typeName"), QStringLiteral("main"));
    xml.writeEndElement(); // task
    xml.writeEndElement(); // resource
    xml.writeEndElement(); // configuration
    xml.writeEndElement(); // configurations
    xml.writeEndElement(); // instances
    writeProjectData(xml);
    xml.writeEndElement(); // project
    xml.writeEndDocument();
    for (const QString &block : m_vendor) {
        const auto why = m_vendorWhy.find(block);
        result.notes << (why == m_vendorWhy.end()
                             ? PlcopenTr::tr("%1 is written as a block of %2's own: other tools "
                                             "read the file but do not know this block")
                                   .arg(block, m_t.displayName)
                             : PlcopenTr::tr("%1 is written as a block of %2's own (%3): other "
                                             "tools read the file but do not know this block")
                                   .arg(block, m_t.displayName, why->second));
    }
    for (const QString &note : m_counterNotes)
        result.notes << note;
    return result;
}

void Exporter::writeListing(QXmlStreamWriter &xml, QStringList *notes) {
    // The listing the vendor's tool downloads, as `convert --to il` writes it. Not an IL body:
    // IEC 61131-3 IL is another language (LD X0 / ANDN X1 / ST Y0), and Beremiz and OpenPLC
    // compile every POU's body, so TMR T0 K50 there would stop their build.
    const ToListingResult listed = ladderToList(m_p.program);
    if (!listed.ok()) {
        for (const Diagnostic &d : listed.problems)
            if (d.severity == Severity::Error) {
                *notes << PlcopenTr::tr("the instruction list is not written beside the ladder: "
                                        "rung %1 does not convert (%2)")
                              .arg(d.location.rung + 1)
                              .arg(d.message);
                return;
            }
    }
    beginData(xml, "instructionList");
    xml.writeStartElement(QLatin1String(kRungNs), QStringLiteral("instructionList"));
    xml.writeAttribute(QStringLiteral("target"), m_t.id);
    xml.writeCharacters(printInstructionList(listed.list));
    xml.writeEndElement();
    endData(xml);
}

void Exporter::beginData(QXmlStreamWriter &xml, const char *what) {
    xml.writeStartElement(QStringLiteral("addData"));
    xml.writeStartElement(QStringLiteral("data"));
    xml.writeAttribute(QStringLiteral("name"),
                       QLatin1String(kRungNs) + QLatin1Char(':') + QLatin1String(what));
    xml.writeAttribute(QStringLiteral("handleUnknown"), QStringLiteral("preserve"));
}

void Exporter::endData(QXmlStreamWriter &xml) {
    xml.writeEndElement(); // data
    xml.writeEndElement(); // addData
}

void Exporter::writeText(QXmlStreamWriter &xml, const char *element, const QString &text) {
    xml.writeStartElement(QLatin1String(element));
    xml.writeTextElement(QLatin1String(kXhtmlNs), QStringLiteral("p"), text);
    xml.writeEndElement();
}

void Exporter::writeInterface(QXmlStreamWriter &xml) {
    xml.writeStartElement(QStringLiteral("interface"));
    xml.writeStartElement(QStringLiteral("localVars"));
    // The symbols' devices in the symbol table's order, then the others in device order.
    std::vector<const Variable *> order;
    std::set<Address> listed;
    for (const Symbol &s : m_p.symbols)
        if (const auto it = m_vars.find(s.address);
            it != m_vars.end() && listed.insert(s.address).second)
            order.push_back(&it->second);
    for (const auto &[address, v] : m_vars)
        if (listed.insert(address).second)
            order.push_back(&v);
    for (const Variable *var : order) {
        const Variable &v = *var;
        const Address &address = v.address;
        xml.writeStartElement(QStringLiteral("variable"));
        xml.writeAttribute(QStringLiteral("name"), iecName(m_t, address));
        if (const QString location = locationOfDevice(m_t, address); !location.isEmpty())
            xml.writeAttribute(QStringLiteral("address"), location);
        xml.writeStartElement(QStringLiteral("type"));
        if (v.instance) {
            xml.writeEmptyElement(QStringLiteral("derived"));
            xml.writeAttribute(QStringLiteral("name"), v.type);
        } else {
            xml.writeEmptyElement(v.type);
        }
        xml.writeEndElement(); // type
        const Symbol *symbol = m_p.symbol(address);
        const auto setValue = m_p.setValues.find(address);
        beginData(xml, "device");
        xml.writeEmptyElement(QLatin1String(kRungNs), QStringLiteral("device"));
        xml.writeAttribute(QStringLiteral("name"), formatAddress(m_t, address));
        if (symbol) {
            xml.writeAttribute(QStringLiteral("symbol"), symbol->name);
            if (!symbol->comment.isEmpty())
                xml.writeAttribute(QStringLiteral("comment"), symbol->comment);
        }
        if (setValue != m_p.setValues.end())
            xml.writeAttribute(QStringLiteral("setValue"), QString::number(setValue->second));
        endData(xml);
        if (symbol)
            writeText(xml, "documentation",
                      symbol->comment.isEmpty()
                          ? symbol->name
                          : QStringLiteral("%1: %2").arg(symbol->name, symbol->comment));
        xml.writeEndElement(); // variable
    }
    for (const auto &[instance, type] : m_edgeInstances) {
        xml.writeStartElement(QStringLiteral("variable"));
        xml.writeAttribute(QStringLiteral("name"), instance);
        xml.writeStartElement(QStringLiteral("type"));
        xml.writeEmptyElement(QStringLiteral("derived"));
        xml.writeAttribute(QStringLiteral("name"), type);
        xml.writeEndElement();
        xml.writeEndElement();
    }
    xml.writeEndElement(); // localVars
    xml.writeEndElement(); // interface
}

void Exporter::writeProjectData(QXmlStreamWriter &xml) {
    if (m_p.watchLists.empty() && m_p.pendingSymbols.empty())
        return;
    xml.writeStartElement(QStringLiteral("addData"));
    for (const WatchList &w : m_p.watchLists) {
        xml.writeStartElement(QStringLiteral("data"));
        xml.writeAttribute(QStringLiteral("name"),
                           QLatin1String(kRungNs) + QStringLiteral(":watchList"));
        xml.writeAttribute(QStringLiteral("handleUnknown"), QStringLiteral("preserve"));
        xml.writeStartElement(QLatin1String(kRungNs), QStringLiteral("watchList"));
        xml.writeAttribute(QStringLiteral("name"), w.name);
        for (const QString &d : w.devices) {
            xml.writeEmptyElement(QLatin1String(kRungNs), QStringLiteral("row"));
            xml.writeAttribute(QStringLiteral("device"), d);
            if (w.format(d) != ValueFormat::Decimal)
                xml.writeAttribute(QStringLiteral("format"), valueFormatKey(w.format(d)));
        }
        xml.writeEndElement();
        xml.writeEndElement();
    }
    if (!m_p.pendingSymbols.empty()) {
        xml.writeStartElement(QStringLiteral("data"));
        xml.writeAttribute(QStringLiteral("name"),
                           QLatin1String(kRungNs) + QStringLiteral(":pendingSymbols"));
        xml.writeAttribute(QStringLiteral("handleUnknown"), QStringLiteral("preserve"));
        xml.writeStartElement(QLatin1String(kRungNs), QStringLiteral("pendingSymbols"));
        for (const PendingSymbol &s : m_p.pendingSymbols) {
            xml.writeEmptyElement(QLatin1String(kRungNs), QStringLiteral("row"));
            xml.writeAttribute(QStringLiteral("device"), s.device);
            xml.writeAttribute(QStringLiteral("name"), s.name);
            xml.writeAttribute(QStringLiteral("comment"), s.comment);
        }
        xml.writeEndElement();
        xml.writeEndElement();
    }
    xml.writeEndElement();
}

void Exporter::writePosition(QXmlStreamWriter &xml, const char *element, int x, int y) {
    xml.writeEmptyElement(QLatin1String(element));
    xml.writeAttribute(QStringLiteral("x"), QString::number(x));
    xml.writeAttribute(QStringLiteral("y"), QString::number(y));
}

void Exporter::writeConnections(QXmlStreamWriter &xml, const std::vector<Conn> &conns, int relY) {
    xml.writeStartElement(QStringLiteral("connectionPointIn"));
    writePosition(xml, "relPosition", 0, relY);
    for (const Conn &c : conns) {
        xml.writeEmptyElement(QStringLiteral("connection"));
        xml.writeAttribute(QStringLiteral("refLocalId"), QString::number(c.ref));
        if (!c.formal.isEmpty())
            xml.writeAttribute(QStringLiteral("formalParameter"), c.formal);
    }
    xml.writeEndElement();
}

void Exporter::writeInstruction(QXmlStreamWriter &xml, const Elem &e) {
    if (e.instruction.isEmpty() && e.contact.isEmpty())
        return;
    beginData(xml, e.instruction.isEmpty() ? "contact" : "instruction");
    xml.writeTextElement(QLatin1String(kRungNs),
                         e.instruction.isEmpty() ? QStringLiteral("contact")
                                                 : QStringLiteral("instruction"),
                         e.instruction.isEmpty() ? e.contact : e.instruction);
    endData(xml);
}

void Exporter::startElement(QXmlStreamWriter &xml, const QString &tag, const Elem &e, bool named) {
    xml.writeStartElement(tag);
    if (named) // a connector's or continuation's name
        xml.writeAttribute(QStringLiteral("name"), e.variable);
    xml.writeAttribute(QStringLiteral("localId"), QString::number(e.id));
    xml.writeAttribute(QStringLiteral("height"), QString::number(e.height));
    xml.writeAttribute(QStringLiteral("width"), QString::number(e.width));
}

void Exporter::writeElem(QXmlStreamWriter &xml, const Elem &e) {
    switch (e.kind) {
    case Elem::Kind::Comment:
        startElement(xml, QStringLiteral("comment"), e);
        writePosition(xml, "position", e.x, e.y);
        writeText(xml, "content", e.variable);
        xml.writeEndElement();
        return;
    case Elem::Kind::LeftRail:
        startElement(xml, QStringLiteral("leftPowerRail"), e);
        writePosition(xml, "position", e.x, e.y);
        xml.writeStartElement(QStringLiteral("connectionPointOut"));
        xml.writeAttribute(QStringLiteral("formalParameter"), QString());
        writePosition(xml, "relPosition", e.width, 20);
        xml.writeEndElement();
        xml.writeEndElement();
        return;
    case Elem::Kind::RightRail:
        startElement(xml, QStringLiteral("rightPowerRail"), e);
        writePosition(xml, "position", e.x, e.y);
        for (const auto &[formal, conns] : e.inputs)
            writeConnections(xml, conns, 20);
        xml.writeEndElement();
        return;
    case Elem::Kind::Contact:
    case Elem::Kind::Coil:
        startElement(
            xml, e.kind == Elem::Kind::Contact ? QStringLiteral("contact") : QStringLiteral("coil"),
            e);
        if (e.negated)
            xml.writeAttribute(QStringLiteral("negated"), QStringLiteral("true"));
        if (!e.edge.isEmpty())
            xml.writeAttribute(QStringLiteral("edge"), e.edge);
        if (!e.storage.isEmpty())
            xml.writeAttribute(QStringLiteral("storage"), e.storage);
        writePosition(xml, "position", e.x, e.y);
        writeConnections(xml, e.inputs.empty() ? std::vector<Conn>{} : e.inputs.front().second, 8);
        xml.writeStartElement(QStringLiteral("connectionPointOut"));
        writePosition(xml, "relPosition", e.width, 8);
        xml.writeEndElement();
        xml.writeTextElement(QStringLiteral("variable"), e.variable);
        writeInstruction(xml, e);
        xml.writeEndElement();
        return;
    case Elem::Kind::InVar:
    case Elem::Kind::OutVar:
        startElement(xml,
                     e.kind == Elem::Kind::InVar ? QStringLiteral("inVariable")
                                                 : QStringLiteral("outVariable"),
                     e);
        writePosition(xml, "position", e.x, e.y);
        if (e.kind == Elem::Kind::InVar) {
            xml.writeStartElement(QStringLiteral("connectionPointOut"));
            writePosition(xml, "relPosition", e.width, 10);
            xml.writeEndElement();
        } else {
            writeConnections(xml, e.inputs.front().second, 10);
        }
        xml.writeTextElement(QStringLiteral("expression"), e.variable);
        xml.writeEndElement();
        return;
    case Elem::Kind::Connector:
        startElement(xml, QStringLiteral("connector"), e, true);
        writePosition(xml, "position", e.x, e.y);
        writeConnections(xml, e.inputs.empty() ? std::vector<Conn>{} : e.inputs.front().second,
                         e.height / 2);
        writeInstruction(xml, e);
        xml.writeEndElement();
        return;
    case Elem::Kind::Continuation:
        startElement(xml, QStringLiteral("continuation"), e, true);
        writePosition(xml, "position", e.x, e.y);
        xml.writeStartElement(QStringLiteral("connectionPointOut"));
        writePosition(xml, "relPosition", e.width, e.height / 2);
        xml.writeEndElement();
        xml.writeEndElement();
        return;
    case Elem::Kind::Block:
        break;
    }
    startElement(xml, QStringLiteral("block"), e);
    xml.writeAttribute(QStringLiteral("typeName"), e.typeName);
    if (!e.instanceName.isEmpty())
        xml.writeAttribute(QStringLiteral("instanceName"), e.instanceName);
    writePosition(xml, "position", e.x, e.y);
    xml.writeStartElement(QStringLiteral("inputVariables"));
    int relY = 10;
    for (const auto &[formal, conns] : e.inputs) {
        xml.writeStartElement(QStringLiteral("variable"));
        xml.writeAttribute(QStringLiteral("formalParameter"), formal);
        writeConnections(xml, conns, relY);
        relY += 10;
        xml.writeEndElement();
    }
    xml.writeEndElement();
    xml.writeEmptyElement(QStringLiteral("inOutVariables"));
    xml.writeStartElement(QStringLiteral("outputVariables"));
    relY = 10;
    for (const QString &formal : e.outputs) {
        xml.writeStartElement(QStringLiteral("variable"));
        xml.writeAttribute(QStringLiteral("formalParameter"), formal);
        xml.writeStartElement(QStringLiteral("connectionPointOut"));
        writePosition(xml, "relPosition", e.width, relY);
        relY += 10;
        xml.writeEndElement();
        xml.writeEndElement();
    }
    xml.writeEndElement();
    writeInstruction(xml, e);
    xml.writeEndElement();
}

} // namespace rung::model::plcopen
