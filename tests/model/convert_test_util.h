#pragma once

// The conversion tests' helpers: parse, round trip, and the property every program must
// keep (IL -> ladder -> IL is a fixpoint after the first pass; listing, ladder and
// canonical listing compute the same outputs).

#include "logic_oracle.h"
#include "model/convert/convert.h"
#include "model/ladder/ladder_text.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

namespace rung::model::test {

inline InstructionList parse(Family family, const QString &text) {
    ParseResult r = parseInstructionList(Target::get(family), text);
    EXPECT_TRUE(r.ok()) << (r.errors.empty() ? std::string()
                                             : QStringLiteral("%1:%2: %3")
                                                   .arg(r.errors[0].line)
                                                   .arg(r.errors[0].column)
                                                   .arg(r.errors[0].message)
                                                   .toStdString())
                        << "\n"
                        << text.toStdString();
    return r.list;
}

inline QString problemsOf(const std::vector<Diagnostic> &ds) {
    QString s;
    for (const Diagnostic &d : ds)
        s += QStringLiteral("%1 line %2 rung %3: %4\n")
                 .arg(d.code)
                 .arg(d.location.line)
                 .arg(d.location.rung)
                 .arg(d.message);
    return s;
}

// IL -> ladder -> IL, printed.
inline QString roundTrip(const InstructionList &list, LadderProgram *ladder = nullptr) {
    ToLadderResult lad = listToLadder(list);
    EXPECT_TRUE(lad.ok()) << problemsOf(lad.problems).toStdString();
    ToListingResult back = ladderToList(lad.ladder);
    EXPECT_TRUE(back.ok()) << problemsOf(back.problems).toStdString();
    if (ladder)
        *ladder = lad.ladder;
    return printInstructionList(back.list);
}

inline QString canonical(Family family, const QString &text) {
    return roundTrip(parse(family, text));
}

inline QString lines(std::initializer_list<const char *> ls) {
    QString s;
    for (const char *l : ls)
        s += QString::fromLatin1(l) + QLatin1Char('\n');
    return s;
}

inline std::set<Address> devicesRead(const InstructionList &list) {
    std::set<Address> out;
    for (const Instruction &i : list.instructions)
        for (const Operand &o : i.operands)
            if (o.kind == Operand::Kind::Device)
                out.insert(o.address);
    return out;
}

inline void checkProgram(const Target &target, const QString &text, std::uint64_t seed) {
    SCOPED_TRACE(
        QStringLiteral("target %1 seed %2\n%3").arg(target.id).arg(seed).arg(text).toStdString());
    ParseResult parsed = parseInstructionList(target, text);
    ASSERT_TRUE(parsed.ok()) << parsed.errors[0].line << ": "
                             << parsed.errors[0].message.toStdString();
    ToLadderResult lad1 = listToLadder(parsed.list);
    ASSERT_TRUE(lad1.ok()) << problemsOf(lad1.problems).toStdString();
    ToListingResult il1 = ladderToList(lad1.ladder);
    ASSERT_TRUE(il1.ok()) << problemsOf(il1.problems).toStdString();
    ToLadderResult lad2 = listToLadder(il1.list);
    ASSERT_TRUE(lad2.ok()) << problemsOf(lad2.problems).toStdString();
    ToListingResult il2 = ladderToList(lad2.ladder);
    // Fixpoint after the first pass.
    ASSERT_EQ(printInstructionList(il2.list), printInstructionList(il1.list));
    ASSERT_EQ(lad2.ladder.rungs.size(), lad1.ladder.rungs.size());
    for (std::size_t r = 0; r < lad1.ladder.rungs.size(); ++r)
        ASSERT_TRUE(lad1.ladder.rungs[r] == lad2.ladder.rungs[r])
            << "rung " << r << "\n"
            << printLadderText(lad1.ladder).toStdString()
            << printLadderText(lad2.ladder).toStdString()
            << printInstructionList(il1.list).toStdString();
    // Same meaning: the listing, its ladder and the canonical listing agree on every output.
    const std::set<Address> devices = devicesRead(parsed.list);
    const std::vector<Address> order(devices.begin(), devices.end());
    const int n = static_cast<int>(order.size());
    // Exhaustive for small programs; above that random cases, enough over 2000 programs a
    // target while keeping the Debug run short.
    const bool exhaustive = n <= 5;
    const int cases = exhaustive ? 1 << n : 24;
    std::mt19937_64 rng(seed);
    for (int k = 0; k < cases; ++k) {
        const std::uint64_t bits = exhaustive ? static_cast<std::uint64_t>(k) : rng();
        const BitReader read = [&](const Address &a) {
            const auto it = std::lower_bound(order.begin(), order.end(), a);
            const auto i = static_cast<std::size_t>(it - order.begin());
            return ((bits >> (i % 64)) & 1u) != 0;
        };
        const OutputImage a = evaluateList(parsed.list, read);
        const OutputImage b = evaluateLadder(lad1.ladder, read);
        const OutputImage c = evaluateList(il1.list, read);
        ASSERT_EQ(a, b) << "case " << k << "\n" << printLadderText(lad1.ladder).toStdString();
        ASSERT_EQ(a, c) << "case " << k;
    }
}

} // namespace rung::model::test
