#pragma once

// What the PLCopen tests share (docs/plcopen.md): the example projects, the schema, an
// import's issues as text, a program's listing, a device by its text. One definition for
// every test file: the test binaries compile their files in batches (a unity build).

#include "model/convert/convert.h"
#include "model/exchange/plcopen.h"
#include "model/target/address.h"

#include <QDirIterator>
#include <QFile>
#include <QProcess>
#include <QStandardPaths>

#include <algorithm>
#include <string>
#include <vector>

namespace rung::testing {

inline std::vector<QString> exampleProjects() {
    std::vector<QString> out;
    QDirIterator it(QStringLiteral(RUNG_SOURCE_DIR "/resources/examples"),
                    {QStringLiteral("*.rung")}, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext())
        out.push_back(it.next());
    std::sort(out.begin(), out.end());
    return out;
}

// PLCopen's TC6 XML 2.01 schema, kept with the test data so that every clone validates
// against it (a copy beside the repository was missing in CI's clone, and the test skipped).
inline QString schemaPath() {
    return QStringLiteral(RUNG_TEST_DATA_DIR "/plcopen/tc6_xml_v201.xsd");
}

// xmllint's complaints about the files, empty when they all validate against the schema.
inline std::string schemaErrors(const QStringList &files) {
    if (QStandardPaths::findExecutable(QStringLiteral("xmllint")).isEmpty())
        return "xmllint is missing: scripts/install-deps.sh installs libxml2-utils";
    QProcess xmllint;
    xmllint.start(QStringLiteral("xmllint"),
                  QStringList{QStringLiteral("--noout"), QStringLiteral("--schema"), schemaPath()} +
                      files);
    if (!xmllint.waitForFinished(120000))
        return "xmllint did not finish";
    return xmllint.exitCode() == 0 ? std::string() : xmllint.readAllStandardError().toStdString();
}

inline std::string issues(const model::PlcopenImport &r) {
    std::string s;
    for (const model::ImportIssue &i : r.issues)
        s += std::to_string(i.line) + ": " + i.element.toStdString() + ": " +
             i.message.toStdString() + "\n";
    for (const model::UnmappedVariable &u : r.unmapped)
        s += std::to_string(u.line) + ": unmapped " + u.name.toStdString() + " -> " +
             u.proposed.toStdString() + "\n";
    return s;
}

inline QString listing(const model::Project &p) {
    return model::printInstructionList(model::ladderToList(p.program).list, {false, false});
}

inline model::Address deviceAt(const model::Target &t, const char *device) {
    return std::get<model::Address>(model::parseAddress(t, QString::fromLatin1(device)));
}

inline QByteArray readTestFile(const QString &path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace rung::testing
