// Bridges from the UI (issue 30): a station's port put on a pseudo-terminal, a serial port or
// TCP from the Network view, with the Connection dock's own settings form; saved in the
// network file; live while the network runs in its window, the pseudo-terminal's path shown
// and copied, and a real master on that path polling the simulated station. And a single
// project's communication ports from the main window, one undo step, kept by the project file.

#include "answer_dialogs.h"
#include "window_fixture.h"

#include "app/gui/language.h"
#include "app/gui/line_settings_form.h"
#include "app/gui/network_bridge_controller.h"
#include "app/gui/network_bridge_dialog.h"
#include "app/gui/network_document.h"
#include "app/gui/network_port_dialog.h"
#include "app/gui/network_view.h"
#include "app/gui/network_window.h"

#include "comms/protocol/modbus_master.h"
#include "comms/transport/pty_transport.h"
#include "editor/document.h"
#include "model/project/project.h"
#include "model/target/target.h"
#include "network/network_file.h"
#include "network/network_session.h"

#include <QApplication>
#include <QClipboard>
#include <QComboBox>
#include <QDeadlineTimer>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QFile>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QProcess>
#include <QPushButton>
#include <QRegularExpression>
#include <QSpinBox>
#include <QStandardPaths>
#include <QUndoStack>

namespace rung::test {
namespace {

using BridgeKind = network::BridgeDescription::Kind;

// A Vigor VB answering MODBUS RTU as station 1 on CP2, its D0 holding 321.
const char *kBridgedNet =
    R"({"stations": [{"name": "plc", "program": "s.il", "model": "VB",
        "ports": {"CP2": {"application": "modbus", "station": 1}}}]})";
const char *kBridgedSlave = "; target: vigor\nLD M9000\nMOV K321 D0\nEND\n";

bool writeText(const QString &path, const char *text) {
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(text) == qint64(qstrlen(text));
}

app::NetworkWindow *openBridgedNetwork(app::MainWindow &window, const QTemporaryDir &dir) {
    const QString file = dir.filePath(QStringLiteral("plant.rungnet"));
    if (!writeText(file, kBridgedNet) ||
        !writeText(dir.filePath(QStringLiteral("s.il")), kBridgedSlave) ||
        !window.openFile(file, QString(), true))
        return nullptr;
    const auto windows = window.findChildren<app::NetworkWindow *>();
    return windows.isEmpty() ? nullptr : windows.back();
}

// What the Bridges dock shows where the port is reached (its rows are made again on changes).
QString shownReached(app::NetworkWindow *net, const QString &end) {
    auto *edit = net->findChild<QLineEdit *>(QStringLiteral("bridgeReached_") + end);
    return edit ? edit->text() : QString();
}

QString shownState(app::NetworkWindow *net, const QString &end) {
    auto *label = net->findChild<QLabel *>(QStringLiteral("bridgeState_") + end);
    return label ? label->text() : QString();
}

// Reads D0 (holding register 0) of MODBUS station 1 through `path` with the product's own
// master codec, as an HMI on the pseudo-terminal would.
std::vector<std::uint16_t> readD0Through(const QString &path, QString *error) {
    comms::PtyTransport hmi(path);
    if (!hmi.open(error))
        return {};
    comms::modbus::Request read;
    read.function = comms::modbus::ReadHoldingRegisters;
    read.address = 0;
    read.count = 1;
    comms::modbus::ReplyDecoder reply(comms::modbus::Framing::Rtu, 1, read);
    if (!hmi.write(comms::modbus::rtuFrame(1, comms::modbus::encodeRequestPdu(read)),
                   QDeadlineTimer(1000), error))
        return {};
    eventually([&] {
        const comms::ReadResult r = hmi.read(QDeadlineTimer(2));
        if (r.status == comms::ReadResult::Status::Data)
            reply.feed(r.bytes);
        return reply.status() != comms::FrameStatus::NeedMore;
    });
    if (reply.status() != comms::FrameStatus::Complete) {
        *error = reply.status() == comms::FrameStatus::NeedMore ? QStringLiteral("no reply")
                                                                : reply.error().message;
        return {};
    }
    return reply.response().registers;
}

TEST(NetworkBridges, APtyBridgeMadeInTheUiIsPolledThroughThePathItShows) {
    QTemporaryDir dir;
    app::MainWindow window;
    app::NetworkWindow *net = openBridgedNetwork(window, dir);
    ASSERT_NE(net, nullptr);
    app::NetworkDocument *doc = net->networkDocument();
    const QString end = QStringLiteral("plc/CP2");
    // Right-click the port > Bridge To > Pseudo-terminal goes through the bridge dialog too
    // when chosen from the Bridges dock's Edit; here the dialog, answered with OK.
    answerDialogs(
        [](QWidget *modal) {
            auto *dialog = qobject_cast<app::NetworkBridgeDialog *>(modal);
            if (!dialog)
                return false;
            EXPECT_TRUE(dialog->problem().isEmpty());
            dialog->accept();
            return true;
        },
        [&] { net->networkView()->editBridge(end, BridgeKind::Pty); });
    ASSERT_NE(doc->bridgeOf(end), nullptr);
    EXPECT_EQ(doc->bridgeOf(end)->kind, BridgeKind::Pty);
    EXPECT_EQ(doc->undoStack()->count(), 1);
    EXPECT_TRUE(net->bridges()->dock()->isVisibleTo(net));

    // The network is built again with the bridge; the worker opens its pseudo-terminal and the
    // dock and the view show its path.
    ASSERT_TRUE(eventually([&] { return !shownReached(net, end).isEmpty(); }))
        << shownState(net, end).toStdString();
    const QString path = shownReached(net, end);
    EXPECT_TRUE(path.startsWith(QStringLiteral("/dev/pts/"))) << path.toStdString();
    EXPECT_EQ(net->networkView()->bridgeText(end),
              QStringLiteral("bridge: pseudo-terminal %1").arg(path));
    EXPECT_TRUE(shownState(net, end).startsWith(QStringLiteral("Open")));

    // Copy puts the path on the clipboard.
    auto *copy = net->findChild<QPushButton *>(QStringLiteral("bridgeCopy_") + end);
    ASSERT_NE(copy, nullptr);
    ASSERT_TRUE(copy->isEnabled());
    QApplication::clipboard()->clear();
    copy->click();
    EXPECT_EQ(QApplication::clipboard()->text(), path);

    // Run: a real master on the path shown reads the station's D0.
    net->session()->run();
    QString error;
    EXPECT_EQ(readD0Through(path, &error), (std::vector<std::uint16_t>{321}))
        << error.toStdString();

    // And Debian's mbpoll, a real MODBUS master, on the same path (as CliNetwork's tests run it
    // against `serve`; installed by scripts/install-deps.sh).
    if (const QString mbpoll = QStandardPaths::findExecutable(QStringLiteral("mbpoll"));
        !mbpoll.isEmpty()) {
        QProcess p;
        p.start(mbpoll, {QStringLiteral("-m"), QStringLiteral("rtu"), QStringLiteral("-b"),
                         QStringLiteral("19200"), QStringLiteral("-P"), QStringLiteral("none"),
                         QStringLiteral("-a"), QStringLiteral("1"), QStringLiteral("-0"),
                         QStringLiteral("-1"), QStringLiteral("-o"), QStringLiteral("1"),
                         QStringLiteral("-t"), QStringLiteral("4"), QStringLiteral("-r"),
                         QStringLiteral("0"), QStringLiteral("-c"), QStringLiteral("1"), path});
        ASSERT_TRUE(p.waitForFinished(20000));
        const QString out = QString::fromUtf8(p.readAllStandardOutput());
        EXPECT_EQ(p.exitCode(), 0) << out.toStdString();
        const auto m = QRegularExpression(QStringLiteral(R"(\[0\]:\s+(-?\d+))")).match(out);
        ASSERT_TRUE(m.hasMatch()) << out.toStdString();
        EXPECT_EQ(m.captured(1).toInt(), 321);
    }

    // Stop builds the network again on the same pseudo-terminal: the master keeps its path.
    toolbarAction(*net, QStringLiteral("Stop"))->trigger();
    net->session()->run();
    EXPECT_EQ(readD0Through(path, &error), (std::vector<std::uint16_t>{321}))
        << error.toStdString();
    EXPECT_EQ(shownReached(net, end), path);
    EXPECT_EQ(net->bridges()->lines()->size(), 1u);

    // Saved, the file holds the bridge and all it held before; read back, the same network.
    ASSERT_TRUE(net->save());
    network::NetworkDescription read;
    ASSERT_TRUE(network::readNetworkFile(doc->filePath(), &read, &error)) << error.toStdString();
    ASSERT_EQ(read.bridges.size(), 1u);
    EXPECT_EQ(read.bridges[0].end, end);
    EXPECT_EQ(read.bridges[0].kind, BridgeKind::Pty);
    EXPECT_TRUE(network::networkDifferences(read, doc->description()).isEmpty())
        << network::networkDifferences(read, doc->description())
               .join(QLatin1Char('\n'))
               .toStdString();
    EXPECT_EQ(read.stations[0].ports, doc->description().stations[0].ports);

    // Undo takes the bridge away; its line is closed once the network is built without it.
    doc->undoStack()->undo();
    EXPECT_EQ(doc->bridgeOf(end), nullptr);
    toolbarAction(*net, QStringLiteral("Stop"))->trigger();
    EXPECT_TRUE(net->networkView()->bridgeText(end).isEmpty());
}

// A serial port that is not there: the bridge says what, where and why, in the dock and on
// the port, and the network runs on without it. The rate chosen in the bridge dialog is the
// port's, changed in the same undo step.
TEST(NetworkBridges, ASerialPortThatDoesNotOpenSaysWhatWhereAndWhy) {
    QTemporaryDir dir;
    app::MainWindow window;
    app::NetworkWindow *net = openBridgedNetwork(window, dir);
    ASSERT_NE(net, nullptr);
    app::NetworkDocument *doc = net->networkDocument();
    const QString end = QStringLiteral("plc/CP2");
    const QString missing = QStringLiteral("/dev/ttyRUNGNOSUCHPORT");
    answerDialogs(
        [&](QWidget *modal) {
            auto *dialog = qobject_cast<app::NetworkBridgeDialog *>(modal);
            if (!dialog)
                return false;
            app::LineSettingsForm *form = dialog->lineForm();
            EXPECT_TRUE(form->isVisibleTo(dialog));
            form->setPort(QString());
            EXPECT_FALSE(dialog->problem().isEmpty()) << "no port: OK is off";
            form->portBox()->setEditText(missing);
            form->baudBox()->setCurrentIndex(form->baudBox()->findData(9600));
            EXPECT_TRUE(dialog->problem().isEmpty());
            dialog->accept();
            return true;
        },
        [&] { net->networkView()->editBridge(end, BridgeKind::Serial); });
    ASSERT_NE(doc->bridgeOf(end), nullptr);
    EXPECT_EQ(doc->bridgeOf(end)->kind, BridgeKind::Serial);
    EXPECT_EQ(doc->bridgeOf(end)->where, missing);
    EXPECT_EQ(doc->description()
                  .stations[0]
                  .ports.value(QStringLiteral("CP2"))
                  .toObject()
                  .value(QStringLiteral("baud")),
              9600);
    EXPECT_EQ(doc->undoStack()->count(), 1);
    ASSERT_TRUE(eventually([&] { return !net->bridges()->error(end).isEmpty(); }));
    const QString why = net->bridges()->error(end);
    EXPECT_TRUE(why.contains(end)) << why.toStdString();
    EXPECT_TRUE(why.contains(missing)) << why.toStdString();
    EXPECT_EQ(shownState(net, end), why);
    EXPECT_TRUE(shownReached(net, end).isEmpty());
    EXPECT_TRUE(net->networkView()->bridgeText(end).contains(QStringLiteral("failed")));
    // The network runs on without the line.
    net->session()->run();
    EXPECT_TRUE(eventually([&] { return net->session()->nowUs() > 50000; }));
    // One undo: the bridge and the rate go together.
    doc->undoStack()->undo();
    EXPECT_EQ(doc->bridgeOf(end), nullptr);
    EXPECT_FALSE(doc->description()
                     .stations[0]
                     .ports.value(QStringLiteral("CP2"))
                     .toObject()
                     .contains(QStringLiteral("baud")));
}

// The bridge dialog asks with the Connection dock's form: a TCP bridge its host and port, a
// listening one the address (0.0.0.0 for all) and the port (0: any free one); a bridge made
// before is shown as it is, and changed in place.
TEST(NetworkBridges, TheDialogAsksEachKindWhatItNeeds) {
    const model::Target &vigor = *model::Target::byId(QStringLiteral("vigor"));
    model::PortConfig config;
    QString error;
    ASSERT_TRUE(model::readPortConfig(
        vigor, vigor.model(QStringLiteral("VB")), QStringLiteral("CP2"),
        {{QJsonObject{{QStringLiteral("application"), QStringLiteral("computer-link")}},
          QStringLiteral("CP2")}},
        &config, &error))
        << error.toStdString();
    network::BridgeDescription old;
    old.end = QStringLiteral("plc/CP2");
    old.kind = BridgeKind::Tcp;
    old.where = QStringLiteral("192.168.1.50:4001");
    app::NetworkBridgeDialog dialog(old, *config.application, config.line, {});
    EXPECT_EQ(dialog.lineForm()->host(), QStringLiteral("192.168.1.50"));
    EXPECT_EQ(dialog.lineForm()->tcpPort(), 4001);
    EXPECT_EQ(dialog.bridge().where, old.where);
    // Computer Link is always 7E1: the form offers only that.
    EXPECT_EQ(dialog.lineForm()->frameBox()->count(), 1);
    EXPECT_EQ(dialog.lineForm()->frameBox()->currentText(), QStringLiteral("7E1"));
    dialog.setKind(BridgeKind::Listen);
    EXPECT_EQ(dialog.lineForm()->tcpPortBox()->minimum(), 0);
    dialog.lineForm()->setHost(QStringLiteral("0.0.0.0"));
    dialog.lineForm()->setTcpPort(0);
    EXPECT_EQ(dialog.bridge().kind, BridgeKind::Listen);
    EXPECT_EQ(dialog.bridge().where, QStringLiteral("0.0.0.0:0"));
    dialog.lineForm()->setHost(QString());
    EXPECT_FALSE(dialog.problem().isEmpty());
    EXPECT_FALSE(dialog.buttons()->button(QDialogButtonBox::Ok)->isEnabled());
    dialog.setKind(BridgeKind::Pty);
    EXPECT_FALSE(dialog.lineForm()->isVisibleTo(&dialog));
    EXPECT_TRUE(dialog.problem().isEmpty());
    EXPECT_EQ(dialog.bridge().where, QString());
    EXPECT_FALSE(dialog.portSettings().has_value());
}

// Edit > Communication Ports...: a single project's port settings, the port chosen and then
// its settings as the network's port dialog has them; one undo step; kept by the project file.
TEST(ProjectPorts, EditCommunicationPortsIsOneUndoStepKeptInTheProject) {
    app::MainWindow window;
    window.newProject(*model::Target::byId(QStringLiteral("vigor")), QStringLiteral("VB"));
    QAction *ports = window.findChild<QAction *>(QStringLiteral("communicationPorts"));
    ASSERT_NE(ports, nullptr);
    EXPECT_EQ(menuAction(window, QStringLiteral("Communication Ports...")), ports);
    editor::Document *doc = window.document();
    const int steps = doc->undoStack()->count();
    answerDialogs(
        [](QWidget *modal) {
            if (auto *choose = qobject_cast<QInputDialog *>(modal)) {
                choose->setTextValue(QStringLiteral("CP2"));
                choose->accept();
                return true;
            }
            if (auto *port = qobject_cast<app::NetworkPortDialog *>(modal)) {
                port->applicationBox()->setCurrentIndex(
                    port->applicationBox()->findData(QStringLiteral("modbus")));
                port->stationBox()->setValue(4);
                port->accept();
                return true;
            }
            return false;
        },
        [&] { ports->trigger(); });
    const QJsonObject expected{
        {QStringLiteral("CP2"),
         QJsonObject{{QStringLiteral("application"), QStringLiteral("modbus")},
                     {QStringLiteral("station"), 4}}}};
    EXPECT_EQ(doc->project().ports, expected);
    EXPECT_EQ(doc->undoStack()->count(), steps + 1);
    EXPECT_TRUE(window.isModified());
    doc->undoStack()->undo();
    EXPECT_TRUE(doc->project().ports.isEmpty());
    doc->undoStack()->redo();
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("ports.rung"));
    ASSERT_TRUE(window.saveTo(file));
    model::ProjectError error;
    const std::optional<model::Project> read = model::loadProject(file, &error);
    ASSERT_TRUE(read.has_value()) << error.message.toStdString();
    EXPECT_EQ(read->ports, expected);
}

// At 1366x768 in English, Hungarian and Italian the bridge dialog and the network window with
// a live bridge show every text whole. RUNG_SCREENSHOT_DIR set: the pictures are saved there
// (docs/screenshots/network-bridge-*.png; run under Xvfb with QT_QPA_PLATFORM=xcb).
TEST(NetworkBridges, FitTheScreenInEveryLanguage) {
    const QString shots = qEnvironmentVariable("RUNG_SCREENSHOT_DIR");
    const char *bridged = R"({"stations": [{"name": "plc", "program": "s.il", "model": "VB",
        "ports": {"CP2": {"application": "modbus", "station": 1}}}],
        "bridges": [{"port": "plc/CP2", "pty": true}]})";
    for (const char *language : {"en", "hu", "it"}) {
        SCOPED_TRACE(language);
        ASSERT_TRUE(app::setLanguage(QString::fromLatin1(language), false));
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
        QTemporaryDir dir;
        const QString file = dir.filePath(QStringLiteral("plant.rungnet"));
        ASSERT_TRUE(writeText(file, bridged));
        ASSERT_TRUE(writeText(dir.filePath(QStringLiteral("s.il")), kBridgedSlave));
        app::MainWindow window;
        ASSERT_TRUE(window.openFile(file, QString(), true));
        auto *net = window.findChildren<app::NetworkWindow *>().back();
        net->resize(1366, 768);
        net->show();
        const QString end = QStringLiteral("plc/CP2");
        ASSERT_TRUE(eventually([&] { return !shownReached(net, end).isEmpty(); }));
        net->session()->run();
        QCoreApplication::processEvents();
        EXPECT_TRUE(net->bridges()->dock()->isVisible());
        for (QLabel *label : net->bridges()->dock()->findChildren<QLabel *>())
            if (label->isVisible() && !label->wordWrap()) {
                EXPECT_GE(label->width(), label->sizeHint().width()) << label->text().toStdString();
            }
        for (QPushButton *button : net->bridges()->dock()->findChildren<QPushButton *>())
            if (button->isVisible()) {
                EXPECT_GE(button->width(), button->sizeHint().width())
                    << button->text().toStdString();
            }
        const QRect port = net->networkView()->itemRect(QStringLiteral("plc"));
        EXPECT_GE(port.width(), QFontMetrics(net->networkView()->canvas()->font())
                                    .horizontalAdvance(net->networkView()->bridgeText(end)));
        if (!shots.isEmpty())
            net->grab().save(
                QStringLiteral("%1/network-bridge-%2.png").arg(shots, QLatin1String(language)));

        // The dialog on a serial bridge, and on a listening one.
        const model::Target &vigor = *model::Target::byId(QStringLiteral("vigor"));
        model::PortConfig config;
        QString error;
        ASSERT_TRUE(model::readPortConfig(
            vigor, vigor.model(QStringLiteral("VB")), QStringLiteral("CP2"),
            {{QJsonObject{{QStringLiteral("application"), QStringLiteral("modbus")}}, end}},
            &config, &error));
        network::BridgeDescription serial;
        serial.end = end;
        serial.kind = BridgeKind::Serial;
        serial.where = QStringLiteral("/dev/ttyUSB0");
        app::NetworkBridgeDialog dialog(serial, *config.application, config.line, {});
        for (const BridgeKind kind : {BridgeKind::Listen, BridgeKind::Serial}) {
            dialog.setKind(kind);
            dialog.show();
            dialog.adjustSize();
            QCoreApplication::processEvents();
            EXPECT_LE(dialog.width(), 1366);
            EXPECT_LE(dialog.height(), 768);
            for (QWidget *w : dialog.findChildren<QWidget *>()) {
                auto *label = qobject_cast<QLabel *>(w);
                auto *radio = qobject_cast<QAbstractButton *>(w);
                if (!w->isVisible() || (label && label->wordWrap()) || (!label && !radio))
                    continue;
                EXPECT_GE(w->width(), w->sizeHint().width())
                    << (label ? label->text() : radio->text()).toStdString();
            }
        }
        if (!shots.isEmpty())
            dialog.grab().save(QStringLiteral("%1/network-bridge-dialog-%2.png")
                                   .arg(shots, QLatin1String(language)));
    }
    app::setLanguage(QStringLiteral("en"), false);
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
}

} // namespace
} // namespace rung::test
