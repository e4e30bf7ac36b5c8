// The ladder view's speed (issue 4): a 10,000-rung project opens and paints its first page,
// scrolling repaints one frame, and the memory the process holds with it open.
#include "tests/model/random_program.cpp"

#include "app/gui/main_window.h"
#include "editor/ladder_view.h"

#include "model/convert/convert.h"

#include <QApplication>
#include <QFile>
#include <QScrollBar>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <benchmark/benchmark.h>

using namespace rung;

namespace {

model::Project bigProject() {
    static model::Project project = [] {
        const model::Target &t = model::Target::get(model::Family::Vigor);
        rung::testing::RandomProgramOptions o;
        o.rungs = 10000;
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

void openAndPaintFirstPage(benchmark::State &state) {
    const model::Project project = bigProject();
    for (auto _ : state) {
        editor::Document document;
        document.setProject(project, QString()); // converts, checks, lays out
        editor::LadderView view(&document);
        view.resize(1400, 900);
        QImage frame = view.viewport()->grab().toImage();
        benchmark::DoNotOptimize(frame.bits());
    }
    state.counters["rungs"] = static_cast<double>(project.program.rungs.size());
    state.counters["rss_MB"] = residentMegabytes();
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
    }
    state.counters["rss_MB"] = residentMegabytes();
}

} // namespace

BENCHMARK(openAndPaintFirstPage)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(scrollOnePage)->Unit(benchmark::kMillisecond);
BENCHMARK(openFileInTheMainWindow)->Unit(benchmark::kMillisecond)->Iterations(3);

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
