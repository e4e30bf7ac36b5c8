// A family is a table (docs/targets.md): the rooms above the target tables read its fields and
// never ask which family they run on, nor name a device. These tests read the source tree and
// name the file and line that breaks the rule.

#include "model/target/address.h"
#include "model/target/target.h"
#include "model/target/target_lists.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>

#include <gtest/gtest.h>

using namespace rung::model;

namespace {

const QString kRoot = QStringLiteral(RUNG_SOURCE_DIR);

// The product's sources outside the target tables (model/target/) and the tests.
QStringList productSources() {
    QStringList files;
    for (const char *room : {"model", "simulator", "comms", "editor", "app"}) {
        const QString dir = kRoot + QLatin1Char('/') + QLatin1String(room);
        if (!QFileInfo::exists(dir))
            continue;
        QDirIterator it(dir, {QStringLiteral("*.cpp"), QStringLiteral("*.h")}, QDir::Files,
                        QDirIterator::Subdirectories);
        while (it.hasNext()) {
            const QString path = it.next();
            if (!path.contains(QLatin1String("/model/target/")))
                files << path;
        }
    }
    files.sort();
    return files;
}

QStringList linesOf(const QString &path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        ADD_FAILURE() << "cannot read " << path.toStdString();
        return {};
    }
    return QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'));
}

QString where(const QString &path, int line) {
    return QDir(kRoot).relativeFilePath(path) + QLatin1Char(':') + QString::number(line + 1);
}

// The string literals of a line of code, comments left out ("//" outside a literal).
QStringList literalsOf(const QString &line) {
    QStringList out;
    QString current;
    bool inString = false;
    for (qsizetype i = 0; i < line.size(); ++i) {
        const QChar c = line[i];
        if (!inString) {
            if (c == QLatin1Char('/') && i + 1 < line.size() && line[i + 1] == QLatin1Char('/'))
                break;
            if (c == QLatin1Char('\'') && i + 2 < line.size()) { // '"' is no literal
                i += line[i + 1] == QLatin1Char('\\') ? 3 : 2;
                continue;
            }
            if (c == QLatin1Char('"')) {
                inString = true;
                current.clear();
            }
        } else if (c == QLatin1Char('\\') && i + 1 < line.size()) {
            current += line[++i];
        } else if (c == QLatin1Char('"')) {
            inString = false;
            out << current;
        } else {
            current += c;
        }
    }
    return out;
}

// Texts of digits only are sizes and formats ("00000" is a margin width, not CPM1 channel 000)
// and are left alone; a CPM1 bit has its dot ("253.13"), every other device a letter.
bool mayBeDevice(const QString &literal) {
    static const QRegularExpression re(QStringLiteral("^(?=.*[A-Za-z.])(?=.*[0-9])\\S+$"));
    return re.match(literal).hasMatch();
}

} // namespace

TEST(SourceGuard, SourcesAreFound) {
    // The guards below would pass on an empty list; make sure they read the real tree.
    const QStringList files = productSources();
    EXPECT_GT(files.size(), 50);
    EXPECT_TRUE(files.contains(kRoot + QStringLiteral("/simulator/compiler.cpp")));
    EXPECT_TRUE(files.contains(kRoot + QStringLiteral("/model/listing/il_parse.cpp")));
}

TEST(SourceGuard, NoFamilyTestOutsideTheTargetTables) {
    for (const QString &path : productSources()) {
        const QStringList lines = linesOf(path);
        for (int k = 0; k < lines.size(); ++k)
            EXPECT_FALSE(lines[k].contains(QLatin1String("Family::")))
                << where(path, k).toStdString()
                << ": a Family:: test outside model/target/; make it a field of the target "
                   "tables (docs/targets.md)";
    }
}

TEST(SourceGuard, FamilyHeaderIsGone) {
    EXPECT_FALSE(QFileInfo::exists(kRoot + QStringLiteral("/simulator/family.h")))
        << "simulator/family.h is back: its facts live in Target::semantics";
}

TEST(SourceGuard, NoDeviceNameLiteralOutsideTheTargetTables) {
    // A literal that is a device of some target ("M9000", "p76", "SM0.0", "253.13") belongs
    // in that target's table.
    for (const QString &path : productSources()) {
        const QStringList lines = linesOf(path);
        for (int k = 0; k < lines.size(); ++k) {
            for (const QString &literal : literalsOf(lines[k])) {
                if (!mayBeDevice(literal))
                    continue;
                for (Family f : Target::families()) {
                    const Target &t = Target::get(f);
                    const auto parsed = parseAddress(t, literal);
                    EXPECT_FALSE(std::holds_alternative<Address>(parsed))
                        << where(path, k).toStdString() << ": \"" << literal.toStdString()
                        << "\" is a " << t.displayName.toStdString()
                        << " device; name it in the target table";
                }
            }
        }
    }
}

TEST(SourceGuard, DeviceNamesOfEveryFamilyAreRecognised) {
    // The guard above asks the tables; these are the names it must catch.
    for (const auto &[family, device] :
         {std::pair{Family::Vpc, "p76"}, std::pair{Family::Vigor, "M9000"},
          std::pair{Family::Cpm1, "253.13"}, std::pair{Family::Pl110, "SM0.0"}}) {
        EXPECT_TRUE(mayBeDevice(QString::fromLatin1(device))) << device;
        EXPECT_TRUE(std::holds_alternative<Address>(
            parseAddress(Target::get(family), QString::fromLatin1(device))))
            << device;
    }
    EXPECT_FALSE(mayBeDevice(QStringLiteral("00000")));
    EXPECT_FALSE(mayBeDevice(QStringLiteral("%1 is out of range")));
}

TEST(SourceGuard, LiteralScannerSeesCodeNotComments) {
    EXPECT_EQ(literalsOf(QStringLiteral(R"(f("M9000"); // "X0")")), QStringList{"M9000"});
    EXPECT_EQ(literalsOf(QStringLiteral(R"(g('"', "a\"b"))")), QStringList{"a\"b"});
    EXPECT_TRUE(literalsOf(QStringLiteral(R"(// "p76")")).isEmpty());
}

// A device written inside a message ("for example \"LD X0\"") is a fact of one family too: a
// CPM1 user reads of a device their PLC does not have. Messages take their examples from the
// target (exampleDevice); this reads every word of every literal.
// Words of texts that read as a device of some family but are none: keys (F2..F8; Vigor has
// F index registers), a colour, a time format.
bool isNoDevice(const QString &word, const QString &literal) {
    static const QRegularExpression key(QStringLiteral("^F([1-9]|1[0-2])$"));
    // The PLCopen standard's name and namespace ("TC6 XML 2.01", ".../xml/tc6_0201") are no
    // CPM1 TC and channel 2.
    if (literal.contains(QLatin1String("plcopen"), Qt::CaseInsensitive) &&
        (word.compare(QLatin1String("TC6"), Qt::CaseInsensitive) == 0 ||
         word == QLatin1String("2.01")))
        return true;
    // A colour (#b00020) is no PL110 B device.
    return key.match(word).hasMatch() || literal.contains(QLatin1Char('#') + word) ||
           word == QLatin1String("0000.00");
}

TEST(SourceGuard, NoDeviceNameInsideATextOutsideTheTargetTables) {
    static const QRegularExpression separators(QStringLiteral("[^A-Za-z0-9.]+"));
    for (const QString &path : productSources()) {
        const QStringList lines = linesOf(path);
        for (int k = 0; k < lines.size(); ++k) {
            for (const QString &literal : literalsOf(lines[k])) {
                for (QString word : literal.split(separators, Qt::SkipEmptyParts)) {
                    while (word.endsWith(QLatin1Char('.')))
                        word.chop(1); // the end of a sentence
                    if (word == literal || !mayBeDevice(word))
                        continue; // a whole literal is the guard above's
                    if (isNoDevice(word, literal))
                        continue;
                    for (Family f : Target::families()) {
                        const Target &t = Target::get(f);
                        EXPECT_FALSE(std::holds_alternative<Address>(parseAddress(t, word)))
                            << where(path, k).toStdString() << ": \"" << word.toStdString()
                            << "\" in \"" << literal.toStdString() << "\" is a "
                            << t.displayName.toStdString()
                            << " device; take the example from the target (exampleDevice)";
                    }
                }
            }
        }
    }
}

// Texts that list the PLCs read the tables: a fifth family needs no new text.
TEST(SourceGuard, NoTextListsTheFamilies) {
    for (const QString &path : productSources()) {
        const QStringList lines = linesOf(path);
        for (int k = 0; k < lines.size(); ++k)
            for (const QString &literal : literalsOf(lines[k])) {
                int named = 0;
                for (const QString &id : targetIds())
                    named += literal.contains(id, Qt::CaseInsensitive) ? 1 : 0;
                EXPECT_LT(named, 2)
                    << where(path, k).toStdString() << ": \"" << literal.toStdString()
                    << "\" names the families; use targetIds() / displayNames()";
            }
    }
}
