// A scenario test of a network (docs/scenario-tests.md, "A network"): `program NET.rungnet`,
// devices written STATION/DEVICE, the whole network on one virtual clock. Here the MODBUS
// application example of the Vigor M/VB/VH communication manual (B-3-6), shipped with the
// examples, with a fault: a slave that falls silent shows in the master's working area while
// the other slave's value still crosses the wire.

#include "network_fixture.h"

#include "network/network_scenario.h"

#include <QDir>
#include <QTemporaryDir>

using namespace rung;
using namespace rung::network;
using namespace rung::network::test;

namespace {

const QString kModbus = QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/networks/modbus/");

simulator::ScenarioResult runText(const QString &networkJson, const QString &scenario) {
    QTemporaryDir dir;
    QFile net(dir.filePath(QStringLiteral("plant.rungnet")));
    EXPECT_TRUE(net.open(QIODevice::WriteOnly));
    net.write(networkJson.toUtf8());
    net.close();
    return simulator::runScenario(
        scenario, dir.filePath(QStringLiteral("tests/plant.rungtest")),
        [](const QString &, const QString &, const QString &) {
            return simulator::ScenarioProgram{}; // a network only
        },
        [](const QString &path, QStringList *errors) {
            return networkScenarioSubject(path, listingLoader(), errors);
        });
}

QString modbusNetwork(const QString &faults) {
    return QStringLiteral(R"({"stations": [
        {"name": "master", "program": "%1master.il", "model": "VB",
         "ports": {"CP2": {"application": "modbus", "station": 0, "mode": "rtu"}}},
        {"name": "s1", "program": "%1slave.il", "model": "VB",
         "ports": {"CP2": {"application": "modbus", "station": 1, "mode": "rtu"}}},
        {"name": "s2", "program": "%1slave.il", "model": "VB",
         "ports": {"CP2": {"application": "modbus", "station": 2, "mode": "rtu"}}}],
        "wires": [["master/CP2", "s1/CP2", "s2/CP2"]], "faults": [%2]})")
        .arg(kModbus, faults);
}

QStringList messages(const simulator::ScenarioResult &r) {
    QStringList out;
    for (const auto &e : r.errors)
        out << QStringLiteral("%1: %2").arg(e.line).arg(e.message);
    for (const auto &f : r.failures)
        out << QStringLiteral("%1: %2").arg(f.line).arg(f.message);
    return out;
}

} // namespace

TEST(NetworkScenario, ASilentSlaveShowsInTheMastersWorkingAreaAndTheOtherGoesOn) {
    const simulator::ScenarioResult r = runText(
        modbusNetwork(QStringLiteral(R"({"kind": "silent", "station": "s1", "from": 1000})")),
        QStringLiteral("program ../plant.rungnet\n"
                       "at 0s set s1/VR1=255 s2/VR1=255\n"
                       "within 1s expect master/D10=99 master/D11=99\n"
                       "at 1s set s2/VR1=0\n"
                       "within 1s expect master/D100=#0A01\n" // status A, station 1
                       "within 1s expect master/D11=0\n"
                       "at 3s expect master/D10=99\n")); // the last value read stays
    EXPECT_TRUE(r.passed()) << messages(r).join(QLatin1Char('\n')).toStdString();
    EXPECT_EQ(r.expectations.size(), 4u);
    EXPECT_EQ(r.durationMs, 3010); // the scan starting at 3 s, as for one program
}

TEST(NetworkScenario, AFailureNamesTheStationsDevicesAndTheirValues) {
    const simulator::ScenarioResult r =
        runText(modbusNetwork({}), QStringLiteral("program ../plant.rungnet\n"
                                                  "at 0s set s1/VR1=255 master/VR2=150\n"
                                                  "within 1s expect master/D10=98\n"
                                                  "always expect s2/D100<100\n"));
    ASSERT_TRUE(r.ran) << messages(r).join(QLatin1Char('\n')).toStdString();
    ASSERT_EQ(r.failures.size(), 2u) << messages(r).join(QLatin1Char('\n')).toStdString();
    EXPECT_EQ(r.failures[0].line, 3);
    EXPECT_EQ(r.failures[0].message,
              QStringLiteral("within 1s of 0ms (until 1s): expected master/D10=98, seen "
                             "master/D10=99"));
    EXPECT_TRUE(r.failures[0].devices.empty()); // not one program's chart
    EXPECT_EQ(r.failures[1].line, 4);
    EXPECT_TRUE(r.failures[1].message.contains(QStringLiteral("seen s2/D100=150")))
        << r.failures[1].message.toStdString();
}

TEST(NetworkScenario, AStationThatIsNotThereIsAnErrorWithItsLine) {
    const simulator::ScenarioResult r =
        runText(modbusNetwork({}), QStringLiteral("program ../plant.rungnet\n"
                                                  "at 1s expect st9/D0=1\n"
                                                  "at 2s expect D0=1\n"));
    EXPECT_FALSE(r.ran);
    EXPECT_EQ(messages(r),
              (QStringList{QStringLiteral("2: st9/D0: no station \"st9\" (the stations: "
                                          "master, s1, s2)"),
                           QStringLiteral("3: D0: name a station's device as "
                                          "STATION/DEVICE, e.g. master/X0")}));
}

TEST(NetworkScenario, ANetworkThatDoesNotBuildSaysWhyOnTheProgramLine) {
    const simulator::ScenarioResult r =
        runText(QStringLiteral(R"({"stations": [{"name": "m", "program": "nowhere.il"}]})"),
                QStringLiteral("# a plant\nprogram ../plant.rungnet\nat 1s expect m/Y0=1\n"));
    EXPECT_FALSE(r.ran);
    ASSERT_FALSE(r.errors.empty());
    EXPECT_EQ(r.errors.front().line, 2);
    EXPECT_TRUE(r.errors.front().message.contains(QStringLiteral("nowhere.il")))
        << r.errors.front().message.toStdString();
}

// One program's scenario names no station; a network's program line takes no --target.
TEST(NetworkScenario, StationsAreForNetworksAndTargetsForPrograms) {
    const simulator::ScenarioResult one = simulator::runScenario(
        QStringLiteral("program latch.il\nat 1s expect s1/Y0=1\n"), QStringLiteral("/p/t.rungtest"),
        [](const QString &, const QString &, const QString &) {
            const model::Target *vigor = model::Target::byId(QStringLiteral("vigor"));
            const model::ParseResult parsed = model::parseInstructionList(
                *vigor, QStringLiteral("LD X0\nOUT Y0\nEND\n"), &vigor->defaultModel());
            model::CheckOptions checks;
            checks.model = &vigor->defaultModel();
            simulator::ScenarioProgram p;
            p.program = simulator::prepareProgram(parsed.list, checks).program;
            return p;
        });
    EXPECT_EQ(messages(one),
              (QStringList{QStringLiteral("2: s1/Y0: STATION/DEVICE names a device of a network's "
                                          "station; this scenario's program is one PLC")}));
    const simulator::ScenarioResult net = runText(
        modbusNetwork({}), QStringLiteral("program ../plant.rungnet --target cpm1\nat 1s expect "
                                          "master/Y0=0\n"));
    EXPECT_FALSE(net.ran);
    ASSERT_EQ(net.errors.size(), 1u);
    EXPECT_TRUE(net.errors.front().message.contains(QStringLiteral("--target")));
}

// `press STATION/KEY`: the key of that station's front panel (PL110 manual 5.2: SWAP steps
// the pages), the other stations' memory untouched; a key of a station without keys names it.
TEST(NetworkScenario, PressReachesTheStationsFrontPanel) {
    const QString pl110 = QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/networks/pl110-exp/");
    const QString network = QStringLiteral(R"({"stations": [
        {"name": "a", "program": "%1master.il", "target": "pl110", "model": "PL110-2A"},
        {"name": "b", "program": "%1master.il", "target": "pl110", "model": "PL110-2A"},
        {"name": "v", "program": "%2master.il", "model": "VB"}], "wires": []})")
                                .arg(pl110, kModbus);
    const simulator::ScenarioResult r =
        runText(network, QStringLiteral("program ../plant.rungnet\n"
                                        "at 0s expect a/SM105=1 b/SM105=1\n"
                                        "at 100ms press b/SWAP\n"
                                        "at 300ms expect a/SM105=1 b/SM105=2\n"));
    EXPECT_TRUE(r.passed()) << messages(r).join(QLatin1Char('\n')).toStdString();
    EXPECT_EQ(r.expectations.size(), 2u);
    const simulator::ScenarioResult vigor =
        runText(network, QStringLiteral("program ../plant.rungnet\nat 1s press v/SET\n"));
    EXPECT_EQ(messages(vigor).join(QLatin1Char('\n')).toStdString(),
              "2: v/SET: the Vigor has no keys on its front panel to press");
}
