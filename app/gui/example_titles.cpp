#include "example_titles.h"

#include "model/target/target.h"

#include <QCoreApplication>
#include <QStringList>

#include <algorithm>

namespace rung::app {

namespace {

struct ExampleTitle {
    const char *baseName;
    const char *title;
};

// One row per example in resources/examples whose name is words, not mnemonics.
constexpr ExampleTitle kTitles[] = {
    {"add-once-a-second", QT_TRANSLATE_NOOP("rung::app::ExampleTitles", "Add once a second")},
    {"timers-down-and-up",
     QT_TRANSLATE_NOOP("rung::app::ExampleTitles", "Timers counting down and up")},
    {"parts-counter",
     QT_TRANSLATE_NOOP("rung::app::ExampleTitles", "Parts counter and reject tracking")},
    {"stairway-light", QT_TRANSLATE_NOOP("rung::app::ExampleTitles", "Stairway light")},
    {"setpoint-page",
     QT_TRANSLATE_NOOP("rung::app::ExampleTitles", "Setpoints on the display, set with the keys")},
    {"counting-range-extension",
     QT_TRANSLATE_NOOP("rung::app::ExampleTitles", "Extending a counter's range")},
    {"delay-off", QT_TRANSLATE_NOOP("rung::app::ExampleTitles", "Off delay")},
    {"flasher", QT_TRANSLATE_NOOP("rung::app::ExampleTitles", "Flasher")},
    {"start-first-latch",
     QT_TRANSLATE_NOOP("rung::app::ExampleTitles", "Latch, START has priority")},
    {"stop-first-latch", QT_TRANSLATE_NOOP("rung::app::ExampleTitles", "Latch, STOP has priority")},
    {"traffic-light", QT_TRANSLATE_NOOP("rung::app::ExampleTitles", "Traffic light")},
    // The networks (File > Examples > Networks).
    {"easy-link",
     QT_TRANSLATE_NOOP("rung::app::ExampleTitles", "Easy Link: a master and two slaves")},
    {"cpu-link", QT_TRANSLATE_NOOP("rung::app::ExampleTitles", "CPU Link")},
    {"parallel-link", QT_TRANSLATE_NOOP("rung::app::ExampleTitles", "Parallel Link")},
    {"modbus", QT_TRANSLATE_NOOP("rung::app::ExampleTitles", "MODBUS master (MBUS) and slaves")},
    {"modbus-table",
     QT_TRANSLATE_NOOP("rung::app::ExampleTitles", "MODBUS master with a table of requests")},
    {"non-protocol",
     QT_TRANSLATE_NOOP("rung::app::ExampleTitles", "Non-protocol communication (RS)")},
    {"vb-1com", QT_TRANSLATE_NOOP("rung::app::ExampleTitles", "VB-1COM module (FROM / TO)")},
    {"pl110-exp", QT_TRANSLATE_NOOP("rung::app::ExampleTitles", "PL110 EXP1 MODBUS master")},
    {"pl110-free-port", QT_TRANSLATE_NOOP("rung::app::ExampleTitles", "PL110 free-port (SEND)")},
    {"cpm1-host-link", QT_TRANSLATE_NOOP("rung::app::ExampleTitles",
                                         "CPM1 peripheral port (Host Link) on a pseudo-terminal")},
};

} // namespace

QString exampleTitle(const model::Target *target, const QString &baseName) {
    for (const ExampleTitle &row : kTitles)
        if (baseName == QLatin1String(row.baseName))
            return QCoreApplication::translate("rung::app::ExampleTitles", row.title);
    QStringList words = baseName.split(QLatin1Char('-'), Qt::SkipEmptyParts);
    if (words.isEmpty())
        return baseName;
    // A network's name of the families it joins ("pl110-vigor"): their names as the tables
    // write them ("PL110 / Vigor").
    if (std::all_of(words.begin(), words.end(),
                    [](const QString &w) { return model::Target::byId(w) != nullptr; })) {
        for (QString &w : words)
            w = model::Target::byId(w)->displayName;
        return words.join(QStringLiteral(" / "));
    }
    int mnemonics = 0;
    for (QString &w : words)
        if (target && target->findInstruction(w.toUpper())) {
            w = w.toUpper();
            ++mnemonics;
        }
    if (mnemonics == words.size() && words.size() > 1)
        return words.join(QStringLiteral(" / "));
    words.front()[0] = words.front()[0].toUpper();
    return words.join(QLatin1Char(' '));
}

QStringList examplesWithTitles() {
    QStringList names;
    for (const ExampleTitle &row : kTitles)
        names << QLatin1String(row.baseName);
    return names;
}

} // namespace rung::app
