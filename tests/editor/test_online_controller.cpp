// The window's side of going online (app/gui/online_controller.h) without the Rung Studio
// window: the document, the simulation, a plain main window to dock into and a virtual PLC
// on a pseudo-terminal.

#include "app/gui/connection_panel.h"
#include "app/gui/online_controller.h"
#include "app/gui/simulation_controller.h"
#include "comms/driver/online_session.h"
#include "editor/document.h"
#include "tests/cli/virtual_plc_fixture.h"

#include <QAction>
#include <QDockWidget>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTest>
#include <QToolBar>

#include <gtest/gtest.h>

using namespace rung;
using test::kPatienceMs;

namespace {

// What the window hands its online controller, and the controller.
struct OnlineAlone {
    QMainWindow window; // the dock's and the menu's place: no Rung Studio window
    editor::Document document;
    app::SimulationController simulation{&document};
    app::OnlineController online{&document, &simulation, window.statusBar(), &window};
    QMenu view;
    QToolBar bar;
    QStringList questions;

    OnlineAlone() {
        online.addActions(&bar, &view);
        online.panel()->setConfirmer([this](const QString &, const QString &text) {
            questions << text;
            return answer;
        });
    }
    bool answer = true;
    QAction *action(const char *name) const {
        return window.menuBar()->findChild<QAction *>(QString::fromLatin1(name));
    }
};

} // namespace

TEST(OnlineControllerAlone, TheOnlineMenuFollowsTheTargetAndTheSession) {
    OnlineAlone f;
    // A VPC has no protocol to go online with: greyed, and the entry says why.
    f.document.reset(model::Target::get(model::Family::Vpc),
                     model::Target::get(model::Family::Vpc).defaultModel().name);
    QAction *go = f.action("onlineConnect");
    ASSERT_NE(go, nullptr);
    EXPECT_FALSE(go->isEnabled());
    EXPECT_EQ(go->toolTip(), f.online.panel()->cannotConnectReason());
    EXPECT_FALSE(go->toolTip().isEmpty());
    // A Vigor has: Go Online with its key, the PLC's modes only once online.
    f.document.reset(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    EXPECT_TRUE(go->isEnabled());
    EXPECT_EQ(go->text(), QStringLiteral("Go &Online"));
    EXPECT_EQ(go->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_W));
    for (const char *name : {"onlineProgram", "onlineMonitor", "onlineRun", "onlineReleaseAll"}) {
        ASSERT_NE(f.action(name), nullptr) << name;
        EXPECT_FALSE(f.action(name)->isEnabled()) << name;
    }
    // The toolbar's button is the menu's entry; View shows and hides the dock.
    EXPECT_TRUE(f.bar.actions().contains(go));
    EXPECT_TRUE(f.view.actions().contains(f.online.dock()->toggleViewAction()));
    EXPECT_EQ(f.online.dock()->parent(), &f.window);
    EXPECT_TRUE(f.online.dock()->isHidden());
}

TEST(OnlineControllerAlone, GoingOnlineWhileSimulatingAsksPausesAndHandsTheSessionOver) {
    using RunState = model::MonitorSource::RunState;
    comms::slave::SlaveOptions options;
    options.protocol = model::ProtocolId::VigorLink;
    options.station = comms::defaultSettings(comms::ProtocolKind::VigorLink).station;
    test::VirtualPlcUnderTest plc(test::kFollowerVigor, options, false);
    ASSERT_TRUE(plc.ready());

    OnlineAlone f;
    f.document.reset(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    ASSERT_TRUE(f.document.setListing(QStringLiteral("LD M0\nOUT Y0\nEND\n"), nullptr));
    comms::ConnectionSettings s = comms::defaultSettings(comms::ProtocolKind::VigorLink);
    s.port = plc.path;
    s.link.timeoutMs = 300;
    s.link.retries = 1;
    f.online.panel()->setSettings(s);
    QSignalSpy handedOver(&f.online, &app::OnlineController::sessionChanged);
    ASSERT_TRUE(f.simulation.run());

    // Declined: the simulation goes on, nothing connects, nothing is handed over.
    f.answer = false;
    f.action("onlineConnect")->trigger();
    ASSERT_EQ(f.questions.size(), 1);
    EXPECT_TRUE(f.questions[0].contains(QStringLiteral("The simulation is running")))
        << f.questions[0].toStdString();
    EXPECT_EQ(f.online.session(), nullptr);
    EXPECT_EQ(f.simulation.runState(), RunState::Running);
    EXPECT_EQ(handedOver.count(), 0);

    // Accepted: paused, the dock shown, the session handed over, the entry says Go Offline.
    f.answer = true;
    f.action("onlineConnect")->trigger();
    EXPECT_TRUE(
        QTest::qWaitFor([&] { return f.simulation.runState() == RunState::Paused; }, kPatienceMs));
    ASSERT_NE(f.online.session(), nullptr);
    ASSERT_EQ(handedOver.count(), 1);
    EXPECT_EQ(handedOver[0][0].value<comms::OnlineSession *>(), f.online.session());
    EXPECT_FALSE(f.online.dock()->isHidden());
    EXPECT_TRUE(QTest::qWaitFor(
        [&] {
            return f.online.session()->connectionState() ==
                   comms::OnlineSession::ConnectionState::Online;
        },
        kPatienceMs));
    EXPECT_EQ(f.action("onlineConnect")->text(), QStringLiteral("Go &Offline"));

    // Offline again: null handed over, said in the status bar.
    f.action("onlineConnect")->trigger();
    EXPECT_TRUE(QTest::qWaitFor([&] { return handedOver.count() == 2; }, kPatienceMs));
    EXPECT_EQ(handedOver[1][0].value<comms::OnlineSession *>(), nullptr);
    EXPECT_EQ(f.window.statusBar()->currentMessage(), QStringLiteral("Offline"));
    EXPECT_EQ(f.action("onlineConnect")->text(), QStringLiteral("Go &Online"));
}
