// The Network view and its document (issue 30): the examples open, every edit undoes and
// redoes to the exact network, saves round-trip through real files, the port dialog offers
// the target's tables, and the view draws, selects, wires and fits the screen in every
// language.

#include "answer_dialogs.h"

#include "app/gui/language.h"
#include "app/gui/network_document.h"
#include "app/gui/network_port_dialog.h"
#include "app/gui/network_station_dialog.h"
#include "app/gui/network_view.h"

#include "model/target/target.h"

#include <QApplication>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QGroupBox>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QMouseEvent>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <gtest/gtest.h>

#include <functional>
#include <optional>

namespace rung::app {
namespace {

using network::BridgeDescription;
using network::NetworkDescription;

const QString kNetExamples = QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/networks");

QStringList netExampleFiles() {
    QStringList out;
    QDirIterator it(kNetExamples, {QStringLiteral("*.rungnet")}, QDir::Files,
                    QDirIterator::Subdirectories);
    while (it.hasNext())
        out << it.next();
    out.sort();
    return out;
}

// An example's folder copied into `dir`, so that edits and saves touch real files of the test.
QString copyNetExample(const QTemporaryDir &dir, const QString &name) {
    const QString to = dir.filePath(name);
    QDir().mkpath(to);
    QDirIterator it(kNetExamples + QLatin1Char('/') + name, QDir::Files);
    while (it.hasNext()) {
        const QString from = it.next();
        QFile::copy(from, to + QLatin1Char('/') + QFileInfo(from).fileName());
    }
    return to + QLatin1Char('/') + name + QStringLiteral(".rungnet");
}

// One user action: one undo step; undo gives the network before it exactly, redo after it.
void expectOneStep(NetworkDocument &doc, const char *what,
                   const std::function<bool(QString *)> &edit) {
    SCOPED_TRACE(what);
    const NetworkDescription before = doc.description();
    const int steps = doc.undoStack()->count();
    QString why;
    ASSERT_TRUE(edit(&why)) << why.toStdString();
    const NetworkDescription after = doc.description();
    EXPECT_FALSE(after == before);
    ASSERT_EQ(doc.undoStack()->count(), steps + 1);
    EXPECT_FALSE(doc.undoStack()->text(steps).isEmpty());
    EXPECT_TRUE(doc.isModified());
    doc.undoStack()->undo();
    EXPECT_TRUE(doc.description() == before);
    doc.undoStack()->redo();
    EXPECT_TRUE(doc.description() == after);
}

TEST(NetworkDocument, EveryExampleOpensAsTheFileReads) {
    for (const QString &file : netExampleFiles()) {
        SCOPED_TRACE(file.toStdString());
        NetworkDocument doc;
        QString error;
        ASSERT_TRUE(doc.open(file, &error)) << error.toStdString();
        NetworkDescription read;
        ASSERT_TRUE(network::readNetworkFile(file, &read, &error));
        EXPECT_TRUE(doc.description() == read);
        EXPECT_FALSE(doc.isModified());
        NetworkView view(&doc);
        view.resize(1366, 768);
        if (const QString shots = qEnvironmentVariable("RUNG_SCREENSHOT_DIR"); !shots.isEmpty())
            view.grab().save(shots + QStringLiteral("/all-") + QFileInfo(file).baseName() +
                             QStringLiteral(".png"));
        for (const auto &s : read.stations) {
            EXPECT_TRUE(doc.stationInfo(s.name).problem.isEmpty()) << s.name.toStdString();
            EXPECT_FALSE(view.itemRect(s.name).isEmpty()) << s.name.toStdString();
        }
        for (const auto &v : read.devices)
            EXPECT_FALSE(view.itemRect(v.name).isEmpty()) << v.name.toStdString();
        // Every end of every wire is drawn, and found where it is drawn.
        for (const auto &w : read.wires)
            for (const QString &end : w.ends) {
                const QPoint at = view.endPoint(end);
                ASSERT_GE(at.x(), 0) << end.toStdString();
                EXPECT_EQ(view.itemAt(at), end);
            }
    }
}

TEST(NetworkDocument, EveryEditIsOneStepThatUndoesAndRedoesExactly) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString file = copyNetExample(dir, QStringLiteral("modbus"));
    NetworkDocument doc;
    QString error;
    ASSERT_TRUE(doc.open(file, &error)) << error.toStdString();
    const QString folder = QFileInfo(file).absolutePath();

    expectOneStep(doc, "add an existing program", [&](QString *why) {
        return doc.addExistingProgram(QStringLiteral("s3"), folder + QStringLiteral("/slave.il"),
                                      QStringLiteral("vigor"), QStringLiteral("VB"), why);
    });
    EXPECT_EQ(doc.station(QStringLiteral("s3"))->program, QStringLiteral("slave.il"));
    expectOneStep(doc, "add a new project", [&](QString *why) {
        return doc.addNewProject(QStringLiteral("pl"), folder + QStringLiteral("/pl.rung"),
                                 QStringLiteral("pl110"), QStringLiteral("PL110-1A"), why);
    });
    EXPECT_TRUE(QFileInfo::exists(folder + QStringLiteral("/pl.rung")));
    EXPECT_EQ(doc.stationInfo(QStringLiteral("pl")).target->id, QStringLiteral("pl110"));
    expectOneStep(doc, "put an end on a wire", [&](QString *why) {
        return doc.connectEnds(QStringLiteral("master/CP2"), QStringLiteral("s3/CP2"), why);
    });
    EXPECT_EQ(doc.description().wires.size(), 1u);
    EXPECT_EQ(doc.description().wires[0].ends.size(), 4);
    expectOneStep(doc, "a new wire", [&](QString *why) {
        return doc.connectEnds(QStringLiteral("pl/COM1"), QStringLiteral("s1/CP1"), why);
    });
    EXPECT_EQ(doc.description().wires.size(), 2u);
    expectOneStep(doc, "disconnect",
                  [&](QString *why) { return doc.disconnectEnd(QStringLiteral("s3/CP2"), why); });
    expectOneStep(doc, "remove a wire",
                  [&](QString *why) { return doc.removeWire(QStringLiteral("w2"), why); });
    expectOneStep(doc, "edit a port", [&](QString *why) {
        return doc.setPortSettings(
            QStringLiteral("s2"), QStringLiteral("CP2"),
            QJsonObject{{QStringLiteral("application"), QStringLiteral("modbus")},
                        {QStringLiteral("station"), 7},
                        {QStringLiteral("baud"), 9600}},
            why);
    });
    EXPECT_EQ(doc.station(QStringLiteral("s2"))
                  ->ports.value(QStringLiteral("CP2"))
                  .toObject()
                  .value(QStringLiteral("station"))
                  .toInt(),
              7);
    for (const auto &[kind, where] : std::vector<std::pair<BridgeDescription::Kind, QString>>{
             {BridgeDescription::Kind::Pty, {}},
             {BridgeDescription::Kind::Serial, QStringLiteral("/dev/ttyUSB0")},
             {BridgeDescription::Kind::Tcp, QStringLiteral("192.168.1.50:4001")},
             {BridgeDescription::Kind::Listen, QStringLiteral("0.0.0.0:5020")}}) {
        BridgeDescription b;
        b.end = QStringLiteral("s1/CP2");
        b.kind = kind;
        b.where = where;
        expectOneStep(doc, "add a bridge", [&](QString *why) { return doc.addBridge(b, why); });
        expectOneStep(doc, "remove a bridge", [&](QString *why) {
            return doc.removeBridge(QStringLiteral("s1/CP2"), why);
        });
    }
    expectOneStep(doc, "the period", [&](QString *why) { return doc.setPeriod(25, why); });
    expectOneStep(doc, "remove a station",
                  [&](QString *why) { return doc.removeStation(QStringLiteral("master"), why); });
    EXPECT_EQ(doc.description().wires[0].ends,
              (QStringList{QStringLiteral("s1/CP2"), QStringLiteral("s2/CP2")}));

    // Undo all the way: the network as the file has it, unmodified.
    NetworkDescription read;
    ASSERT_TRUE(network::readNetworkFile(file, &read, &error));
    while (doc.undoStack()->canUndo())
        doc.undoStack()->undo();
    EXPECT_TRUE(doc.description() == read);
    EXPECT_FALSE(doc.isModified());
}

TEST(NetworkDocument, EditsThatTheTablesRefuseSayWhyAndChangeNothing) {
    NetworkDocument doc;
    QString error;
    ASSERT_TRUE(doc.open(kNetExamples + QStringLiteral("/cpu-link/cpu-link.rungnet"), &error));
    const NetworkDescription before = doc.description();
    QString why;
    // B-3-4: CPU Link stations are 0..7.
    EXPECT_FALSE(
        doc.setPortSettings(QStringLiteral("slave1"), QStringLiteral("CP2"),
                            QJsonObject{{QStringLiteral("application"), QStringLiteral("cpu-link")},
                                        {QStringLiteral("station"), 9}},
                            &why));
    EXPECT_TRUE(why.contains(QStringLiteral("station"))) << why.toStdString();
    // CPU Link publishes no frames: no bridge.
    BridgeDescription b;
    b.end = QStringLiteral("slave1/CP2");
    EXPECT_FALSE(doc.addBridge(b, &why));
    EXPECT_TRUE(why.contains(QStringLiteral("CPU Link"))) << why.toStdString();
    b.end = QStringLiteral("slave1/CP9");
    EXPECT_FALSE(doc.addBridge(b, &why));
    EXPECT_TRUE(why.contains(QStringLiteral("CP9"))) << why.toStdString();
    EXPECT_FALSE(doc.connectEnds(QStringLiteral("master/CP2"), QStringLiteral("slave2/CP2"), &why));
    EXPECT_FALSE(doc.addExistingProgram(QStringLiteral("master"),
                                        kNetExamples + QStringLiteral("/cpu-link/master.il"), {},
                                        {}, &why));
    EXPECT_TRUE(why.contains(QStringLiteral("master")));
    EXPECT_FALSE(doc.addNewProject(QStringLiteral("x"),
                                   kNetExamples + QStringLiteral("/cpu-link/master.il"),
                                   QStringLiteral("vigor"), QStringLiteral("VB"), &why));
    EXPECT_TRUE(why.contains(QStringLiteral("exists"))) << why.toStdString();
    EXPECT_FALSE(doc.setPeriod(0, &why));
    EXPECT_TRUE(doc.description() == before);
    EXPECT_EQ(doc.undoStack()->count(), 0);
}

TEST(NetworkDocument, RemovingAStationSaysWhatGoesWithIt) {
    NetworkDocument doc;
    QString error;
    ASSERT_TRUE(
        doc.open(kNetExamples + QStringLiteral("/pl110-vigor/pl110-vigor.rungnet"), &error));
    BridgeDescription b;
    b.end = QStringLiteral("vb/CP2");
    b.kind = BridgeDescription::Kind::Listen;
    b.where = QStringLiteral("0.0.0.0:5020");
    ASSERT_TRUE(doc.addBridge(b, &error)) << error.toStdString();
    const QStringList also = doc.removalConsequences(QStringLiteral("vb"));
    ASSERT_EQ(also.size(), 2) << also.join(QLatin1Char('\n')).toStdString();
    EXPECT_EQ(also[0],
              QStringLiteral("wire rs485 (pl/COM1, vb/CP2) goes: fewer than two ends are left"));
    EXPECT_EQ(also[1], QStringLiteral("the bridge of vb/CP2 (TCP listener) goes"));
    ASSERT_TRUE(doc.removeStation(QStringLiteral("vb"), &error));
    EXPECT_TRUE(doc.description().wires.empty());
    EXPECT_TRUE(doc.description().bridges.empty());

    // On a bus of three, the station's end comes off and the wire stays.
    ASSERT_TRUE(doc.open(kNetExamples + QStringLiteral("/easy-link/easy-link.rungnet"), &error));
    EXPECT_EQ(doc.removalConsequences(QStringLiteral("s5")),
              QStringList{QStringLiteral("s5/CP2 comes off wire w1")});
    EXPECT_TRUE(doc.removalConsequences(QStringLiteral("nobody")).isEmpty());
}

TEST(NetworkDocument, SaveAndSaveAsRoundTripThroughRealFiles) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString file = copyNetExample(dir, QStringLiteral("pl110-vigor"));
    NetworkDocument doc;
    QString error;
    QStringList notKept;
    ASSERT_TRUE(doc.open(file, &error)) << error.toStdString();
    QSignalSpy modified(&doc, &NetworkDocument::modifiedChanged);
    ASSERT_TRUE(doc.setPortSettings(
        QStringLiteral("pl"), QStringLiteral("COM1"),
        QJsonObject{{QStringLiteral("application"), QStringLiteral("modbus-master")},
                    {QStringLiteral("baud"), 9600}},
        &error))
        << error.toStdString();
    ASSERT_TRUE(doc.setPeriod(20, &error));
    EXPECT_TRUE(doc.isModified());
    ASSERT_TRUE(saveNetwork(nullptr, &doc)); // File > Save: nothing to ask
    EXPECT_FALSE(doc.isModified());
    EXPECT_EQ(modified.count(), 2); // on, then off

    NetworkDocument again;
    ASSERT_TRUE(again.open(file, &error)) << error.toStdString();
    EXPECT_TRUE(again.description() == doc.description());
    // The comment the user wrote is still there.
    EXPECT_TRUE(again.description().comment.toString().startsWith(QStringLiteral("A PL110")));

    // Save As into another folder: the programs stay where they are.
    const QString elsewhere = dir.filePath(QStringLiteral("other/net.rungnet"));
    ASSERT_TRUE(QDir().mkpath(dir.filePath(QStringLiteral("other"))));
    ASSERT_TRUE(doc.saveAs(elsewhere, &notKept, &error)) << error.toStdString();
    EXPECT_EQ(doc.filePath(), elsewhere);
    EXPECT_EQ(doc.station(QStringLiteral("pl"))->program, QStringLiteral("../pl110-vigor/pl.il"));
    NetworkDocument third;
    ASSERT_TRUE(third.open(elsewhere, &error)) << error.toStdString();
    EXPECT_TRUE(network::networkDifferences(third.description(), again.description()).isEmpty());
    EXPECT_TRUE(third.stationInfo(QStringLiteral("pl")).problem.isEmpty());

    // Undo after a save: modified again, and the file unchanged until the next save.
    doc.undoStack()->undo();
    EXPECT_TRUE(doc.isModified());

    // A new network saved for the first time.
    NetworkDocument fresh;
    fresh.newNetwork();
    EXPECT_FALSE(fresh.save(&notKept, &error));
    ASSERT_TRUE(fresh.addExistingProgram(QStringLiteral("vb"),
                                         QFileInfo(file).absolutePath() + QStringLiteral("/vb.il"),
                                         {}, {}, &error))
        << error.toStdString();
    const QString firstSave = dir.filePath(QStringLiteral("fresh.rungnet"));
    ASSERT_TRUE(fresh.saveAs(firstSave, &notKept, &error)) << error.toStdString();
    EXPECT_EQ(fresh.station(QStringLiteral("vb"))->program, QStringLiteral("pl110-vigor/vb.il"));
}

TEST(NetworkView, DraggingFromPortToPortMakesAWireAndDeleteTakesItOff) {
    NetworkDocument doc;
    QString error;
    ASSERT_TRUE(doc.open(kNetExamples + QStringLiteral("/easy-link/easy-link.rungnet"), &error));
    NetworkView view(&doc);
    view.setQuiet(true);
    QSignalSpy refused(&view, &NetworkView::editRefused);
    view.resize(1366, 768);
    view.show();
    QWidget *canvas = view.canvas();
    const QPoint from = view.endPoint(QStringLiteral("master/CP1"));
    const QPoint to = view.endPoint(QStringLiteral("s5/CP1"));
    ASSERT_GE(from.x(), 0);
    ASSERT_GE(to.x(), 0);
    QTest::mousePress(canvas, Qt::LeftButton, {}, from);
    QMouseEvent move(QEvent::MouseMove, QPointF(to), canvas->mapToGlobal(QPointF(to)), Qt::NoButton,
                     Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(canvas, &move);
    QTest::mouseRelease(canvas, Qt::LeftButton, {}, to);
    ASSERT_EQ(doc.description().wires.size(), 2u) << refused.count();
    EXPECT_EQ(doc.description().wires[1].ends,
              (QStringList{QStringLiteral("master/CP1"), QStringLiteral("s5/CP1")}));
    EXPECT_EQ(doc.undoStack()->count(), 1);

    // The port selected, Delete takes it off its wire (the wire goes: one end left).
    QTest::mouseClick(canvas, Qt::LeftButton, {}, view.endPoint(QStringLiteral("s5/CP1")));
    EXPECT_EQ(view.selection(), QStringLiteral("s5/CP1"));
    QTest::keyClick(&view, Qt::Key_Delete);
    EXPECT_EQ(doc.description().wires.size(), 1u);
    EXPECT_EQ(doc.undoStack()->count(), 2);

    // A drag the network refuses (a port onto another end of its own wire) says why.
    const QPoint master = view.endPoint(QStringLiteral("master/CP2"));
    const QPoint s2 = view.endPoint(QStringLiteral("s2/CP2"));
    QTest::mousePress(canvas, Qt::LeftButton, {}, master);
    QMouseEvent again(QEvent::MouseMove, QPointF(s2), canvas->mapToGlobal(QPointF(s2)),
                      Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(canvas, &again);
    QTest::mouseRelease(canvas, Qt::LeftButton, {}, s2);
    ASSERT_EQ(refused.count(), 1);
    EXPECT_TRUE(refused.at(0).at(0).toString().contains(QStringLiteral("w1")));
    EXPECT_EQ(doc.undoStack()->count(), 2);
}

TEST(NetworkView, SelectingAndDoubleClickingAStationSayWhich) {
    NetworkDocument doc;
    QString error;
    ASSERT_TRUE(doc.open(kNetExamples + QStringLiteral("/cpu-link/cpu-link.rungnet"), &error));
    NetworkView view(&doc);
    view.resize(1366, 768);
    view.show();
    QSignalSpy selected(&view, &NetworkView::stationSelected);
    QSignalSpy activated(&view, &NetworkView::stationActivated);
    const QRect box = view.itemRect(QStringLiteral("slave1"));
    const QPoint head = box.topLeft() + QPoint(box.width() / 2, 6);
    QTest::mouseClick(view.canvas(), Qt::LeftButton, {}, head);
    ASSERT_EQ(selected.count(), 1);
    EXPECT_EQ(selected.at(0).at(0).toString(), QStringLiteral("slave1"));
    QTest::mouseDClick(view.canvas(), Qt::LeftButton, {}, head);
    ASSERT_EQ(activated.count(), 1);
    EXPECT_EQ(activated.at(0).at(0).toString(), QStringLiteral("slave1"));
    QTest::keyClick(&view, Qt::Key_Return);
    EXPECT_EQ(activated.count(), 2);

    // Zoom: twice as large, and Ctrl+0 back.
    const QRect before = view.itemRect(QStringLiteral("master"));
    view.setZoom(2.0);
    EXPECT_NEAR(view.itemRect(QStringLiteral("master")).width(), 2 * before.width(), 2);
    QTest::keyClick(&view, Qt::Key_0, Qt::ControlModifier);
    EXPECT_DOUBLE_EQ(view.zoom(), 1.0);

    // A station removed by undoing its addition leaves no selection behind.
    ASSERT_TRUE(doc.addExistingProgram(QStringLiteral("extra"),
                                       kNetExamples + QStringLiteral("/cpu-link/slave1.il"), {}, {},
                                       &error));
    view.select(QStringLiteral("extra"));
    doc.undoStack()->undo();
    EXPECT_TRUE(view.selection().isEmpty());
}

TEST(NetworkView, FitsTheScreenInEveryLanguage) {
    // At 1366 x 768 the two examples the user guide shows are drawn whole, in English,
    // Hungarian and Italian: no box's text wider than its box, nothing past the screen.
    // RUNG_SCREENSHOT_DIR set: the pictures are saved there (docs/screenshots/).
    const QString shots = qEnvironmentVariable("RUNG_SCREENSHOT_DIR");
    for (const char *language : {"en", "hu", "it"}) {
        ASSERT_TRUE(setLanguage(QString::fromLatin1(language), false));
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
        for (const char *example : {"cpu-link", "pl110-vigor"}) {
            SCOPED_TRACE(std::string(language) + " " + example);
            NetworkDocument doc;
            QString error;
            ASSERT_TRUE(doc.open(kNetExamples +
                                     QStringLiteral("/%1/%1.rungnet").arg(QLatin1String(example)),
                                 &error));
            NetworkView view(&doc);
            view.resize(1366, 768);
            view.show();
            QCoreApplication::processEvents();
            EXPECT_LE(view.canvas()->width(), view.viewport()->width());
            EXPECT_LE(view.canvas()->height(), view.viewport()->height());
            for (const auto &s : doc.description().stations) {
                const QRect box = view.itemRect(s.name);
                EXPECT_TRUE(view.canvas()->rect().contains(box)) << s.name.toStdString();
            }
            if (!shots.isEmpty())
                view.grab().save(QStringLiteral("%1/network-%2-%3.png")
                                     .arg(shots, QLatin1String(example), QLatin1String(language)));
        }
        // The port dialog with CPU Link's panel and with the PL110's longest protocol name:
        // every label, combo box and group title as wide as its text needs.
        const model::Target &vigor = *model::Target::byId(QStringLiteral("vigor"));
        const model::Target &pl = *model::Target::byId(QStringLiteral("pl110"));
        const QJsonObject cpu{{QStringLiteral("application"), QStringLiteral("cpu-link")},
                              {QStringLiteral("slaves"), 2}};
        const QJsonObject nais{{QStringLiteral("application"), QStringLiteral("nais-master")}};
        NetworkPortDialog vigorDialog(vigor, QStringLiteral("VB"), QStringLiteral("CP2"), cpu, {},
                                      QStringLiteral("master/CP2"));
        NetworkPortDialog plDialog(pl, QStringLiteral("PL110-1A"), QStringLiteral("COM1"), nais, {},
                                   QStringLiteral("pl/COM1"));
        for (NetworkPortDialog *dialog : {&vigorDialog, &plDialog}) {
            dialog->show();
            QCoreApplication::processEvents();
            for (QLabel *label : dialog->findChildren<QLabel *>()) {
                if (label->isVisible() && !label->wordWrap()) {
                    EXPECT_GE(label->width(), label->sizeHint().width())
                        << language << " " << label->text().toStdString();
                }
            }
            for (QComboBox *box : dialog->findChildren<QComboBox *>()) {
                if (box->isVisible()) {
                    EXPECT_GE(box->width(), box->sizeHint().width())
                        << language << " " << box->currentText().toStdString();
                }
            }
            EXPECT_LE(dialog->width(), 1366);
            EXPECT_LE(dialog->height(), 768);
            if (!shots.isEmpty())
                dialog->grab().save(QStringLiteral("%1/network-port-%2-%3.png")
                                        .arg(shots,
                                             dialog == &plDialog ? QStringLiteral("pl110")
                                                                 : QStringLiteral("vigor"),
                                             QLatin1String(language)));
        }
    }
    setLanguage(QStringLiteral("en"), false);
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
}

TEST(NetworkPortDialog, OffersTheTargetsChoicesAndDefaults) {
    const model::Target &vigor = *model::Target::byId(QStringLiteral("vigor"));
    const model::PortSpec &cp2 = *vigor.port(QStringLiteral("CP2"));
    NetworkPortDialog dialog(vigor, QStringLiteral("VB"), QStringLiteral("CP2"), {}, {},
                             QStringLiteral("master/CP2"));
    // Every application the VB's CP2 has (B-3-1's "2nd COM Port Setting"), the first default.
    int onVb = 0;
    for (const auto &a : cp2.applications)
        onVb += model::applicationOn(a, QStringLiteral("VB")) ? 1 : 0;
    EXPECT_EQ(dialog.applicationBox()->count(), onVb);
    EXPECT_TRUE(dialog.applicationBox()->itemText(0).contains(QStringLiteral("(default)")));
    EXPECT_TRUE(dialog.settings().isEmpty()); // nothing set: nothing written
    EXPECT_TRUE(dialog.problem().isEmpty());

    // CPU Link: 38400 only, stations 0..7, the master's panel with B-3-4's ranges.
    dialog.applicationBox()->setCurrentIndex(
        dialog.applicationBox()->findData(QStringLiteral("cpu-link")));
    const model::PortApplication &cpu = *cp2.application(u"cpu-link");
    ASSERT_EQ(dialog.baudBox()->count(), int(cpu.bauds.size()));
    EXPECT_EQ(dialog.baudBox()->itemData(0).toInt(), 38400);
    EXPECT_EQ(dialog.stationBox()->minimum(), cpu.stationMin);
    EXPECT_EQ(dialog.stationBox()->maximum(), cpu.stationMax);
    EXPECT_FALSE(dialog.cpuLinkGroup()->isHidden());
    EXPECT_TRUE(dialog.modbusGroup()->isHidden());
    EXPECT_EQ(dialog.slavesBox()->minimum(), 1);
    EXPECT_EQ(dialog.slavesBox()->maximum(), 7);
    EXPECT_EQ(dialog.rangeBox()->maximum(), 3);
    dialog.slavesBox()->setValue(2);
    EXPECT_EQ(dialog.settings(),
              (QJsonObject{{QStringLiteral("application"), QStringLiteral("cpu-link")},
                           {QStringLiteral("slaves"), 2}}));

    // Keys the user wrote stay, even at their defaults.
    const QJsonObject written{{QStringLiteral("application"), QStringLiteral("modbus")},
                              {QStringLiteral("station"), 1},
                              {QStringLiteral("mode"), QStringLiteral("rtu")},
                              {QStringLiteral("frame"), QStringLiteral("8N1")}};
    NetworkPortDialog kept(vigor, QStringLiteral("VB"), QStringLiteral("CP2"), written, {}, {});
    EXPECT_EQ(kept.settings(), written);
    EXPECT_FALSE(kept.modbusGroup()->isHidden());

    // Out of range: shown, refused with the reason, OK off.
    NetworkPortDialog wrong(vigor, QStringLiteral("VB"), QStringLiteral("CP2"),
                            QJsonObject{{QStringLiteral("application"), QStringLiteral("modbus")},
                                        {QStringLiteral("station"), 300}},
                            {}, {});
    EXPECT_EQ(wrong.stationBox()->value(), 300);
    EXPECT_TRUE(wrong.problem().contains(QStringLiteral("station")))
        << wrong.problem().toStdString();
    EXPECT_FALSE(wrong.buttons()->button(QDialogButtonBox::Ok)->isEnabled());
    wrong.stationBox()->setValue(5);
    EXPECT_TRUE(wrong.problem().isEmpty());
    EXPECT_TRUE(wrong.buttons()->button(QDialogButtonBox::Ok)->isEnabled());
}

TEST(NetworkPortDialog, OffersThePl110sProtocolsPortByPort) {
    const model::Target &pl = *model::Target::byId(QStringLiteral("pl110"));
    for (const char *name : {"COM1", "EXP1", "COM2"}) {
        SCOPED_TRACE(name);
        const model::PortSpec &spec = *pl.port(QString::fromLatin1(name));
        NetworkPortDialog dialog(pl, QStringLiteral("PL110-1A"), QLatin1String(name), {}, {}, {});
        ASSERT_EQ(dialog.applicationBox()->count(), int(spec.applications.size()));
        for (int i = 0; i < dialog.applicationBox()->count(); ++i)
            EXPECT_EQ(dialog.applicationBox()->itemData(i).toString(),
                      QLatin1String(spec.applications[std::size_t(i)].id));
        EXPECT_EQ(dialog.baudBox()->itemData(0).toInt(), spec.applications.front().bauds.front());
    }
    // A project's settings under the network's: their values are the defaults shown.
    NetworkPortDialog layered(
        pl, QStringLiteral("PL110-1A"), QStringLiteral("COM1"), {},
        QJsonObject{{QStringLiteral("application"), QStringLiteral("modbus-master")},
                    {QStringLiteral("baud"), 9600}},
        {});
    EXPECT_EQ(layered.applicationBox()->currentData().toString(), QStringLiteral("modbus-master"));
    EXPECT_EQ(layered.baudBox()->currentData().toInt(), 9600);
    EXPECT_TRUE(layered.baudBox()->currentText().contains(QStringLiteral("(default)")));
    EXPECT_TRUE(layered.settings().isEmpty());
}

using test::answerDialogs;

TEST(NetworkView, DeleteOnAStationAsksWhatGoesWithIt) {
    NetworkDocument doc;
    QString error;
    ASSERT_TRUE(
        doc.open(kNetExamples + QStringLiteral("/pl110-vigor/pl110-vigor.rungnet"), &error));
    NetworkView view(&doc);
    view.resize(1366, 768);
    view.show();
    view.select(QStringLiteral("vb"));
    QString asked;
    const auto press = [&asked](QMessageBox::StandardButton which) {
        return [&asked, which](QWidget *modal) {
            auto *box = qobject_cast<QMessageBox *>(modal);
            if (!box)
                return false;
            asked = box->text();
            box->button(which)->click();
            return true;
        };
    };
    answerDialogs(press(QMessageBox::Cancel), [&] { QTest::keyClick(&view, Qt::Key_Delete); });
    EXPECT_TRUE(asked.contains(QStringLiteral("wire rs485 (pl/COM1, vb/CP2) goes")))
        << asked.toStdString();
    EXPECT_NE(doc.station(QStringLiteral("vb")), nullptr);
    EXPECT_EQ(doc.undoStack()->count(), 0);
    answerDialogs(press(QMessageBox::Yes), [&] { QTest::keyClick(&view, Qt::Key_Delete); });
    EXPECT_EQ(doc.station(QStringLiteral("vb")), nullptr);
    EXPECT_TRUE(doc.description().wires.empty());
    EXPECT_EQ(doc.undoStack()->count(), 1);
}

TEST(NetworkPortDialog, EditsASingleProjectsPorts) {
    // A project's "ports" (no network): the port chosen, then its settings; the other ports
    // stay as they were.
    const model::Target &vigor = *model::Target::byId(QStringLiteral("vigor"));
    const QJsonObject ports{{QStringLiteral("CP1"), QJsonObject{{QStringLiteral("station"), 0}}}};
    std::optional<QJsonObject> edited;
    answerDialogs(
        [](QWidget *modal) {
            if (auto *choose = qobject_cast<QInputDialog *>(modal)) {
                choose->setTextValue(QStringLiteral("CP2"));
                choose->accept();
                return true;
            }
            if (auto *port = qobject_cast<NetworkPortDialog *>(modal)) {
                port->applicationBox()->setCurrentIndex(
                    port->applicationBox()->findData(QStringLiteral("modbus")));
                port->stationBox()->setValue(4);
                port->accept();
                return true;
            }
            return false;
        },
        [&] { edited = editProjectPorts(nullptr, vigor, QStringLiteral("VB"), ports); });
    ASSERT_TRUE(edited.has_value());
    EXPECT_EQ(*edited,
              (QJsonObject{{QStringLiteral("CP1"), QJsonObject{{QStringLiteral("station"), 0}}},
                           {QStringLiteral("CP2"),
                            QJsonObject{{QStringLiteral("application"), QStringLiteral("modbus")},
                                        {QStringLiteral("station"), 4}}}}));
}

TEST(NetworkStationDialog, NeverOverwritesAFile) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString file = copyNetExample(dir, QStringLiteral("cpu-link"));
    NetworkDocument doc;
    QString error;
    ASSERT_TRUE(doc.open(file, &error));
    NetworkStationDialog dialog(&doc);
    EXPECT_EQ(dialog.name(), QStringLiteral("plc"));
    EXPECT_EQ(dialog.file(), QFileInfo(file).absolutePath() + QStringLiteral("/plc.rung"));
    EXPECT_TRUE(dialog.buttons()->button(QDialogButtonBox::Ok)->isEnabled());
    dialog.nameEdit()->setText(QStringLiteral("master"));
    EXPECT_FALSE(dialog.buttons()->button(QDialogButtonBox::Ok)->isEnabled());
    dialog.nameEdit()->setText(QStringLiteral("slave1"));
    EXPECT_FALSE(dialog.buttons()->button(QDialogButtonBox::Ok)->isEnabled()); // a station's name
    dialog.nameEdit()->setText(QStringLiteral("newone"));
    dialog.fileEdit()->setText(QFileInfo(file).absolutePath() + QStringLiteral("/master.il"));
    emit dialog.fileEdit()->textEdited(dialog.fileEdit()->text());
    EXPECT_FALSE(dialog.buttons()->button(QDialogButtonBox::Ok)->isEnabled());
    EXPECT_TRUE(dialog.problemLabel()->text().contains(QStringLiteral("master.il")));
}

// A network's description wraps to the view's width: in the network window beside its docks
// (about 640 px at 1366 x 768) the cpm1-host-link example's text was cut at 700 px, read
// only by scrolling sideways; it reads whole now, and wraps anew when the view is widened.
TEST(NetworkView, TheDescriptionWrapsToTheViewsWidth) {
    NetworkDocument doc;
    QString error;
    ASSERT_TRUE(
        doc.open(kNetExamples + QStringLiteral("/cpm1-host-link/cpm1-host-link.rungnet"), &error))
        << error.toStdString();
    ASSERT_TRUE(doc.description().comment.isString());
    NetworkView view(&doc);
    view.resize(640, 500);
    view.show();
    QCoreApplication::processEvents();
    EXPECT_LE(view.canvas()->width(), view.viewport()->width());
    const int narrowHeight = view.canvas()->height();
    view.resize(1300, 500);
    QCoreApplication::processEvents();
    EXPECT_LE(view.canvas()->width(), view.viewport()->width());
    EXPECT_LT(view.canvas()->height(), narrowHeight); // fewer lines of description
}

} // namespace
} // namespace rung::app
