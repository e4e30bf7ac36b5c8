#include "model/exchange/plcopen_xml.h"
#include "model/tr.h"

#include <QCoreApplication>
#include <QXmlStreamReader>

namespace rung::model {

namespace {

// A PLCopen file nests a few levels deep; a file that nests deeper than this is no PLCopen
// file, and the limit keeps a hostile one from exhausting the stack.
constexpr int kMaxDepth = 64;

} // namespace

std::unique_ptr<XmlNode> readXmlTree(const QByteArray &bytes, QString *error) {
    QXmlStreamReader xml(bytes);
    auto root = std::make_unique<XmlNode>();
    std::vector<XmlNode *> stack{root.get()};
    while (!xml.atEnd()) {
        switch (xml.readNext()) {
        case QXmlStreamReader::StartElement: {
            if (stack.size() > kMaxDepth) {
                *error = PlcopenTr::tr("line %1: the XML nests deeper than %2 levels")
                             .arg(xml.lineNumber())
                             .arg(kMaxDepth);
                return nullptr;
            }
            XmlNode node;
            node.name = xml.name().toString();
            node.namespaceUri = xml.namespaceUri().toString();
            node.attributes = xml.attributes();
            node.line = static_cast<int>(xml.lineNumber());
            stack.back()->children.push_back(std::move(node));
            stack.push_back(&stack.back()->children.back());
            break;
        }
        case QXmlStreamReader::EndElement:
            if (stack.size() > 1)
                stack.pop_back();
            break;
        case QXmlStreamReader::Characters:
            stack.back()->text += xml.text();
            break;
        default:
            break;
        }
    }
    if (xml.hasError()) {
        *error = PlcopenTr::tr("line %1, column %2: the file is not well-formed XML (%3)")
                     .arg(xml.lineNumber())
                     .arg(xml.columnNumber())
                     .arg(xml.errorString());
        return nullptr;
    }
    if (root->children.size() != 1) {
        *error = PlcopenTr::tr("the file holds no XML element");
        return nullptr;
    }
    auto top = std::make_unique<XmlNode>(std::move(root->children.front()));
    return top;
}

} // namespace rung::model
