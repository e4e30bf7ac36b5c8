// The ladder view's speed (issue 4): a 10,000-rung project opens and paints its first page,
// scrolling repaints one frame, and the memory the process holds with it open. The live
// overlay (issue 11): how often it repaints with a 2,000-rung program simulated as fast as
// possible, what one overlay frame costs, and the time from toggling an input to the frame
// that shows its coil changed, at real-time speed.
#include "tests/benchmarks/smoke.h"
#include "tests/model/random_program.cpp"

#include "app/gui/main_window.h"
#include "app/gui/network_window.h"
#include "app/gui/simulation_controller.h"
#include "editor/il_editor.h"
#include "editor/ladder_painter.h"
#include "editor/ladder_view.h"
#include "network/network_session.h"
#include "simulator/session.h"

#include "model/convert/convert.h"
#include "model/target/address.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QPaintEvent>
#include <QComboBox>
#include <QScrollBar>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QThread>

#include <algorithm>

#include <malloc.h>

#include <benchmark/benchmark.h>

using namespace rung;

namespace {

model::Project bigProject() {
    static model::Project project = [] {
        const model::Target &t = model::Target::get(model::Family::Vigor);
        rung::testing::RandomProgramOptions o;
        o.rungs = bench::sized(10000, 200);
        const model::ParseResult parsed =
            model::parseInstructionList(t, rung::testing::randomProgram(t, 7, o));
        model::Project p;
        p.target = &t;
        p.model = t.defaultModel().name;
        p.program = model::listToLadder(parsed.list).ladder;
        return p;
    }();
    return project;
}

double residentMegabytes() {
    QFile f(QStringLiteral("/proc/self/statm"));
    if (!f.open(QIODevice::ReadOnly))
        return 0;
    const QList<QByteArray> fields = f.readAll().split(' ');
    return fields.size() > 1 ? fields[1].toDouble() * 4096.0 / (1024 * 1024) : 0;
}

// The heap in use (glibc's count of allocated bytes, mapped blocks included): what the program
// holds, without the freed memory the allocator keeps for reuse, which the resident size
// counts and which depends on the order of earlier allocations more than on what is open.
double heapMegabytes() {
    const struct mallinfo2 info = mallinfo2();
    return static_cast<double>(info.uordblks + info.hblkhd) / (1024 * 1024);
}

// Both, read while the project is open (not after the loop, when it has been closed), once
// the events the opening posted are delivered, as a running application's loop would.
struct HeldMemory {
    // The heap before the first iteration (the benchmark's own copies of the program): what
    // the view or the window adds is heap - before.
    double before = heapMegabytes();
    double resident = 0;
    double heap = 0;
    void read(benchmark::State &state) {
        state.PauseTiming();
        QCoreApplication::processEvents();
        resident = std::max(resident, residentMegabytes());
        heap = std::max(heap, heapMegabytes());
        state.ResumeTiming();
    }
    void report(benchmark::State &state) const {
        state.counters["rss_MB"] = resident;
        state.counters["heap_MB"] = heap;
        state.counters["heap_before_MB"] = before;
    }
};

void openAndPaintFirstPage(benchmark::State &state) {
    const model::Project project = bigProject();
    HeldMemory held;
    for (auto _ : state) {
        editor::Document document;
        document.setProject(project, QString()); // converts, checks, lays out
        editor::LadderView view(&document);
        view.resize(1400, 900);
        QImage frame = view.viewport()->grab().toImage();
        benchmark::DoNotOptimize(frame.bits());
        held.read(state);
    }
    state.counters["rungs"] = static_cast<double>(project.program.rungs.size());
    held.report(state);
}

void scrollOnePage(benchmark::State &state) {
    editor::Document document;
    document.setProject(bigProject(), QString());
    editor::LadderView view(&document);
    view.resize(1400, 900);
    int value = 0;
    for (auto _ : state) {
        value =
            (value + view.viewport()->height()) % std::max(1, view.verticalScrollBar()->maximum());
        view.verticalScrollBar()->setValue(value);
        QImage frame = view.viewport()->grab().toImage();
        benchmark::DoNotOptimize(frame.bits());
    }
}

// What a user waits for: File > Open of a 10,000-rung project file in the main window
// (read and validate the JSON, convert, check, fill the IL editor, paint the first page).
void openFileInTheMainWindow(benchmark::State &state) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("big.rung"));
    model::ProjectError error;
    if (!model::saveProject(bigProject(), path, &error)) {
        state.SkipWithError("could not write the project");
        return;
    }
    HeldMemory held;
    for (auto _ : state) {
        app::MainWindow window;
        window.resize(1400, 900);
        window.show();
        if (!window.openFile(path, QString(), true)) {
            state.SkipWithError("the project did not open");
            return;
        }
        QImage frame = window.grab().toImage();
        benchmark::DoNotOptimize(frame.bits());
        held.read(state);
    }
    held.report(state);
}

// A 2,000-rung Vigor program whose first rung is LD X20 / OUT Y20 (devices the random rungs
// do not use) and whose second counts the scans in D100 (so that every snapshot changes what
// the first page shows), saved as a project the main window opens.
// On failure: an empty path and why in `why`.
QString overlayProjectFile(QTemporaryDir &dir, std::string &why) {
    const model::Target &t = model::Target::get(model::Family::Vigor);
    // The generator numbers a timer per extended rung: 800 of them stay within the target's
    // timers (timers, compares, moves: values under the boxes); 1,200 plain rungs follow.
    rung::testing::RandomProgramOptions boxes;
    boxes.rungs = bench::sized(800, 40);
    boxes.extended = true;
    boxes.end = false;
    // 2,000 rungs within the VH's 16,000 steps: networks two deep, one output a rung.
    boxes.maxDepth = 2;
    boxes.branches = false;
    rung::testing::RandomProgramOptions plain;
    plain.rungs = bench::sized(1200, 60);
    plain.maxDepth = 2;
    plain.branches = false;
    const QString text = QStringLiteral("LD X20\nOUT Y20\nLD M9000\nINC D100\n") +
                         rung::testing::randomProgram(t, 11, boxes) +
                         rung::testing::randomProgram(t, 12, plain);
    const model::ParseResult parsed = model::parseInstructionList(t, text);
    if (!parsed.ok()) {
        const model::ParseError &e = parsed.errors.front();
        why = QStringLiteral("the generated listing does not parse: line %1: %2")
                  .arg(e.line)
                  .arg(e.message)
                  .toStdString();
        return {};
    }
    model::Project p;
    p.target = &t;
    p.model = t.defaultModel().name;
    p.program = model::listToLadder(parsed.list).ladder;
    const QString path = dir.filePath(QStringLiteral("overlay.rung"));
    model::ProjectError error;
    if (!model::saveProject(p, path, &error)) {
        why = "the project could not be written";
        return {};
    }
    return path;
}

// Counts the paint events of a widget and when the last one ended.
struct PaintCounter : QObject {
    int paints = 0;
    QElapsedTimer clock;
    qint64 firstNs = -1, lastNs = -1;
    PaintCounter() { clock.start(); }
    bool eventFilter(QObject *, QEvent *event) override {
        if (event->type() == QEvent::Paint) {
            ++paints;
            lastNs = clock.nsecsElapsed();
            if (firstNs < 0)
                firstNs = lastNs;
        }
        return false;
    }
    void reset() {
        paints = 0;
        firstNs = lastNs = -1;
    }
    // Frames a second between the first and the last frame: a window that ends between two
    // frames does not count as time without frames.
    double rate() const {
        return paints > 1 ? (paints - 1) * 1e9 / static_cast<double>(lastNs - firstNs) : 0.0;
    }
};

// The window as a user has it: ladder and list side by side, 1366x768, the program running.
struct RunningWindow {
    QTemporaryDir dir;
    app::MainWindow window;
    bool ok = false;
    std::string why; // what went wrong when !ok
    explicit RunningWindow(double speed) {
        const QString path = overlayProjectFile(dir, why);
        window.resize(1366, 768);
        window.setSideBySide(true);
        window.show();
        if (path.isEmpty())
            return;
        if (!window.openFile(path, QString(), true)) {
            why = "the project did not open";
            return;
        }
        // The controller says why it does not start (the program's errors).
        QString said;
        QObject::connect(window.simulation(), &app::SimulationController::message, &window,
                         [&said](const QString &text) { said += text + QLatin1Char(' '); });
        QObject::connect(window.simulation(), &app::SimulationController::problems, &window,
                         [&said](const std::vector<model::Diagnostic> &errors) {
                             for (const model::Diagnostic &d : errors)
                                 said += QStringLiteral("%1 (line %2, rung %3): %4; ")
                                             .arg(d.code)
                                             .arg(d.location.line)
                                             .arg(d.location.rung + 1)
                                             .arg(d.message);
                         });
        window.simulation()->setSpeed(speed);
        ok = window.simulation()->run();
        if (!ok)
            why = "the program did not run: " + said.toStdString();
        QApplication::processEvents();
    }
    ~RunningWindow() { window.simulation()->stop(); }
};

// The overlay's frame rate with the program scanning as fast as the engine goes: every
// snapshotChanged (at most 30 a second) repaints the rungs on screen that changed. Counters:
// frames (ladder repaints) and snapshots per second, scans per second.
void overlayFramesAtFullSpeed(benchmark::State &state) {
    RunningWindow w(0.0);
    if (!w.ok) {
        state.SkipWithError(w.why.c_str());
        return;
    }
    editor::LadderView *view = w.window.ladderView();
    PaintCounter frames;
    view->viewport()->installEventFilter(&frames);
    int snapshots = 0;
    QObject::connect(w.window.simulation()->session(), &model::MonitorSource::snapshotChanged, view,
                     [&snapshots] { ++snapshots; });
    QApplication::processEvents();
    const quint64 scansBefore = w.window.simulation()->session()->snapshot()->statistics.scans;
    QElapsedTimer clock;
    clock.start();
    frames.reset();
    snapshots = 0;
    for (auto _ : state) {
        // One second of the event loop, as the user's screen has it.
        QElapsedTimer second;
        second.start();
        while (second.elapsed() < 1000)
            QApplication::processEvents(QEventLoop::AllEvents, 5);
    }
    const double seconds = static_cast<double>(clock.elapsed()) / 1000.0;
    const quint64 scans =
        w.window.simulation()->session()->snapshot()->statistics.scans - scansBefore;
    state.counters["overlay_fps"] = frames.rate();
    state.counters["overlay_frames_per_window_s"] = frames.paints / seconds;
    state.counters["snapshots_per_s"] = snapshots / seconds;
    state.counters["scans_per_s"] = static_cast<double>(scans) / seconds;
    state.counters["rungs"] = static_cast<double>(w.window.document()->ladder().rungs.size());
    view->viewport()->removeEventFilter(&frames);
}

// What one overlay frame costs the UI thread: the snapshot's power flow mapped to the rungs on
// screen and those rungs repainted (the ladder at 1366x768), the program paused between
// frames so that each frame has its own scan.
void overlayFrameCost(benchmark::State &state) {
    RunningWindow w(0.0);
    if (!w.ok) {
        state.SkipWithError(w.why.c_str());
        return;
    }
    app::SimulationController *sim = w.window.simulation();
    sim->pause();
    editor::LadderView *view = w.window.ladderView();
    const model::Address x20 = std::get<model::Address>(
        model::parseAddress(w.window.document()->target(), QStringLiteral("X20")));
    bool on = false;
    for (auto _ : state) {
        state.PauseTiming();
        on = !on;
        sim->session()->writeBit(x20, on);
        sim->singleScan();
        // The scan's snapshot, not yet told to the view.
        QElapsedTimer wait;
        wait.start();
        while (sim->session()->snapshot()->statistics.scans == 0 ||
               sim->session()->snapshot()->bit(x20) != on) {
            if (wait.elapsed() > 2000)
                break;
            QThread::msleep(1);
        }
        state.ResumeTiming();
        // snapshotChanged as the source emits it, then the repaint it asks for.
        emit sim->session()->snapshotChanged();
        view->viewport()->repaint();
    }
}

// Input to screen at real-time speed (x1, 10 ms scans): X20 written through the source, then
// the event loop runs until a repaint of the ladder shows Y20's coil changed (its fill, read
// from the screen). The time includes the wait for the next scan, the snapshot and
// notification rate limit (34 ms) and the repaint.
void inputToScreenLatency(benchmark::State &state) {
    RunningWindow w(1.0);
    if (!w.ok) {
        state.SkipWithError(w.why.c_str());
        return;
    }
    app::SimulationController *sim = w.window.simulation();
    editor::LadderView *view = w.window.ladderView();
    // The first rung's coil on screen: the ladder beside the list is narrower than a rung.
    view->verticalScrollBar()->setValue(0);
    view->horizontalScrollBar()->setValue(view->horizontalScrollBar()->maximum());
    QApplication::processEvents();
    const model::Address x20 = std::get<model::Address>(
        model::parseAddress(w.window.document()->target(), QStringLiteral("X20")));
    const QRect out = view->cellRectOnScreen({0, 0, view->metrics().gridColumns});
    const QPoint coil(static_cast<int>(out.left() + out.width() * 0.4),
                      static_cast<int>(out.top() + view->metrics().rowHeight * 0.55));
    PaintCounter frames;
    view->viewport()->installEventFilter(&frames);
    const QColor lit = editor::LadderPainter::energisedColor();
    std::vector<double> latencies;
    bool on = false;
    for (auto _ : state) {
        on = !on;
        QElapsedTimer clock;
        clock.start();
        sim->session()->writeBit(x20, on);
        bool shown = false;
        while (!shown && clock.elapsed() < bench::patienceMs(2000)) {
            const int before = frames.paints;
            QApplication::processEvents(QEventLoop::AllEvents, 1);
            if (frames.paints == before)
                continue;
            const double at = static_cast<double>(clock.nsecsElapsed()) / 1e6;
            shown = (view->viewport()->grab().toImage().pixelColor(coil) == lit) == on;
            if (shown)
                latencies.push_back(at);
        }
        if (!shown) {
            state.SkipWithError("the coil did not change on screen in time");
            break;
        }
        state.SetIterationTime(latencies.back() / 1000.0);
        // Next toggle at a random phase of the scan and of the notification timer.
        QElapsedTimer pause;
        pause.start();
        while (pause.elapsed() < 60 + static_cast<int>(latencies.size() * 7 % 40))
            QApplication::processEvents(QEventLoop::AllEvents, 5);
    }
    view->viewport()->removeEventFilter(&frames);
    if (latencies.empty())
        return;
    std::sort(latencies.begin(), latencies.end());
    state.counters["median_ms"] = latencies[latencies.size() / 2];
    state.counters["p90_ms"] = latencies[latencies.size() * 9 / 10];
    state.counters["max_ms"] = latencies.back();
}

// Issue 30: a network of eight Vigor stations in CPU Link, each running about 200 rungs,
// simulated as fast as the machine goes in the network window at 1366x768, a station's ladder
// on screen and eight devices of eight stations in the watch table. Counters: the ladder's
// repaints a second (limit >= 30, as the single program's overlay), the watch table's, and
// how many times real time the network runs.
void networkFramesAtFullSpeed(benchmark::State &state) {
    QTemporaryDir dir;
    QString stations;
    QStringList ends;
    const int rungs = bench::sized(200, 20);
    for (int k = 0; k < 8; ++k) {
        QFile program(dir.filePath(QStringLiteral("s%1.il").arg(k)));
        if (!program.open(QIODevice::WriteOnly)) {
            state.SkipWithError("cannot write the stations' programs");
            return;
        }
        // As bench_network's stations (contacts, a coil, a move and an addition a rung), the
        // addition a counter of scans, so that every rung on screen changes every scan.
        QString text = QStringLiteral("; target: vigor\n");
        for (int r = 0; r < rungs; ++r)
            text += QStringLiteral("LD X%1\nAND M%2\nOR M%3\nOUT Y%4\nLD M9000\nMOV D%5 D%6\n"
                                   "ADD D%7 K1 D%7\n")
                        .arg(QString::number(r % 8, 8))
                        .arg(r % 100 + 100)
                        .arg(r % 100 + 200)
                        .arg(QString::number(r % 16, 8))
                        .arg(k * 10 + r % 4)
                        .arg(100 + r % 100)
                        .arg(300 + r % 100);
        program.write((text + QStringLiteral("END\n")).toUtf8());
        program.close();
        stations += QStringLiteral(R"(%1{"name": "s%2", "program": "s%2.il", "model": "VB",
            "ports": {"CP2": {"application": "cpu-link", "station": %2%3}}})")
                        .arg(k ? QStringLiteral(",") : QString())
                        .arg(k)
                        .arg(k ? QString() : QStringLiteral(R"(, "slaves": 7, "range": 1)"));
        ends << QStringLiteral("\"s%1/CP2\"").arg(k);
    }
    QFile net(dir.filePath(QStringLiteral("eight.rungnet")));
    if (!net.open(QIODevice::WriteOnly)) {
        state.SkipWithError("cannot write the network");
        return;
    }
    net.write(QStringLiteral(R"({"stations": [%1], "wires": [[%2]]})")
                  .arg(stations, ends.join(QLatin1Char(',')))
                  .toUtf8());
    net.close();
    app::NetworkWindow window;
    QString error;
    if (!window.open(net.fileName(), &error)) {
        state.SkipWithError(error.toStdString().c_str());
        return;
    }
    if (!window.session() || window.session()->stations().size() != 8) {
        const std::string why =
            ("the network does not build: " + window.statusBar()->currentMessage()).toStdString();
        state.SkipWithError(why.c_str());
        return;
    }
    window.resize(1366, 768);
    window.show();
    for (int k = 0; k < 8; ++k)
        window.watch(QStringLiteral("s%1/D%2").arg(k).arg(k));
    window.stationSelector()->setCurrentIndex(3); // s3, the Ladder tab in front
    editor::LadderView *view = window.ladderView(QStringLiteral("s3"));
    auto *table = window.findChild<QTableView *>(QStringLiteral("networkWatchTable"));
    PaintCounter frames, tableFrames;
    view->viewport()->installEventFilter(&frames);
    table->viewport()->installEventFilter(&tableFrames);
    network::NetworkSession *session = window.session();
    session->setSpeed(0);
    session->run();
    QApplication::processEvents();
    const qint64 startUs = session->nowUs();
    QElapsedTimer clock;
    clock.start();
    frames.reset();
    tableFrames.reset();
    for (auto _ : state) {
        QElapsedTimer second;
        second.start();
        while (second.elapsed() < 1000)
            QApplication::processEvents(QEventLoop::AllEvents, 5);
    }
    const double seconds = static_cast<double>(clock.elapsed()) / 1000.0;
    state.counters["ladder_fps"] = frames.rate();
    state.counters["watch_fps"] = tableFrames.rate();
    state.counters["realtime_x"] = static_cast<double>(session->nowUs() - startUs) / 1e6 / seconds;
    session->stop();
    view->viewport()->removeEventFilter(&frames);
    table->viewport()->removeEventFilter(&tableFrames);
}

} // namespace

BENCHMARK(networkFramesAtFullSpeed)->Unit(benchmark::kMillisecond)->Iterations(bench::times(3));
BENCHMARK(overlayFramesAtFullSpeed)->Unit(benchmark::kMillisecond)->Iterations(bench::times(3));
BENCHMARK(overlayFrameCost)->Unit(benchmark::kMillisecond)->Iterations(bench::times(40));
BENCHMARK(inputToScreenLatency)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(bench::times(40));
BENCHMARK(openAndPaintFirstPage)->Unit(benchmark::kMillisecond)->Iterations(bench::times(3));
BENCHMARK(scrollOnePage)->Unit(benchmark::kMillisecond);
BENCHMARK(openFileInTheMainWindow)->Unit(benchmark::kMillisecond)->Iterations(bench::times(3));

int main(int argc, char **argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QStandardPaths::setTestModeEnabled(true); // the main window's settings stay out of the way
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("RungStudioBenchmarks"));
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    return 0;
}
