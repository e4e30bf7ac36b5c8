// The words a scan can write (simulator/scan_writes.h), which the network's history compares
// in place of the whole image: every word a scan changed is among them, scan after scan, for
// random programs of every family, every golden trace's program and every example project,
// with random inputs; and the benchmark network's program is a few ranges, not the image.

#include "simulator/compiler.h"
#include "simulator/engine.h"
#include "simulator/scan_writes.h"

#include "tests/benchmarks/network_program.h"
#include "tests/simulator/random_programs.h"

#include "model/convert/convert.h"
#include "model/listing/il.h"
#include "model/project/project.h"
#include "model/target/address.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QRegularExpression>

#include <gtest/gtest.h>

#include <random>

namespace rung::simulator {

namespace {

bool inRanges(const WordRanges &ranges, std::size_t word) {
    for (const auto &[b, e] : ranges)
        if (b <= word && word < e)
            return true;
    return false;
}

// Scans with random inputs; every word a scan changed (the inputs set before it are the
// scan's to read: it copies them from the stimulus) is among scanWrites. Returns how many
// words changed in all, so that a test can tell it saw something happen.
std::size_t expectScansWriteOnlyTheirWords(const std::shared_ptr<const Program> &program,
                                           const std::vector<model::Address> &inputs, int scans,
                                           unsigned seed) {
    const std::optional<WordRanges> writes = scanWrites(*program);
    if (!writes)
        return 0; // any word: nothing to check
    Engine engine(program);
    engine.setPeriodMs(10);
    std::mt19937 rng(seed);
    std::size_t changed = 0;
    for (int scan = 0; scan < scans; ++scan) {
        for (const model::Address &in : inputs)
            engine.setBit(in, (rng() % 4u) < 2);
        const std::vector<std::int32_t> before(engine.words().begin(), engine.words().end());
        engine.scan();
        const std::span<const std::int32_t> after = engine.words();
        for (std::size_t w = 0; w < before.size(); ++w)
            if (before[w] != after[w]) {
                ++changed;
                EXPECT_TRUE(inRanges(*writes, w))
                    << "word " << w << " changed in scan " << scan << " and is not among "
                    << writes->size() << " ranges";
                if (!inRanges(*writes, w))
                    return changed;
            }
    }
    return changed;
}

QString readText(const QString &path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly | QIODevice::Text) ? QString::fromUtf8(f.readAll())
                                                         : QString();
}

} // namespace

TEST(ScanWrites, EveryWordARandomProgramOfEveryFamilyChangesIsAmongThem) {
    std::size_t changed = 0;
    test::forEachRandomProgram(30, 10,
                               [&](const model::Target &t, const model::InstructionList &list,
                                   const CompileResult &compiled, unsigned seed) {
                                   changed += expectScansWriteOnlyTheirWords(
                                       compiled.program, test::inputsOf(t, list), 60, seed);
                               });
    EXPECT_GT(changed, 1000u);
}

// The golden traces' programs (tests/data/sim, tests/data/il): the manuals' examples, among them
// BMOV, MOVIND, CCD, RS, SFT, STEP / SNXT, the CPM1's arithmetic, the PL110's presets.
TEST(ScanWrites, EveryWordAManualsExampleChangesIsAmongThem) {
    static const QRegularExpression targetRe(QStringLiteral("^; target: (\\w+)"));
    int programs = 0;
    int checked = 0;
    for (const char *dir : {"/sim", "/il"}) {
        const QDir d(QStringLiteral(RUNG_TEST_DATA_DIR) + QLatin1String(dir));
        for (const QString &name : d.entryList({QStringLiteral("*.il")}, QDir::Files)) {
            SCOPED_TRACE(name.toStdString());
            const QString text = readText(d.filePath(name));
            const auto m = targetRe.match(text);
            const model::Target *t = m.hasMatch() ? model::Target::byId(m.captured(1)) : nullptr;
            if (!t)
                continue; // a parser's seed without its target line
            const model::ParseResult parsed = model::parseInstructionList(*t, text);
            ASSERT_TRUE(parsed.ok());
            const CompileResult compiled = compileProgram(parsed.list);
            ASSERT_TRUE(compiled.ok());
            ++programs;
            if (scanWrites(*compiled.program))
                ++checked;
            expectScansWriteOnlyTheirWords(compiled.program, test::inputsOf(*t, parsed.list), 300,
                                           static_cast<unsigned>(programs));
        }
    }
    EXPECT_GE(programs, 50);
    EXPECT_GE(checked, 40); // most are not "any word"
}

TEST(ScanWrites, EveryWordAnExampleProjectChangesIsAmongThem) {
    std::size_t changed = 0;
    const int examples = test::forEachExampleProgram(
        [&](const model::Target &t, const model::InstructionList &list, const CompileResult &c) {
            changed += expectScansWriteOnlyTheirWords(c.program, test::inputsOf(t, list), 400, 11);
        });
    EXPECT_GE(examples, 10);
    EXPECT_GT(changed, 100u);
}

// What the history gains: the benchmark network's program (tests/benchmarks/network_program.h,
// 59 rungs of contacts, a coil, a move and an addition) writes its coils, 59 registers and the
// system devices, a few hundred words of a Vigor VB's ten thousand.
TEST(ScanWrites, AProgramOfCoilsMovesAndAdditionsWritesAFewRangesNotTheImage) {
    const model::Target &t = *model::Target::byId(QStringLiteral("vigor"));
    const QString text = bench::thousandSteps(0);
    const model::ParseResult parsed =
        model::parseInstructionList(t, text, t.model(QStringLiteral("VB")));
    ASSERT_TRUE(parsed.ok());
    const CompileResult compiled = compileProgram(parsed.list);
    ASSERT_TRUE(compiled.ok());
    const std::optional<WordRanges> writes = scanWrites(*compiled.program);
    ASSERT_TRUE(writes);
    std::size_t words = 0;
    for (const auto &[b, e] : *writes)
        words += e - b;
    EXPECT_LT(words, 400u);
    EXPECT_GT(compiled.program->layout->wordCount(), 5000);
    const auto word = [&](const char *device) {
        return static_cast<std::size_t>(compiled.program->layout->word(
            std::get<model::Address>(model::parseAddress(t, QString::fromLatin1(device)))));
    };
    for (const char *written : {"D100", "D158", "D300", "D358"})
        EXPECT_TRUE(inRanges(*writes, word(written))) << written;
    EXPECT_FALSE(inRanges(*writes, word("D0"))); // only read
    EXPECT_FALSE(inRanges(*writes, word("D7000")));
    expectScansWriteOnlyTheirWords(compiled.program, test::inputsOf(t, parsed.list), 50, 3);
}

// Where the program says at run time what it writes, any word.
TEST(ScanWrites, AnIndexedOperandOrACommunicationInstructionMeansAnyWord) {
    const model::Target &t = *model::Target::byId(QStringLiteral("vigor"));
    for (const char *text : {"; target: vigor\nLD M0\nMOV K5 D0E0\nEND\n",
                             "; target: vigor\nLD M0\nMOV K5 K4Y0\nEND\n",
                             "; target: vigor\nLD M0\nRS D0 K2 D10 K2\nEND\n"}) {
        SCOPED_TRACE(text);
        const model::ParseResult parsed = model::parseInstructionList(
            t, QString::fromLatin1(text), t.model(QStringLiteral("VB")));
        ASSERT_TRUE(parsed.ok()) << parsed.errors.front().message.toStdString();
        const CompileResult compiled = compileProgram(parsed.list);
        ASSERT_TRUE(compiled.ok());
        EXPECT_FALSE(scanWrites(*compiled.program));
    }
}

} // namespace rung::simulator
