// The Traffic view of a network (app/gui/network_traffic_view.h) over a real run: the modbus
// example of the Vigor M/VB/VH communication manual (B-3-6) built with the loader the
// command-line tool uses, its traffic decoded in the table; the model under Qt's model tester
// with batches and its cap; the filters; the frame chosen for the timing chart's cursor; CSV
// and text saved to real files and read back.

#include "app/cli/cli_network.h"
#include "app/gui/language.h"
#include "app/gui/network_traffic_model.h"
#include "app/gui/network_traffic_view.h"
#include "comms/transport/pty_transport.h"
#include "network/bridge.h"
#include "network/traffic.h"
#include "network/traffic_decode.h"

#include "tests/editor/model_tester.h"
#include "tests/eventually.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFile>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QSignalSpy>
#include <QTableView>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace rung;
using app::NetworkTrafficModel;
using app::NetworkTrafficView;

namespace {

const QString kExamples = QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/networks/");

// A network of the examples, built as `rungstudio-cli simulate` builds it, run for `ms` of
// virtual time with its traffic recorded (and a fault added when given).
struct TrafficRun {
    std::unique_ptr<network::Network> net;
    std::vector<network::TrafficRecord> records;
    QString error;
};

TrafficRun runExample(const QString &file, qint64 ms,
                      std::optional<network::FaultDescription> fault = {}) {
    TrafficRun run;
    network::NetworkDescription d;
    if (!network::readNetworkFile(kExamples + file, &d, &run.error))
        return run;
    if (fault)
        d.faults.push_back(*fault);
    run.net = network::Network::build(d, app::cliProgramLoader(), &run.error);
    if (!run.net)
        return run;
    run.net->setTrafficSink(
        [records = &run.records](const network::TrafficRecord &r) { records->push_back(r); });
    run.net->runUntil(ms * 1000);
    return run;
}

QString readBack(const QString &path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly | QIODevice::Text) ? QString::fromUtf8(f.readAll())
                                                         : QString();
}

int columnOf(const QString &title) {
    for (int c = 0; c < NetworkTrafficModel::ColumnCount; ++c) {
        NetworkTrafficModel model;
        if (model.headerData(c, Qt::Horizontal).toString() == title)
            return c;
    }
    return -1;
}

} // namespace

TEST(NetworkTrafficModel, BatchesAndItsCapPassTheModelTester) {
    TrafficRun run = runExample(QStringLiteral("modbus/modbus.rungnet"), 2000);
    ASSERT_TRUE(run.net) << run.error.toStdString();
    ASSERT_GE(run.records.size(), 40u);
    NetworkTrafficModel model;
    test::CheckedModel checked(&model);
    model.setNetwork(*run.net);
    QSignalSpy dropped(&model, &NetworkTrafficModel::rowsDropped);
    // Three batches, then a cap below what came: the oldest rows go and the count says how many.
    const std::size_t third = run.records.size() / 3;
    model.append({run.records.begin(), run.records.begin() + std::ptrdiff_t(third)});
    model.append({run.records.begin() + std::ptrdiff_t(third),
                  run.records.begin() + std::ptrdiff_t(2 * third)});
    EXPECT_EQ(model.rowCount(), int(2 * third));
    EXPECT_EQ(model.droppedRows(), 0);
    EXPECT_EQ(dropped.count(), 0);
    model.setMaxRows(int(third));
    EXPECT_EQ(model.rowCount(), int(third));
    EXPECT_EQ(model.droppedRows(), qint64(third));
    model.append({run.records.begin() + std::ptrdiff_t(2 * third), run.records.end()});
    EXPECT_EQ(model.rowCount(), int(third));
    EXPECT_EQ(model.droppedRows(), qint64(run.records.size() - third));
    ASSERT_GE(dropped.count(), 2);
    EXPECT_EQ(dropped.last().at(0).toLongLong(), qint64(run.records.size() - third));
    // The rows kept are the newest, in order.
    EXPECT_EQ(model.record(model.rowCount() - 1).startUs, run.records.back().startUs);
    EXPECT_EQ(model.index(0, NetworkTrafficModel::Time)
                  .data(NetworkTrafficModel::StartUsRole)
                  .toLongLong(),
              run.records[run.records.size() - third].startUs);
    // A batch larger than the cap keeps its own newest rows.
    model.clear();
    EXPECT_EQ(model.droppedRows(), 0);
    model.setMaxRows(5);
    model.append(run.records);
    EXPECT_EQ(model.rowCount(), 5);
    EXPECT_EQ(model.droppedRows(), qint64(run.records.size() - 5));
    EXPECT_EQ(model.record(4).startUs, run.records.back().startUs);
    EXPECT_TRUE(checked.findings().isEmpty()) << checked.findings().join(u'\n').toStdString();
}

TEST(NetworkTrafficModel, TimeIsSecondsMillisecondsMicroseconds) {
    EXPECT_EQ(NetworkTrafficModel::timeText(0).toStdString(), "0.000.000");
    EXPECT_EQ(NetworkTrafficModel::timeText(12'345'678).toStdString(), "12.345.678");
    EXPECT_EQ(NetworkTrafficModel::timeText(7'292).toStdString(), "0.007.292");
}

// The view over the modbus example: the master's first request and the slave's reply, decoded
// in the table as a user reads them.
TEST(NetworkTrafficView, DecodesTheFramesOfARealRun) {
    TrafficRun run = runExample(QStringLiteral("modbus/modbus.rungnet"), 1000);
    ASSERT_TRUE(run.net) << run.error.toStdString();
    NetworkTrafficView view;
    view.resize(1366, 500);
    view.setNetwork(*run.net);
    view.append(run.records);
    QAbstractItemModel *shown = view.table()->model();
    ASSERT_EQ(shown->rowCount(), int(run.records.size()));
    const auto cell = [&](int row, int column) {
        return shown->index(row, column).data().toString();
    };
    // Find the first request and its reply.
    int request = -1;
    for (int row = 0; row < shown->rowCount() && request < 0; ++row)
        if (cell(row, NetworkTrafficModel::Command).startsWith(QStringLiteral("\u2192")))
            request = row;
    ASSERT_GE(request, 0);
    const network::DecodedFrame &f = view.model()->decoded(request);
    EXPECT_EQ(cell(request, NetworkTrafficModel::Time),
              NetworkTrafficModel::timeText(run.records[std::size_t(request)].startUs));
    EXPECT_EQ(cell(request, NetworkTrafficModel::Wire).toStdString(), "w1");
    EXPECT_EQ(cell(request, NetworkTrafficModel::Sender).toStdString(), "master/CP2");
    EXPECT_EQ(cell(request, NetworkTrafficModel::Protocol).toStdString(), "MODBUS RTU");
    EXPECT_EQ(cell(request, NetworkTrafficModel::Station), QString::number(f.station));
    EXPECT_EQ(cell(request, NetworkTrafficModel::Receiver),
              QStringLiteral("s%1/CP2").arg(f.station));
    EXPECT_TRUE(cell(request, NetworkTrafficModel::Address).startsWith(QLatin1Char('D')))
        << cell(request, NetworkTrafficModel::Address).toStdString();
    EXPECT_EQ(cell(request, NetworkTrafficModel::Error).toStdString(), "");
    EXPECT_EQ(cell(request, NetworkTrafficModel::Bytes),
              QString::fromLatin1(run.records[std::size_t(request)].bytes.toHex(' ').toUpper()));
    const int reply = request + 1;
    EXPECT_TRUE(cell(reply, NetworkTrafficModel::Command).startsWith(QStringLiteral("\u2190")));
    EXPECT_EQ(cell(reply, NetworkTrafficModel::Receiver).toStdString(), "master/CP2");
    EXPECT_EQ(cell(reply, NetworkTrafficModel::Sender), QStringLiteral("s%1/CP2").arg(f.station));
    EXPECT_EQ(cell(reply, NetworkTrafficModel::Address),
              cell(request, NetworkTrafficModel::Address));
    EXPECT_EQ(cell(reply, NetworkTrafficModel::Error).toStdString(), "");
    // The status line counts the frames.
    EXPECT_NE(view.findChild<QLabel *>(QStringLiteral("trafficStatus"))
                  ->text()
                  .indexOf(QString::number(run.records.size())),
              -1);
}

// The cpm1-host-link example (the CPM1's peripheral port, Host Link) as the IDE runs it: the
// view learns the wiring when the network is built, then the port's bridge opens (a
// pseudo-terminal here) and the spec's read of DM 0000 ("@00RD0000000157*") comes from its
// real line. The table shows the command decoded and the PLC's answer read against it.
TEST(NetworkTrafficView, DecodesAHostLinkReadOfTheCpm1Example) {
    network::NetworkDescription d;
    QString error;
    ASSERT_TRUE(network::readNetworkFile(
        kExamples + QStringLiteral("cpm1-host-link/cpm1-host-link.rungnet"), &d, &error))
        << error.toStdString();
    ASSERT_EQ(d.bridges.size(), 1u);
    std::unique_ptr<network::Network> net =
        network::Network::build(d, app::cliProgramLoader(), &error);
    ASSERT_TRUE(net) << error.toStdString();
    std::vector<network::TrafficRecord> records;
    net->setTrafficSink([&records](const network::TrafficRecord &r) { records.push_back(r); });
    NetworkTrafficView view;
    view.resize(1366, 500);
    view.setNetwork(*net);
    std::shared_ptr<comms::Transport> pty = comms::PtyTransport::createPair(&error);
    ASSERT_TRUE(pty) << error.toStdString();
    network::BridgeEndpoint *line = network::attachBridgeLine(*net, d.bridges[0].end, pty, &error);
    ASSERT_NE(line, nullptr) << error.toStdString();
    ASSERT_TRUE(net->runUntil(100'000));
    net->inject(line, "@00RD0000000157*\r");
    ASSERT_TRUE(net->runUntil(200'000));
    ASSERT_EQ(records.size(), 2u);
    view.append(records);
    QAbstractItemModel *shown = view.table()->model();
    ASSERT_EQ(shown->rowCount(), 2);
    const auto cell = [&](int row, int column) {
        return shown->index(row, column).data().toString().toStdString();
    };
    EXPECT_EQ(cell(0, NetworkTrafficModel::Sender), "bridge:cpm1/PERIPHERAL");
    EXPECT_EQ(cell(0, NetworkTrafficModel::Receiver), "cpm1/PERIPHERAL");
    EXPECT_EQ(cell(0, NetworkTrafficModel::Protocol), "Host Link");
    EXPECT_EQ(cell(0, NetworkTrafficModel::Station), "0");
    EXPECT_EQ(cell(0, NetworkTrafficModel::Command), "\u2192 RD read DM words");
    EXPECT_EQ(cell(0, NetworkTrafficModel::Address), "DM 0000 (0000)");
    EXPECT_EQ(cell(0, NetworkTrafficModel::Count), "1");
    EXPECT_EQ(cell(0, NetworkTrafficModel::Error), "");
    // The batch count DM 0000 is 0 after a start: the PLC's reply carries it.
    EXPECT_EQ(cell(1, NetworkTrafficModel::Sender), "cpm1/PERIPHERAL");
    EXPECT_EQ(cell(1, NetworkTrafficModel::Receiver), "bridge:cpm1/PERIPHERAL");
    EXPECT_EQ(cell(1, NetworkTrafficModel::Protocol), "Host Link");
    EXPECT_EQ(cell(1, NetworkTrafficModel::Command), "\u2190 RD read DM words");
    EXPECT_EQ(cell(1, NetworkTrafficModel::Address), "DM 0000 (0000)");
    EXPECT_EQ(cell(1, NetworkTrafficModel::Data), "0000");
    EXPECT_EQ(cell(1, NetworkTrafficModel::Error), "");
    EXPECT_FALSE(shown->index(1, 0).data(NetworkTrafficModel::FailedRole).toBool());
}

TEST(NetworkTrafficView, FiltersByWireStationAndErrors) {
    network::FaultDescription corrupt;
    corrupt.kind = network::FaultDescription::Kind::Corrupt;
    corrupt.wire = QStringLiteral("w1");
    corrupt.frame = 2;
    corrupt.byte = 3;
    TrafficRun run = runExample(QStringLiteral("modbus/modbus.rungnet"), 1000, corrupt);
    ASSERT_TRUE(run.net) << run.error.toStdString();
    NetworkTrafficView view;
    view.setNetwork(*run.net);
    view.append(run.records);
    QAbstractItemModel *shown = view.table()->model();
    const int all = shown->rowCount();
    ASSERT_EQ(all, int(run.records.size()));
    EXPECT_EQ(view.findChild<QComboBox *>(QStringLiteral("trafficStation"))->count(), 4); // all + 3
    // Station s1: the frames it sent and those for it, nothing of s2.
    view.setStationFilter(QStringLiteral("s1"));
    const int s1 = shown->rowCount();
    EXPECT_GT(s1, 0);
    EXPECT_LT(s1, all);
    for (int row = 0; row < s1; ++row) {
        const QString sender = shown->index(row, NetworkTrafficModel::Sender).data().toString();
        const QString receiver = shown->index(row, NetworkTrafficModel::Receiver).data().toString();
        EXPECT_TRUE(sender == QStringLiteral("s1/CP2") || receiver == QStringLiteral("s1/CP2"))
            << sender.toStdString() << " -> " << receiver.toStdString();
    }
    // Errors only: the corrupted frame (its note and its CRC) and nothing that read well.
    view.setStationFilter({});
    view.findChild<QCheckBox *>(QStringLiteral("trafficErrorsOnly"))->setChecked(true);
    ASSERT_GE(shown->rowCount(), 1);
    EXPECT_LT(shown->rowCount(), all);
    bool sawCorrupted = false;
    for (int row = 0; row < shown->rowCount(); ++row) {
        const QString note = shown->index(row, NetworkTrafficModel::Note).data().toString();
        const QString error = shown->index(row, NetworkTrafficModel::Error).data().toString();
        EXPECT_FALSE(note.isEmpty() && error.isEmpty());
        if (note.contains(QStringLiteral("corrupted"))) {
            sawCorrupted = true;
            EXPECT_NE(error.indexOf(QStringLiteral("CRC")), -1) << error.toStdString();
            // The fault's row is marked: its background is not the table's.
            EXPECT_TRUE(
                shown->index(row, NetworkTrafficModel::Note).data(Qt::BackgroundRole).isValid());
        }
    }
    EXPECT_TRUE(sawCorrupted);
    // The example has one wire: choosing it shows every frame.
    view.setErrorsOnly(false);
    view.setWireFilter(QStringLiteral("w1"));
    EXPECT_EQ(shown->rowCount(), all);
}

TEST(NetworkTrafficView, ChoosingAFrameMovesTheChartsCursor) {
    TrafficRun run = runExample(QStringLiteral("easy-link/easy-link.rungnet"), 500);
    ASSERT_TRUE(run.net) << run.error.toStdString();
    ASSERT_GE(run.records.size(), 4u);
    NetworkTrafficView view;
    view.setNetwork(*run.net);
    view.append(run.records);
    QSignalSpy chosen(&view, &NetworkTrafficView::frameChosen);
    QTableView *table = view.table();
    table->selectionModel()->setCurrentIndex(table->model()->index(3, 0),
                                             QItemSelectionModel::ClearAndSelect |
                                                 QItemSelectionModel::Rows);
    ASSERT_EQ(chosen.count(), 1);
    EXPECT_EQ(chosen.at(0).at(0).toLongLong(), run.records[3].startUs);
    // Through the filter the row is the filtered one's.
    view.setStationFilter(QStringLiteral("s2"));
    table->selectionModel()->setCurrentIndex(table->model()->index(0, 0),
                                             QItemSelectionModel::ClearAndSelect |
                                                 QItemSelectionModel::Rows);
    ASSERT_GE(chosen.count(), 2);
    const qint64 us = chosen.last().at(0).toLongLong();
    EXPECT_EQ(us, table->model()->index(0, 0).data(NetworkTrafficModel::StartUsRole).toLongLong());
    EXPECT_EQ(table->model()->index(0, NetworkTrafficModel::Time).data().toString(),
              NetworkTrafficModel::timeText(us));
}

TEST(NetworkTrafficView, SavesCsvAndTextThatReadBack) {
    TrafficRun run = runExample(QStringLiteral("modbus/modbus.rungnet"), 300);
    ASSERT_TRUE(run.net) << run.error.toStdString();
    NetworkTrafficView view;
    view.setNetwork(*run.net, kExamples + QStringLiteral("modbus/modbus.rungnet"));
    view.append(run.records);
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    QString error;

    // Text: the CLI's traffic lines, byte for byte, under its header.
    const QString text = dir.filePath(QStringLiteral("traffic.txt"));
    ASSERT_TRUE(view.saveText(text, &error)) << error.toStdString();
    QString expected = network::trafficHeader(QStringLiteral("modbus.rungnet")) + u'\n';
    for (const network::TrafficRecord &r : run.records)
        expected += network::formatTraffic(r) + u'\n';
    EXPECT_EQ(readBack(text).toStdString(), expected.toStdString());

    // CSV: a header of the columns, a line per frame, the cells as the table shows them.
    const QString csv = dir.filePath(QStringLiteral("traffic.csv"));
    ASSERT_TRUE(view.saveCsv(csv, &error)) << error.toStdString();
    const QStringList lines = readBack(csv).split(u'\n', Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), int(run.records.size()) + 1);
    EXPECT_TRUE(
        lines[0].startsWith(QStringLiteral("Time (s),Wire,Sender,Receiver,Protocol,Station,")))
        << lines[0].toStdString();
    const QStringList first = lines[1].split(u',');
    ASSERT_EQ(first.size(), NetworkTrafficModel::ColumnCount) << lines[1].toStdString();
    EXPECT_EQ(first[NetworkTrafficModel::Time],
              NetworkTrafficModel::timeText(run.records[0].startUs));
    EXPECT_EQ(first[NetworkTrafficModel::Sender], run.records[0].sender);
    EXPECT_EQ(first[NetworkTrafficModel::Bytes],
              QString::fromLatin1(run.records[0].bytes.toHex(' ').toUpper()));
    EXPECT_EQ(columnOf(QStringLiteral("Bytes")), NetworkTrafficModel::Bytes);

    // Filtered, a text file says what it leaves out.
    view.setStationFilter(QStringLiteral("s2"));
    ASSERT_TRUE(view.saveText(text, &error)) << error.toStdString();
    const QStringList filtered = readBack(text).split(u'\n', Qt::SkipEmptyParts);
    ASSERT_EQ(filtered.size(), view.shownRows() + 2);
    EXPECT_TRUE(filtered[1].startsWith(QStringLiteral("# "))) << filtered[1].toStdString();
    EXPECT_NE(filtered[1].indexOf(QStringLiteral("station s2")), -1) << filtered[1].toStdString();

    // A folder that is not there: a clear error, no file.
    EXPECT_FALSE(view.saveCsv(dir.filePath(QStringLiteral("no/such/folder/t.csv")), &error));
    EXPECT_NE(error.indexOf(QStringLiteral("Cannot write")), -1) << error.toStdString();
}

// Language > Magyar while frames are shown: the choosers, the column titles and the decoded
// cells follow; back to English, they read as before.
TEST(NetworkTrafficView, FollowsALanguageSwitch) {
    TrafficRun run = runExample(QStringLiteral("modbus/modbus.rungnet"), 300);
    ASSERT_TRUE(run.net) << run.error.toStdString();
    NetworkTrafficView view;
    view.setNetwork(*run.net);
    view.append(run.records);
    QAbstractItemModel *shown = view.table()->model();
    const QString english = shown->index(0, NetworkTrafficModel::Command).data().toString();
    ASSERT_NE(english.indexOf(QStringLiteral("read holding registers")), -1)
        << english.toStdString();
    ASSERT_TRUE(app::setLanguage(QStringLiteral("hu"), false));
    // The switch reaches the widgets as a posted LanguageChange.
    auto *errorsOnly = view.findChild<QCheckBox *>(QStringLiteral("trafficErrorsOnly"));
    ASSERT_TRUE(rung::waits::eventually(
        [&] { return errorsOnly->text() == QStringLiteral("Csak &hibák"); }));
    EXPECT_EQ(shown->headerData(NetworkTrafficModel::Wire, Qt::Horizontal).toString().toStdString(),
              "Vezeték");
    EXPECT_NE(shown->index(0, NetworkTrafficModel::Command)
                  .data()
                  .toString()
                  .indexOf(QStringLiteral("tartóregiszterek olvasása")),
              -1);
    EXPECT_EQ(view.findChild<QComboBox *>(QStringLiteral("trafficWire"))->itemText(0).toStdString(),
              "Minden vezeték");
    app::setLanguage(QStringLiteral("en"), false);
    ASSERT_TRUE(rung::waits::eventually(
        [&] { return errorsOnly->text() == QStringLiteral("&Errors only"); }));
    EXPECT_EQ(shown->index(0, NetworkTrafficModel::Command).data().toString(), english);
    EXPECT_EQ(shown->rowCount(), int(run.records.size()));
}

// A long run: 100,500 frames in batches of 500, as a dock receives them. The view keeps the
// newest 100,000 in one table (no widget per row), says how many it let go, and a filter over
// all of them still answers.
TEST(NetworkTrafficView, KeepsTheNewestFramesOfALongRunWithinItsCap) {
    TrafficRun run = runExample(QStringLiteral("modbus/modbus.rungnet"), 1000);
    ASSERT_TRUE(run.net) << run.error.toStdString();
    ASSERT_GE(run.records.size(), 50u);
    NetworkTrafficView view;
    view.resize(1366, 500);
    view.setNetwork(*run.net);
    view.show();
    const int total = NetworkTrafficModel::DefaultMaxRows + 500;
    const qint64 period = run.records.back().endUs;
    std::vector<network::TrafficRecord> batch;
    for (int i = 0; i < total; ++i) {
        network::TrafficRecord r = run.records[std::size_t(i) % run.records.size()];
        const qint64 shift = qint64(i / int(run.records.size())) * period;
        r.startUs += shift;
        r.endUs += shift;
        batch.push_back(std::move(r));
        if (batch.size() == 500)
            view.append(std::exchange(batch, {}));
    }
    view.append(std::move(batch));
    NetworkTrafficModel *model = view.model();
    EXPECT_EQ(model->rowCount(), NetworkTrafficModel::DefaultMaxRows);
    EXPECT_EQ(model->droppedRows(), 500);
    EXPECT_EQ(view.shownRows(), NetworkTrafficModel::DefaultMaxRows);
    EXPECT_TRUE(view.findChildren<QCheckBox *>().size() == 1); // the filter's, none per row
    const QString status = view.findChild<QLabel *>(QStringLiteral("trafficStatus"))->text();
    EXPECT_NE(status.indexOf(QStringLiteral("500 older frames were let go")), -1)
        << status.toStdString();
    // The rows read as the decoder reads them: the last one is the newest frame.
    EXPECT_FALSE(model->decoded(model->rowCount() - 1).failed());
    view.setStationFilter(QStringLiteral("s2"));
    EXPECT_GT(view.shownRows(), 0);
    EXPECT_LT(view.shownRows(), NetworkTrafficModel::DefaultMaxRows);
}

// A slave that stays silent: the master's requests to it are marked in the table once the next
// request shows that no reply came, and "Errors only" finds them.
TEST(NetworkTrafficView, MarksTheRequestsThatGotNoReply) {
    network::FaultDescription silent;
    silent.kind = network::FaultDescription::Kind::Silent;
    silent.station = QStringLiteral("s1");
    TrafficRun run = runExample(QStringLiteral("modbus/modbus.rungnet"), 2000, silent);
    ASSERT_TRUE(run.net) << run.error.toStdString();
    NetworkTrafficView view;
    view.setNetwork(*run.net);
    // Batches of 3: a request and the request that shows it unanswered often fall apart.
    for (std::size_t i = 0; i < run.records.size(); i += 3)
        view.append({run.records.begin() + std::ptrdiff_t(i),
                     run.records.begin() + std::ptrdiff_t(std::min(i + 3, run.records.size()))});
    view.setErrorsOnly(true);
    QAbstractItemModel *shown = view.table()->model();
    int noReply = 0;
    for (int row = 0; row < shown->rowCount(); ++row) {
        const QString error = shown->index(row, NetworkTrafficModel::Error).data().toString();
        if (error != network::TrafficDecoder::noReplyText())
            continue;
        ++noReply;
        EXPECT_EQ(shown->index(row, NetworkTrafficModel::Receiver).data().toString().toStdString(),
                  "s1/CP2");
        EXPECT_EQ(shown->index(row, NetworkTrafficModel::Sender).data().toString().toStdString(),
                  "master/CP2");
    }
    EXPECT_GT(noReply, 0);
    // s2 answers: none of its requests is marked.
    view.setErrorsOnly(false);
    view.setStationFilter(QStringLiteral("s2"));
    for (int row = 0; row < shown->rowCount(); ++row)
        EXPECT_EQ(shown->index(row, NetworkTrafficModel::Error).data().toString().toStdString(),
                  "");
}

// The columns are sized on the first rows; a later frame with a longer text (here the first
// "no reply" error, long after the first request) widens its column so the text reads, up to
// the column's cap, and a column the user sized by hand stays as the user left it.
TEST(NetworkTrafficView, AColumnWidensForALongerTextLaterUnlessSizedByHand) {
    network::FaultDescription silent;
    silent.kind = network::FaultDescription::Kind::Silent;
    silent.station = QStringLiteral("s1");
    TrafficRun run = runExample(QStringLiteral("modbus/modbus.rungnet"), 2000, silent);
    ASSERT_TRUE(run.net) << run.error.toStdString();
    ASSERT_GT(run.records.size(), 20u);
    NetworkTrafficView view;
    view.resize(1300, 500);
    view.setNetwork(*run.net);
    view.append({run.records.front()}); // a request: no error yet
    QTableView *table = view.table();
    QAbstractItemModel *shown = table->model();
    ASSERT_EQ(shown->rowCount(), 1);
    ASSERT_TRUE(shown->index(0, NetworkTrafficModel::Error).data().toString().isEmpty());
    const int before = table->columnWidth(NetworkTrafficModel::Error);
    const QString noReply = network::TrafficDecoder::noReplyText();
    const int needed = table->fontMetrics().horizontalAdvance(noReply);
    ASSERT_GT(needed, before); // else the test shows nothing

    view.append({run.records.begin() + 1, run.records.begin() + 10});
    bool seen = false;
    for (int row = 0; row < shown->rowCount(); ++row)
        seen = seen || shown->index(row, NetworkTrafficModel::Error).data().toString() == noReply;
    ASSERT_TRUE(seen);
    const int em = table->fontMetrics().horizontalAdvance(QLatin1Char('M'));
    EXPECT_GE(table->columnWidth(NetworkTrafficModel::Error), std::min(needed, 24 * em));

    // Sized by hand: the view leaves it, though wider texts come.
    table->horizontalHeader()->resizeSection(NetworkTrafficModel::Error, before);
    view.append({run.records.begin() + 10, run.records.end()});
    EXPECT_EQ(table->columnWidth(NetworkTrafficModel::Error), before);
}
