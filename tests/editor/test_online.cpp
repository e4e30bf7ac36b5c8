// The IDE online (issue 13): the main window and its connection panel against the virtual
// PLC served over a real pseudo-terminal, for Vigor Computer Link, Modbus RTU (PL110) and
// Host Link (CPM1): connect, see a coil follow an input set in the PLC, force a bit, write a
// word, RUN / STOP, pull the cable and see the error, the stale values and the reconnect.
// Every wait has a deadline of a few seconds; the virtual PLC scans every 10 ms.

#include "app/gui/connection_panel.h"
#include "app/gui/main_window.h"
#include "app/gui/simulation_controller.h"
#include "comms/driver/online_session.h"
#include "editor/ladder_view.h"
#include "editor/watch_list_view.h"
#include "model/target/address.h"
#include "tests/cli/virtual_plc_fixture.h"
#include "tests/editor/watch_rows.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QHelpEvent>
#include <QLabel>
#include <QLayout>
#include <QLineEdit>
#include <QMenu>
#include <QPlainTextEdit>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStatusBar>
#include <QTabBar>
#include <QTemporaryDir>
#include <QTest>
#include <QToolTip>
#include <QTreeWidget>

#include <gtest/gtest.h>

#include <atomic>

namespace rung::test {
namespace {

using State = comms::OnlineSession::ConnectionState;
constexpr int kPatienceMs = 5000;

// The cable between the virtual PLC and the pty: cut() drops every byte both ways, as a
// pulled cable does; the PLC and the IDE's port stay as they are.
class Cable final : public comms::Transport {
public:
    explicit Cable(std::unique_ptr<comms::Transport> inner)
        : m_inner(std::move(inner)) {}
    void cut(bool cut) { m_cut = cut; }
    QString name() const override { return m_inner->name(); }
    bool open(QString *error) override { return m_inner->open(error); }
    void close() override { m_inner->close(); }
    bool isOpen() const override { return m_inner->isOpen(); }
    bool write(QByteArrayView bytes, QDeadlineTimer deadline, QString *error) override {
        return m_cut ? true : m_inner->write(bytes, deadline, error);
    }
    comms::ReadResult read(QDeadlineTimer deadline) override {
        comms::ReadResult r = m_inner->read(deadline);
        if (m_cut && r.status == comms::ReadResult::Status::Data)
            return {}; // lost on the way: the PLC hears nothing
        return r;
    }
    void discardInput() override { m_inner->discardInput(); }
    void cancel() override { m_inner->cancel(); }

private:
    std::unique_ptr<comms::Transport> m_inner;
    std::atomic<bool> m_cut{false};
};

struct Case {
    const char *name;
    const char *target;
    comms::ProtocolKind protocol;
    const char *listing;
    const char *input; // set in the PLC; the coil follows it
    const char *coil;
    const char *word; // written from the IDE; result = word (+1 for Vigor)
    const char *result;
    int offset;        // result - word
    bool forces;       // the protocol forces bits (Host Link)
    bool monitorMode;  // PROGRAM / MONITOR / RUN (Host Link), else RUN / STOP
    bool setsMode;     // the protocol switches RUN / STOP (not Vigor Computer Link)
    const char *timer; // rung 3 times it from the input: what the overlay writes under it
};

// gtest names a failing case by its protocol, not by its bytes.
void PrintTo(const Case &c, std::ostream *os) {
    *os << c.name;
}

// The timers' presets: a Vigor K constant lives in the program (the link reads no set
// value), the PL110's is read from PT1, the CPM1's # constant is in the program too.
const Case kCases[] = {
    {"Vigor", "vigor", comms::ProtocolKind::VigorLink,
     "LD X0\nOUT Y0\nLD M9000\nADD D0 K1 D1\nLD X0\nTMR T0 K350\nEND\n", "X0", "Y0", "D0", "D1", 1,
     false, false, false, "/350 ×0.1 s"},
    {"Pl110Modbus", "pl110", comms::ProtocolKind::ModbusRtu,
     "LD I1\nOUT Q1\nLD SM0.0\nMOV V0 V1\nLD I1\nTON T1 300 100\nEND\n", "I1", "Q1", "V0", "V1", 0,
     false, false, true, "/300 ×0.1 s"},
    {"Cpm1HostLink", "cpm1", comms::ProtocolKind::HostLink,
     "LD 000.01\nOUT 010.01\nLD 253.13\nMOV(21) DM 0000 DM 0001\nLD 000.01\nTIM 000 "
     "#0350\nEND(01)\n",
     "000.01", "010.01", "DM 0000", "DM 0001", 0, true, true, true, "/350 ×0.1 s"},
};

class Online : public ::testing::TestWithParam<Case> {
protected:
    const Case &c = GetParam();
    const model::Target &target = *model::Target::byId(QString::fromLatin1(c.target));
    QTemporaryDir dir;
    std::unique_ptr<app::VirtualPlc> plc;
    Cable *cable = nullptr;
    QString path;
    app::MainWindow window;
    app::ConnectionPanel *panel = window.connectionPanel();
    QStringList questions;

    void SetUp() override {
        // The virtual PLC, as `rungstudio-cli serve --pty` runs it, behind the cable.
        const QString file = dir.filePath(QStringLiteral("plc.il"));
        QFile f(file);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write("; target: ");
        f.write(c.target);
        f.write("\n");
        f.write(c.listing);
        f.close();
        QString errText;
        QTextStream err(&errText);
        app::LoadedProgram loaded;
        ASSERT_EQ(app::loadProgram({file, {}, {}}, &loaded, err), 0) << errText.toStdString();
        app::VirtualPlc::Options o;
        o.slave.protocol = comms::protocolIdOf(c.protocol);
        o.slave.station = comms::defaultSettings(c.protocol).station;
        o.periodMs = 10;
        plc = std::make_unique<app::VirtualPlc>(loaded.program, o);
        QString error;
        auto pty = comms::PtyTransport::createPair(&error);
        ASSERT_TRUE(pty) << error.toStdString();
        path = pty->peerPath();
        auto wire = std::make_unique<Cable>(std::move(pty));
        cable = wire.get();
        ASSERT_TRUE(plc->serve(std::move(wire), &error)) << error.toStdString();

        // The same program in the IDE, online to it.
        window.newProject(target, target.defaultModel().name);
        std::vector<model::Diagnostic> errors;
        ASSERT_TRUE(window.document()->setListing(QString::fromLatin1(c.listing), &errors));
        window.resize(1200, 800);
        window.show();
        panel->setConfirmer([this](const QString &, const QString &text) {
            questions << text;
            return true;
        });
        comms::ConnectionSettings s = comms::defaultSettings(c.protocol);
        s.port = path;
        s.link.timeoutMs = 150;
        s.link.retries = 1;
        panel->setSettings(s);
    }
    void TearDown() override {
        panel->disconnectFromPlc();
        plc.reset();
    }

    model::Address at(const char *device) const {
        return std::get<model::Address>(model::parseAddress(target, QString::fromLatin1(device)));
    }
    comms::OnlineSession *session() const { return panel->session(); }
    std::shared_ptr<const model::Snapshot> shown() const {
        return window.monitorSource() ? window.monitorSource()->snapshot() : nullptr;
    }
    qint64 value(const char *device) const {
        const auto s = shown();
        return s ? s->value(at(device)) : -99999;
    }
    bool bit(const char *device) const {
        const auto s = shown();
        return s && s->bit(at(device));
    }
    // The PLC's own image, as a device on the machine sets it.
    void setInPlc(const char *device, bool on) {
        const auto change =
            plc->image()->apply({{model::DeviceCommand::Kind::WriteBit, at(device), on ? 1 : 0}},
                                QDeadlineTimer(kPatienceMs));
        ASSERT_TRUE(change.done()) << change.message.toStdString();
    }
    qint64 plcValue(const char *device) const {
        return plc->image()->snapshot()->value(at(device));
    }
    // commandFinished for the id: ok, and the text.
    std::pair<bool, QString> finished(model::MonitorSource::CommandId id, QSignalSpy &spy) {
        const auto find = [&]() -> const QList<QVariant> * {
            for (const auto &call : spy)
                if (call[0].value<model::MonitorSource::CommandId>() == id)
                    return &call;
            return nullptr;
        };
        if (!QTest::qWaitFor([&] { return find() != nullptr; }, kPatienceMs))
            return {false, QStringLiteral("no answer within the patience")};
        return {find()->at(1).toBool(), find()->at(2).toString()};
    }
    QAction *action(const char *name) const {
        return window.findChild<QAction *>(QString::fromLatin1(name));
    }
    void goOnline() {
        QAction *go = action("onlineConnect");
        ASSERT_TRUE(go && go->isEnabled());
        go->trigger();
        ASSERT_TRUE(session());
        ASSERT_TRUE(QTest::qWaitFor([&] { return session()->connectionState() == State::Online; },
                                    kPatienceMs))
            << panel->stateText().toStdString();
    }
};

TEST_P(Online, TheViewsShowThePlcAndFollowItsInputs) {
    goOnline();
    EXPECT_EQ(window.monitorSource(), session());
    EXPECT_TRUE(window.findChild<QDockWidget *>(QStringLiteral("connectionDock"))->isVisible());
    auto *origin = window.statusBar()->findChild<QLabel *>(QStringLiteral("monitorOrigin"));
    ASSERT_TRUE(origin);
    EXPECT_EQ(origin->text(), app::MainWindow::originText(app::MainWindow::MonitorOrigin::Online));
    EXPECT_TRUE(panel->stateText().startsWith(QStringLiteral("Online: ")))
        << panel->stateText().toStdString();
    EXPECT_TRUE(action("onlineConnect")->text().contains(QStringLiteral("Offline")));
    // Only what the views show is polled: the ladder shows the coil and its input.
    const std::vector<model::Address> watched = session()->watched();
    EXPECT_NE(std::find(watched.begin(), watched.end(), at(c.coil)), watched.end());

    setInPlc(c.input, true);
    EXPECT_TRUE(QTest::qWaitFor([&] { return bit(c.coil); }, kPatienceMs));
    setInPlc(c.input, false);
    EXPECT_TRUE(QTest::qWaitFor([&] { return !bit(c.coil); }, kPatienceMs));
    // Every device the views show has an address on the wire: no "... has no address in ..."
    // (the CPM1's 253.13 is read by RR, as `rungstudio-cli read` reads it).
    EXPECT_TRUE(session()->errorText().isEmpty()) << session()->errorText().toStdString();
    EXPECT_TRUE(QTest::qWaitFor([&] { return !panel->trafficLog()->toPlainText().isEmpty(); },
                                kPatienceMs));
    EXPECT_TRUE(panel->trafficLog()->toPlainText().contains(QStringLiteral("PC>PLC")));
    EXPECT_TRUE(panel->trafficLog()->toPlainText().contains(QStringLiteral("PLC>PC")));
    EXPECT_TRUE(panel->statisticsText().contains(QStringLiteral("Round trip")));
    // Save... writes the log as shown, a record a line.
    const QString saved = dir.filePath(QStringLiteral("traffic.txt"));
    QString error;
    ASSERT_TRUE(panel->saveTraffic(saved, &error)) << error.toStdString();
    QFile log(saved);
    ASSERT_TRUE(log.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(log.readAll());
    EXPECT_TRUE(
        text.startsWith(panel->trafficLog()->toPlainText().section(QLatin1Char('\n'), 0, 0)));
    EXPECT_TRUE(text.contains(QStringLiteral(" PC>PLC ")));
    EXPECT_FALSE(panel->saveTraffic(dir.filePath(QStringLiteral("no/such/dir/t.txt")), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("no/such/dir"))) << error.toStdString();

    // Offline: the simulation's (none) again, and the window says so.
    action("onlineConnect")->trigger();
    EXPECT_EQ(panel->session(), nullptr);
    EXPECT_EQ(window.monitorSource(), nullptr);
    EXPECT_EQ(panel->stateText(), QStringLiteral("Offline"));
}

// A timer's box shows the time elapsed over its preset, read from the PLC where an area
// holds it, else the box's own: never the 0 of a set value no protocol can read.
TEST_P(Online, ATimerShowsItsTimeOverItsPreset) {
    goOnline();
    const auto text = [&] {
        const model::RungOverlay o = window.ladderView()->overlay(2);
        return o.output(0) ? o.output(0)->value : QString();
    };
    EXPECT_TRUE(QTest::qWaitFor(
        [&] { return text() == QStringLiteral("0") + QString::fromUtf8(c.timer); }, kPatienceMs))
        << text().toStdString();
    setInPlc(c.input, true);
    EXPECT_TRUE(QTest::qWaitFor(
        [&] {
            return text().endsWith(QString::fromUtf8(c.timer)) &&
                   !text().startsWith(QLatin1Char('0'));
        },
        kPatienceMs))
        << text().toStdString();
    // Hovering the box: its tooltip names the same preset.
    editor::LadderView *view = window.ladderView();
    const QRect box = view->cellRectOnScreen({2, 0, view->metrics().gridColumns});
    ASSERT_TRUE(box.isValid());
    QHelpEvent hover(QEvent::ToolTip, box.center(), view->viewport()->mapToGlobal(box.center()));
    QApplication::sendEvent(view->viewport(), &hover);
    const QString preset = QString::fromUtf8(c.timer).section(QLatin1Char(' '), 0, 0).mid(1);
    EXPECT_TRUE(QToolTip::text().contains(QStringLiteral("set %1, ").arg(preset)))
        << QToolTip::text().toStdString();
}

TEST_P(Online, WritesAskOnceNameTheDeviceAndThePlcAndShowTheAnswer) {
    goOnline();
    QSignalSpy done(session(), &model::MonitorSource::commandFinished);
    const auto id = session()->writeWord(at(c.word), 41);
    const auto [ok, error] = finished(id, done);
    EXPECT_TRUE(ok) << error.toStdString();
    ASSERT_EQ(questions.size(), 1);
    EXPECT_TRUE(questions[0].contains(model::formatAddress(target, at(c.word))))
        << questions[0].toStdString();
    EXPECT_TRUE(questions[0].contains(session()->plcName())) << questions[0].toStdString();
    EXPECT_TRUE(panel->lastCommandText().contains(QStringLiteral("acknowledged")))
        << panel->lastCommandText().toStdString();
    EXPECT_TRUE(QTest::qWaitFor([&] { return plcValue(c.result) == 41 + c.offset; }, kPatienceMs))
        << plcValue(c.result);

    // Force the coil: against the program where the protocol forces, else a clear refusal.
    const auto forced = session()->force(at(c.coil), true);
    const auto [forceOk, forceError] = finished(forced, done);
    EXPECT_EQ(questions.size(), 1) << "asked once for each connection";
    EXPECT_EQ(forceOk, c.forces) << forceError.toStdString();
    if (c.forces) {
        EXPECT_TRUE(QTest::qWaitFor([&] { return bit(c.coil); }, kPatienceMs));
        const auto released = session()->releaseAll();
        EXPECT_TRUE(finished(released, done).first);
        EXPECT_TRUE(QTest::qWaitFor([&] { return !bit(c.coil); }, kPatienceMs));
    } else {
        EXPECT_FALSE(forceError.isEmpty());
        EXPECT_TRUE(panel->lastCommandText().contains(forceError))
            << panel->lastCommandText().toStdString();
    }

    // Declined: nothing is sent, and the panel says so.
    panel->disconnectFromPlc();
    questions.clear();
    panel->setConfirmer([this](const QString &, const QString &text) {
        questions << text;
        return false;
    });
    goOnline();
    QSignalSpy again(session(), &model::MonitorSource::commandFinished);
    const auto refused = session()->writeWord(at(c.word), 7);
    const auto [refusedOk, why] = finished(refused, again);
    EXPECT_FALSE(refusedOk);
    EXPECT_TRUE(why.contains(QStringLiteral("nothing was sent"))) << why.toStdString();
    EXPECT_EQ(questions.size(), 1);
    EXPECT_EQ(plcValue(c.result), 41 + c.offset);
}

// The ladder's context menu offers a force only where the protocol has one; elsewhere the
// entries are greyed and say why (and what to do instead), instead of a refusal after a try.
TEST_P(Online, TheContextMenuOffersForcesOnlyWhereTheProtocolCanForce) {
    auto *ladder = window.findChild<editor::LadderView *>();
    ASSERT_TRUE(ladder);
    goOnline();
    std::unique_ptr<QMenu> menu(ladder->monitorMenu({0, 0, 0}, nullptr));
    ASSERT_NE(menu, nullptr);
    const auto entry = [&menu](const QString &text) -> QAction * {
        for (QAction *a : menu->actions())
            if (QString(a->text()).remove(QLatin1Char('&')) == text)
                return a;
        return nullptr;
    };
    const QString input = model::formatAddress(target, at(c.input));
    QAction *force = entry(QStringLiteral("Force %1 ON").arg(input));
    QAction *release = entry(QStringLiteral("Release %1").arg(input));
    QAction *set = entry(QStringLiteral("Set %1 ON").arg(input));
    ASSERT_TRUE(force && release && set);
    EXPECT_TRUE(set->isEnabled());
    EXPECT_EQ(force->isEnabled(), c.forces);
    EXPECT_EQ(release->isEnabled(), c.forces);
    EXPECT_EQ(session()->forceRefusal().isEmpty(), c.forces);
    if (!c.forces) {
        EXPECT_TRUE(force->toolTip().contains(session()->plcName()))
            << force->toolTip().toStdString();
        EXPECT_TRUE(force->toolTip().contains(QStringLiteral("Set the bit instead")))
            << force->toolTip().toStdString();
    }
}

TEST_P(Online, RunAndStopAskFirstAndTheModeFollows) {
    goOnline();
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return session()->plcMode() == comms::PlcMode::Run; }, kPatienceMs))
        << comms::modeName(session()->plcMode()).toStdString();
    EXPECT_EQ(action("onlineMonitor")->isEnabled(), c.monitorMode);
    EXPECT_EQ(action("onlineReleaseAll")->isEnabled(), c.forces);
    if (!c.setsMode) {
        // Nothing offered that the protocol cannot do, and the menu says why.
        EXPECT_FALSE(action("onlineProgram")->isEnabled());
        EXPECT_FALSE(action("onlineRun")->isEnabled());
        EXPECT_TRUE(action("onlineRun")->toolTip().contains(QStringLiteral("switch on the PLC")))
            << action("onlineRun")->toolTip().toStdString();
        // Hovered in the open menu, the greyed entry says it.
        QMenu *menu = nullptr;
        for (QObject *o : action("onlineRun")->associatedObjects())
            if (auto *m = qobject_cast<QMenu *>(o))
                menu = m;
        ASSERT_TRUE(menu);
        menu->popup(window.mapToGlobal(QPoint(200, 40)));
        ASSERT_TRUE(QTest::qWaitForWindowExposed(menu));
        const QPoint at = menu->actionGeometry(action("onlineRun")).center();
        QHelpEvent hover(QEvent::ToolTip, at, menu->mapToGlobal(at));
        QApplication::sendEvent(menu, &hover);
        EXPECT_EQ(QToolTip::text(), action("onlineRun")->toolTip());
        menu->close();
        // Asked anyway (a script, a key held over): the answer says it is not done.
        QSignalSpy done(session(), &model::MonitorSource::commandFinished);
        panel->requestPlcMode(comms::PlcMode::Stop);
        EXPECT_TRUE(QTest::qWaitFor([&] { return done.size() == 1; }, kPatienceMs));
        EXPECT_FALSE(done[0][1].toBool());
        EXPECT_TRUE(panel->lastCommandText().contains(QStringLiteral("not done")))
            << panel->lastCommandText().toStdString();
        EXPECT_EQ(session()->plcMode(), comms::PlcMode::Run);
        return;
    }
    EXPECT_EQ(action("onlineRun")->toolTip(), QStringLiteral("PLC to RUN")); // Qt's default
    QSignalSpy done(session(), &model::MonitorSource::commandFinished);
    action("onlineProgram")->trigger();
    ASSERT_EQ(questions.size(), 1);
    EXPECT_TRUE(questions[0].contains(session()->plcName()));
    const comms::PlcMode stopped = c.monitorMode ? comms::PlcMode::Program : comms::PlcMode::Stop;
    EXPECT_TRUE(QTest::qWaitFor([&] { return session()->plcMode() == stopped; }, kPatienceMs))
        << comms::modeName(session()->plcMode()).toStdString() << " "
        << panel->lastCommandText().toStdString();
    action("onlineRun")->trigger();
    EXPECT_EQ(questions.size(), 2);
    EXPECT_TRUE(
        QTest::qWaitFor([&] { return session()->plcMode() == comms::PlcMode::Run; }, kPatienceMs));
    // Declined: nothing is sent and the mode stays. Proved by a round trip that must come
    // after it, not by a pause: the session sends waiting commands before each refresh, so
    // once the views show an input changed in the PLC after the refusal, a mode change asked
    // before would have gone first (and PROGRAM / STOP would have kept the coil from following).
    panel->setConfirmer([](const QString &, const QString &) { return false; });
    QSignalSpy commands(session(), &model::MonitorSource::commandFinished);
    action("onlineProgram")->trigger();
    const bool on = !plc->image()->snapshot()->bit(at(c.input));
    setInPlc(c.input, on);
    EXPECT_TRUE(QTest::qWaitFor([&] { return bit(c.coil) == on; }, kPatienceMs));
    EXPECT_TRUE(commands.isEmpty()); // no command started, not even one answered "cancelled"
    EXPECT_EQ(session()->plcMode(), comms::PlcMode::Run);
    EXPECT_EQ(plc->image()->mode(), comms::slave::OperatingMode::Run);
}

TEST_P(Online, APulledCableShowsAtOnceKeepsStaleValuesAndReconnectsByItself) {
    goOnline();
    setInPlc(c.input, true);
    ASSERT_TRUE(QTest::qWaitFor([&] { return bit(c.coil); }, kPatienceMs));
    cable->cut(true);
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return session()->connectionState() == State::Lost; }, kPatienceMs));
    EXPECT_TRUE(panel->stateText().startsWith(QStringLiteral("Connection ")))
        << panel->stateText().toStdString();
    // Said once: "lost", the PLC, the cause, and that it tries again.
    EXPECT_EQ(panel->stateText().count(QStringLiteral("lost")), 1)
        << panel->stateText().toStdString();
    EXPECT_EQ(panel->stateText().count(QStringLiteral("Trying again")), 1)
        << panel->stateText().toStdString();
    EXPECT_TRUE(panel->stateText().contains(session()->plcName()))
        << panel->stateText().toStdString();
    EXPECT_FALSE(session()->errorText().isEmpty());
    EXPECT_TRUE(QTest::qWaitFor([&] { return shown() && shown()->stale; }, kPatienceMs));
    EXPECT_TRUE(bit(c.coil)) << "the last value is kept";
    EXPECT_EQ(window.monitorSource(), session()) << "still the PLC's, marked stale";
    // Cable back: online again without the user doing anything, values live.
    setInPlc(c.input, false);
    cable->cut(false);
    EXPECT_TRUE(
        QTest::qWaitFor([&] { return session()->connectionState() == State::Online; }, kPatienceMs))
        << panel->stateText().toStdString();
    EXPECT_TRUE(QTest::qWaitFor([&] { return !bit(c.coil) && !shown()->stale; }, kPatienceMs));
    EXPECT_GE(session()->statistics().reconnects, 1u);
    EXPECT_TRUE(panel->statisticsText().contains(QStringLiteral("reconnects 1")))
        << panel->statisticsText().toStdString();
}

// Issue 31: the watch table names a timer's preset as the box does (the Vigor's K constant
// lives in the program: "60 of 350", not "60 of ?").
TEST_P(Online, TheWatchTableShowsATimersPresetAsTheBoxDoes) {
    editor::WatchListView *watch = window.watchListView();
    const char *timer = c.protocol == comms::ProtocolKind::VigorLink   ? "T0"
                        : c.protocol == comms::ProtocolKind::ModbusRtu ? "T1"
                                                                       : "TIM 000";
    watch->addDevice(model::formatAddress(target, at(timer)));
    ASSERT_EQ(test::watchRows(watch), 1);
    const QPersistentModelIndex row =
        test::watchIndex(watch, 0, 0, editor::WatchListView::ValueColumn);
    ASSERT_TRUE(row.isValid());
    goOnline();
    const QString preset =
        QStringLiteral(" of %1, ")
            .arg(QString::fromUtf8(c.timer).section(QLatin1Char(' '), 0, 0).mid(1));
    EXPECT_TRUE(
        QTest::qWaitFor([&] { return row.data().toString().contains(preset); }, kPatienceMs))
        << row.data().toString().toStdString();
}

// Issue 31: a value typed in the watch table is not shown while the first write of the
// connection is asked about (nor after a no): the row shows what the PLC holds.
TEST_P(Online, AWatchValueIsNotShownBeforeTheWriteIsConfirmed) {
    editor::WatchListView *watch = window.watchListView();
    watch->addDevice(model::formatAddress(target, at(c.word)));
    const QPersistentModelIndex row =
        test::watchIndex(watch, 0, 0, editor::WatchListView::ValueColumn);
    ASSERT_TRUE(row.isValid());
    goOnline();
    const auto shownValue = [&] { return row.data().toString(); };
    ASSERT_TRUE(QTest::qWaitFor([&] { return !shownValue().isEmpty(); }, kPatienceMs));
    const QString before = shownValue();
    QString whileAsked = QStringLiteral("(not asked)");
    panel->setConfirmer([&](const QString &, const QString &) {
        whileAsked = shownValue();
        return false;
    });
    // Typed into the value column, as the cell editor commits it.
    watch->model()->setData(row, QStringLiteral("4321"));
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return whileAsked != QStringLiteral("(not asked)"); }, kPatienceMs));
    EXPECT_EQ(whileAsked, before);
    EXPECT_EQ(shownValue(), before);
}

// Issue 31: what the PLC cannot answer online is a warning of its own, not in the green of
// "Online" (a CPM1's TR bits have no Host Link address).
TEST_P(Online, ADeviceThePlcCannotReadIsAWarningApartFromTheState) {
    if (c.protocol != comms::ProtocolKind::HostLink)
        GTEST_SKIP() << "the TR bits are a CPM1's";
    window.watchListView()->addDevice(QStringLiteral("TR 0"));
    goOnline();
    ASSERT_TRUE(QTest::qWaitFor([&] { return !panel->warningText().isEmpty(); }, kPatienceMs));
    EXPECT_TRUE(panel->warningText().contains(QStringLiteral("TR 0")))
        << panel->warningText().toStdString();
    auto *state = panel->findChild<QLabel *>(QStringLiteral("connectionState"));
    auto *warning = panel->findChild<QLabel *>(QStringLiteral("connectionWarning"));
    ASSERT_TRUE(state && warning);
    EXPECT_TRUE(QTest::qWaitFor([&] { return warning->isVisible(); }, kPatienceMs));
    EXPECT_TRUE(warning->text().contains(panel->warningText()));
    EXPECT_FALSE(state->text().contains(panel->warningText())) << state->text().toStdString();
    EXPECT_TRUE(state->text().startsWith(QStringLiteral("Online: ")));
    // The state in the green of Online; the warning not green, not bold.
    EXPECT_TRUE(state->styleSheet().contains(QStringLiteral("#1b5e20")));
    EXPECT_FALSE(warning->styleSheet().contains(QStringLiteral("#1b5e20")));
    EXPECT_FALSE(warning->styleSheet().contains(QStringLiteral("bold")));
}

// An online PLC and a simulation never feed the views together (the window's side, the same
// for every protocol: tried with one).
class OnlineAndSimulation : public Online {};

TEST_P(OnlineAndSimulation, GoingOnlinePausesTheSimulationAndSimulatingOffersToGoOffline) {
    using RunState = model::MonitorSource::RunState;
    app::SimulationController *simulation = window.simulation();
    ASSERT_TRUE(simulation->run());
    ASSERT_EQ(window.monitorSource(), simulation->monitorSource());
    // Declined: the simulation goes on, nothing connects.
    panel->setConfirmer([this](const QString &, const QString &text) {
        questions << text;
        return false;
    });
    action("onlineConnect")->trigger();
    EXPECT_EQ(session(), nullptr);
    ASSERT_EQ(questions.size(), 1);
    EXPECT_TRUE(questions[0].contains(QStringLiteral("simulation"))) << questions[0].toStdString();
    EXPECT_EQ(simulation->runState(), RunState::Running);
    // Accepted: paused, and the views show the PLC.
    panel->setConfirmer([this](const QString &, const QString &text) {
        questions << text;
        return true;
    });
    goOnline();
    EXPECT_TRUE(
        QTest::qWaitFor([&] { return simulation->runState() == RunState::Paused; }, kPatienceMs));
    EXPECT_EQ(window.monitorSource(), session());
    // Run while online: paused again, and the offer to go offline; declined keeps the PLC.
    panel->setConfirmer([this](const QString &, const QString &text) {
        questions << text;
        return false;
    });
    simulation->run();
    EXPECT_TRUE(
        QTest::qWaitFor([&] { return simulation->runState() == RunState::Paused; }, kPatienceMs));
    EXPECT_TRUE(questions.last().contains(QStringLiteral("Go offline to simulate")))
        << questions.last().toStdString();
    EXPECT_NE(session(), nullptr);
    EXPECT_EQ(window.monitorSource(), session());
    // Accepted: offline, and the simulation runs and feeds the views again.
    panel->setConfirmer([](const QString &, const QString &) { return true; });
    simulation->run();
    EXPECT_TRUE(QTest::qWaitFor([&] { return session() == nullptr; }, kPatienceMs));
    EXPECT_TRUE(
        QTest::qWaitFor([&] { return simulation->runState() == RunState::Running; }, kPatienceMs));
    EXPECT_EQ(window.monitorSource(), simulation->monitorSource());
}

INSTANTIATE_TEST_SUITE_P(VirtualPlcOnAPty, Online, ::testing::ValuesIn(kCases),
                         [](const auto &info) { return std::string(info.param.name); });
INSTANTIATE_TEST_SUITE_P(VirtualPlcOnAPty, OnlineAndSimulation, ::testing::Values(kCases[0]),
                         [](const auto &info) { return std::string(info.param.name); });

// Without a PLC on the line: the test says what it found (nothing) without hanging the UI.
TEST(OnlinePanel, TestConnectionOnASilentLineSaysSoWithinItsDeadline) {
    QString error;
    auto pty = comms::PtyTransport::createPair(&error); // nobody answers on it
    ASSERT_TRUE(pty) << error.toStdString();
    app::MainWindow window;
    window.newProject(model::Target::get(model::Family::Pl110), QString());
    app::ConnectionPanel *panel = window.connectionPanel();
    comms::ConnectionSettings s = comms::defaultSettings(comms::ProtocolKind::ModbusRtu);
    s.port = pty->peerPath();
    s.link.timeoutMs = 100;
    s.link.retries = 0;
    panel->setSettings(s);
    QSignalSpy result(panel, &app::ConnectionPanel::testFinished);
    auto *settings = panel->findChild<QWidget *>(QStringLiteral("connectionSettings"));
    ASSERT_NE(settings, nullptr);
    EXPECT_TRUE(settings->isEnabled());
    ASSERT_TRUE(panel->testConnection());
    // While it tests, the settings it tests cannot change under it.
    EXPECT_FALSE(settings->isEnabled());
    ASSERT_TRUE(result.wait(kPatienceMs));
    EXPECT_TRUE(settings->isEnabled());
    EXPECT_FALSE(result[0][0].toBool());
    EXPECT_TRUE(result[0][1].toString().startsWith(QStringLiteral("No answer")))
        << result[0][1].toString().toStdString();
    EXPECT_EQ(panel->session(), nullptr);
}

TEST(OnlinePanel, TestConnectionReadsTheIdentityOfTheVirtualPlc) {
    comms::slave::SlaveOptions options;
    options.protocol = model::ProtocolId::HostLink;
    options.station = 0;
    VirtualPlcUnderTest plc("; target: cpm1\nLD 000.01\nOUT 010.01\nEND(01)\n", options, false);
    ASSERT_TRUE(plc.ready());
    app::MainWindow window;
    window.newProject(model::Target::get(model::Family::Cpm1), QString());
    app::ConnectionPanel *panel = window.connectionPanel();
    comms::ConnectionSettings s = comms::defaultSettings(comms::ProtocolKind::HostLink);
    s.port = plc.path;
    panel->setSettings(s);
    QSignalSpy result(panel, &app::ConnectionPanel::testFinished);
    ASSERT_TRUE(panel->testConnection());
    ASSERT_TRUE(result.wait(kPatienceMs));
    EXPECT_TRUE(result[0][0].toBool()) << result[0][1].toString().toStdString();
    EXPECT_TRUE(result[0][1].toString().contains(QStringLiteral("model code 11h")))
        << result[0][1].toString().toStdString();
    EXPECT_EQ(panel->session(), nullptr) << "a test does not stay online";
}

// Online > Test Connection before a port is chosen: the panel comes to the front, says what
// it needs where the user looks, and puts the cursor in the port's field.
TEST(OnlinePanel, TestConnectionWithoutAPortShowsThePanelAndAsksForOne) {
    app::MainWindow window;
    window.newProject(model::Target::get(model::Family::Pl110), QString());
    window.show();
    window.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&window));
    app::ConnectionPanel *panel = window.connectionPanel();
    comms::ConnectionSettings s = comms::defaultSettings(comms::ProtocolKind::ModbusRtu);
    s.port.clear();
    panel->setSettings(s);
    auto *port = panel->findChild<QComboBox *>(QStringLiteral("connectionPort"));
    ASSERT_TRUE(port);
    EXPECT_FALSE(port->lineEdit()->placeholderText().isEmpty()) << "the empty field says why";
    // The panel was open once, and the project is in front of it now.
    window.findChild<QDockWidget *>(QStringLiteral("connectionDock"))->show();
    QApplication::processEvents();
    window.findChild<QDockWidget *>(QStringLiteral("projectDock"))->raise();
    QApplication::processEvents();
    // The tab in front in the panel's tab group.
    const auto front = [&window]() -> QString {
        for (QTabBar *bar : window.findChildren<QTabBar *>())
            for (int i = 0; i < bar->count(); ++i)
                if (bar->tabText(i) == QStringLiteral("Connection"))
                    return bar->tabText(bar->currentIndex());
        return {};
    };
    ASSERT_EQ(front(), QStringLiteral("Project"));
    window.findChild<QAction *>(QStringLiteral("onlineTest"))->trigger();
    QApplication::processEvents();
    EXPECT_EQ(front(), QStringLiteral("Connection")) << "not behind another tab";
    const auto *result = panel->findChild<QLabel *>(QStringLiteral("connectionTestResult"));
    EXPECT_TRUE(result->text().startsWith(QStringLiteral("Choose the serial port")))
        << result->text().toStdString();
    EXPECT_TRUE(QTest::qWaitFor([&] { return port->hasFocus(); }, kPatienceMs));
    EXPECT_EQ(panel->session(), nullptr);
}

// The TCP settings take the room they need: no gap where the serial ones (three rows) would be.
TEST(OnlinePanel, TheTcpSettingsAreNotFollowedByTheSerialOnesRoom) {
    app::MainWindow window;
    window.newProject(model::Target::get(model::Family::Pl110), QString());
    app::ConnectionPanel *panel = window.connectionPanel();
    auto *via = panel->findChild<QWidget *>(QStringLiteral("connectionVia"));
    auto *host = panel->findChild<QLineEdit *>(QStringLiteral("connectionHost"));
    auto *port = panel->findChild<QComboBox *>(QStringLiteral("connectionPort"));
    ASSERT_TRUE(via && host && port);
    window.show();
    const auto heightFor = [via] { return via->layout()->totalHeightForWidth(300); };
    comms::ConnectionSettings s = comms::defaultSettings(comms::ProtocolKind::ModbusTcp);
    s.via = comms::ConnectionSettings::Via::Tcp;
    panel->setSettings(s);
    ASSERT_TRUE(host->isVisibleTo(panel));
    ASSERT_FALSE(port->isVisibleTo(panel));
    const int tcp = heightFor();
    panel->setSettings(comms::defaultSettings(comms::ProtocolKind::ModbusRtu));
    ASSERT_TRUE(port->isVisibleTo(panel));
    const int serial = heightFor();
    EXPECT_LT(tcp, serial) << "the TCP settings (two rows) keep the serial ones' (three) room";
}

TEST(OnlinePanel, AVpcIsListedAndSaysWhatToDoInstead) {
    app::MainWindow window;
    window.newProject(model::Target::get(model::Family::Vpc), QString());
    app::ConnectionPanel *panel = window.connectionPanel();
    EXPECT_FALSE(panel->canConnect());
    auto *note = panel->findChild<QLabel *>(QStringLiteral("connectionUnpublished"));
    ASSERT_TRUE(note);
    EXPECT_TRUE(note->text().contains(QStringLiteral("not published")));
    EXPECT_TRUE(note->text().contains(QStringLiteral("rungstudio-cli record")));
    EXPECT_FALSE(panel->connectToPlc());
    // Greyed in the Online menu and the tool bar, and hovering says why and what instead.
    for (const char *name : {"onlineConnect", "onlineTest"}) {
        QAction *a = window.findChild<QAction *>(QString::fromLatin1(name));
        EXPECT_FALSE(a->isEnabled()) << name;
        EXPECT_EQ(a->toolTip(), note->text()) << name;
    }
    // A PL110 project after it: the entries are live and say what they do.
    window.newProject(model::Target::get(model::Family::Pl110), QString());
    QAction *go = window.findChild<QAction *>(QStringLiteral("onlineConnect"));
    EXPECT_TRUE(go->isEnabled());
    EXPECT_TRUE(go->toolTip().startsWith(QStringLiteral("Go Online")))
        << go->toolTip().toStdString();
}

TEST(OnlinePanel, ThePortIsRememberedForTheNextWindow) {
    QString error;
    auto pty = comms::PtyTransport::createPair(&error);
    ASSERT_TRUE(pty) << error.toStdString();
    {
        app::MainWindow window;
        window.newProject(model::Target::get(model::Family::Pl110), QString());
        comms::ConnectionSettings s = comms::defaultSettings(comms::ProtocolKind::ModbusRtu);
        s.port = pty->peerPath();
        s.link.timeoutMs = 50;
        s.link.retries = 0;
        window.connectionPanel()->setSettings(s);
        ASSERT_TRUE(window.connectionPanel()->connectToPlc());
        window.connectionPanel()->disconnectFromPlc();
    }
    app::MainWindow window;
    window.newProject(model::Target::get(model::Family::Pl110), QString());
    EXPECT_EQ(window.connectionPanel()->settings().port, pty->peerPath());
}

TEST(OnlinePanel, LineSettingsStartFromTheProtocolsDefaults) {
    app::MainWindow window;
    window.newProject(model::Target::get(model::Family::Cpm1), QString());
    const comms::ConnectionSettings hostLink = window.connectionPanel()->settings();
    EXPECT_EQ(hostLink.protocol, comms::ProtocolKind::HostLink);
    EXPECT_EQ(hostLink.serial.baud, 9600);
    EXPECT_EQ(comms::frameFormatText(hostLink.serial), QStringLiteral("7E2"));
    EXPECT_EQ(hostLink.station, 0);
    window.newProject(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    const comms::ConnectionSettings vigor = window.connectionPanel()->settings();
    EXPECT_EQ(vigor.protocol, comms::ProtocolKind::VigorLink);
    EXPECT_EQ(vigor.serial.baud, 19200);
    EXPECT_EQ(comms::frameFormatText(vigor.serial), QStringLiteral("7E1"));
}

// The station field takes the stations the protocol numbers, no more: Host Link units 0..31,
// Vigor stations 0..255, Modbus 1..247 and the PL110's 255 for "any" (it was 0..247 for all).
TEST(OnlinePanel, TheStationFieldTakesTheProtocolsStations) {
    app::MainWindow window;
    auto *station =
        window.connectionPanel()->findChild<QSpinBox *>(QStringLiteral("connectionStation"));
    ASSERT_NE(station, nullptr);
    const auto range = [station] { return std::pair{station->minimum(), station->maximum()}; };
    window.newProject(model::Target::get(model::Family::Cpm1), QString());
    EXPECT_EQ(range(), (std::pair{0, 31}));
    window.newProject(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    EXPECT_EQ(range(), (std::pair{0, 255}));
    window.newProject(model::Target::get(model::Family::Pl110), QString());
    EXPECT_EQ(window.connectionPanel()->settings().protocol, comms::ProtocolKind::ModbusRtu);
    EXPECT_EQ(range(), (std::pair{1, 255}));
}

} // namespace
} // namespace rung::test
