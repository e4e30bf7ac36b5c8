#pragma once

// The XML of a PLCopen file as a small tree with line numbers (QtCore has a stream reader
// only), and the namespaces. Internal to model/exchange.

#include <QString>
#include <QXmlStreamAttributes>

#include <memory>
#include <vector>

namespace rung::model {

inline constexpr const char *kPlcopenNs = "http://www.plcopen.org/xml/tc6_0201";
inline constexpr const char *kXhtmlNs = "http://www.w3.org/1999/xhtml";
// Rung Studio's own addData (docs/plcopen.md): the instruction as the target writes it, a
// device and its symbol, the target, watch lists.
inline constexpr const char *kRungNs = "urn:rungstudio:plcopen";

struct XmlNode {
    QString name; // local name
    QString namespaceUri;
    QXmlStreamAttributes attributes;
    QString text; // the text directly inside (trimmed)
    int line = 0;
    std::vector<XmlNode> children;

    QString attribute(const char *name) const {
        return attributes.value(QLatin1String(name)).toString();
    }
    bool has(const char *name) const { return attributes.hasAttribute(QLatin1String(name)); }
    const XmlNode *child(const char *name) const {
        for (const XmlNode &c : children)
            if (c.name == QLatin1String(name))
                return &c;
        return nullptr;
    }
    std::vector<const XmlNode *> all(const char *name) const {
        std::vector<const XmlNode *> out;
        for (const XmlNode &c : children)
            if (c.name == QLatin1String(name))
                out.push_back(&c);
        return out;
    }
    // All text below this node, joined (an xhtml paragraph's).
    QString allText() const {
        QString out = text;
        for (const XmlNode &c : children) {
            const QString t = c.allText();
            if (!t.isEmpty())
                out += (out.isEmpty() ? QString() : QStringLiteral("\n")) + t;
        }
        return out;
    }
};

// nullptr with *error (line, column, why) when the bytes are no well-formed XML.
std::unique_ptr<XmlNode> readXmlTree(const QByteArray &bytes, QString *error);

} // namespace rung::model
