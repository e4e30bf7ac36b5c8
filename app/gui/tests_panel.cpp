#include "tests_panel.h"

#include "compare_window.h"
#include "dialogs.h"
#include "eliding_label.h"
#include "file_dialogs.h"

#include "editor/document.h"
#include "editor/timing_chart.h"

#include "model/convert/convert.h"
#include "model/project/file_read.h"
#include "simulator/compiler.h"
#include "simulator/scenario_record.h"
#include "simulator/scenario_trace.h"

#include <QCoreApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QDirIterator>
#include <QEvent>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QSaveFile>
#include <QToolButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace rung::app {

namespace {

constexpr qint64 kMaxScenarioBytes = 8 * 1024 * 1024;

enum Role { FileRole = Qt::UserRole + 1, FailureRole };

QString canonical(const QString &path) {
    const QString c = QFileInfo(path).canonicalFilePath();
    return c.isEmpty() ? QDir::cleanPath(QFileInfo(path).absoluteFilePath()) : c;
}

// A program file a scenario names that is not the open project: read and prepared as the
// simulation prepares one.
simulator::ScenarioProgram programFromFile(const QString &path, const QString &targetId,
                                           const model::Target &fallback) {
    simulator::ScenarioProgram out;
    const model::Target *target = targetId.isEmpty() ? &fallback : model::Target::byId(targetId);
    if (!target) {
        out.errors << QCoreApplication::translate("rung::app::TestsPanel", "unknown target %1")
                          .arg(targetId);
        return out;
    }
    QString error;
    const auto project = loadForComparison(path, *target, &error);
    if (!project) {
        out.errors << error;
        return out;
    }
    const model::ToListingResult listed = model::ladderToList(project->program);
    if (!listed.ok()) {
        out.errors << QStringLiteral("%1: %2").arg(path, listed.problems.front().message);
        return out;
    }
    model::CheckOptions options;
    options.model = target->model(project->model);
    const simulator::CompileResult compiled = simulator::prepareProgram(listed.list, options);
    for (const model::Diagnostic &d : compiled.diagnostics)
        if (d.severity == model::Severity::Error)
            out.errors << QStringLiteral("%1: %2").arg(path, d.message);
    out.program = compiled.program;
    return out;
}

} // namespace

TestsPanel::TestsPanel(editor::Document *document, QWidget *parent)
    : QWidget(parent)
    , m_document(document) {
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    auto *buttons = new QHBoxLayout;
    // Tool buttons, and the folder on a line of its own: the dock is a tab beside the timing
    // chart, and a wider minimum than the chart's widened the whole window past small screens.
    m_runAll = new QToolButton;
    m_runOne = new QToolButton;
    m_refresh = new QToolButton;
    m_record = new QToolButton;
    for (QToolButton *b : {m_runAll, m_runOne, m_refresh, m_record})
        buttons->addWidget(b);
    buttons->addStretch(1);
    layout->addLayout(buttons);
    m_folder = new ElidingLabel;
    m_folder->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_folder);
    m_unsavedHint = new QLabel;
    m_unsavedHint->setWordWrap(true);
    layout->addWidget(m_unsavedHint);
    m_tree = new QTreeWidget;
    m_tree->setColumnCount(2);
    m_tree->header()->setSectionResizeMode(0, QHeaderView::Interactive);
    m_tree->header()->setStretchLastSection(true);
    m_tree->setColumnWidth(0, 380);
    layout->addWidget(m_tree);
    connect(m_runAll, &QToolButton::clicked, this, [this] { run(); });
    connect(m_runOne, &QToolButton::clicked, this, [this] {
        QTreeWidgetItem *item = m_tree->currentItem();
        while (item && item->parent())
            item = item->parent();
        if (item)
            run({item->data(0, FileRole).toString()});
    });
    connect(m_refresh, &QToolButton::clicked, this, &TestsPanel::refresh);
    connect(m_record, &QToolButton::clicked, this, &TestsPanel::record);
    connect(m_tree, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem *item) {
        const QVariant failure = item->data(0, FailureRole);
        if (failure.isValid() && item->parent())
            showFailure(item->parent()->data(0, FileRole).toString(),
                        static_cast<std::size_t>(failure.toULongLong()));
    });
    connect(m_document, &editor::Document::pathChanged, this, &TestsPanel::refresh);
    retranslate();
    refresh();
}

TestsPanel::~TestsPanel() {
    join();
}

void TestsPanel::join() {
    if (m_worker.joinable())
        m_worker.join();
}

void TestsPanel::changeEvent(QEvent *event) {
    QWidget::changeEvent(event);
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        showResults();
    }
}

void TestsPanel::retranslate() {
    m_runAll->setText(tr("Run All"));
    m_runOne->setText(tr("Run"));
    m_refresh->setText(tr("Refresh"));
    updateRecordButton();
    m_runOne->setToolTip(tr("Runs the selected scenario"));
    m_tree->setHeaderLabels({tr("Scenario / expectation"), tr("Result")});
    const bool saved = !m_document->path().isEmpty();
    m_unsavedHint->setText(tr("Save the project: its scenario tests (.rungtest) are the files "
                              "beside it that name it"));
    m_unsavedHint->setVisible(!saved);
    m_folder->setFullText(
        saved ? tr("Scenario tests (.rungtest) that name this project, in %1 and below")
                    .arg(QDir::toNativeSeparators(QFileInfo(m_document->path()).absolutePath()))
              : QString());
    m_folder->setVisible(saved);
}

void TestsPanel::refresh() {
    m_files.clear();
    const QString project = m_document->path();
    if (!project.isEmpty()) {
        const QString self = canonical(project);
        QDirIterator it(QFileInfo(project).absolutePath(), {QStringLiteral("*.rungtest")},
                        QDir::Files, QDirIterator::Subdirectories);
        while (it.hasNext()) {
            const QString file = it.next();
            QByteArray bytes;
            QString error;
            if (model::readAtMost(file, kMaxScenarioBytes, &bytes, &error) != model::ReadStatus::Ok)
                continue;
            std::vector<simulator::ScenarioError> errors;
            const simulator::Scenario s =
                simulator::parseScenario(QString::fromUtf8(bytes), file, &errors);
            const QString program = QFileInfo(s.program).isAbsolute()
                                        ? s.program
                                        : QFileInfo(file).dir().filePath(s.program);
            // The project's own, or one that does not read (shown, so its errors are seen).
            if (s.program.isEmpty() || canonical(program) == self)
                m_files << file;
        }
        m_files.sort();
    }
    m_results.erase(std::remove_if(m_results.begin(), m_results.end(),
                                   [this](const simulator::ScenarioResult &r) {
                                       return !m_files.contains(r.file);
                                   }),
                    m_results.end());
    retranslate();
    showResults();
}

QString TestsPanel::programOf(const QString &scenarioFile, QString *targetId, QString *error) {
    QByteArray bytes;
    QString ioError;
    if (const model::ReadStatus status =
            model::readAtMost(scenarioFile, kMaxScenarioBytes, &bytes, &ioError);
        status != model::ReadStatus::Ok) {
        *error = model::readFailure(status, scenarioFile, kMaxScenarioBytes, ioError);
        return {};
    }
    std::vector<simulator::ScenarioError> errors;
    const simulator::Scenario s =
        simulator::parseScenario(QString::fromUtf8(bytes), scenarioFile, &errors);
    if (s.program.isEmpty()) {
        *error = tr("%1 names no program: its first statement is `program FILE`")
                     .arg(QDir::toNativeSeparators(scenarioFile));
        return {};
    }
    if (targetId)
        *targetId = s.target;
    return QFileInfo(s.program).isAbsolute() ? s.program
                                             : QFileInfo(scenarioFile).dir().filePath(s.program);
}

bool TestsPanel::select(const QString &file) {
    refresh();
    const QString wanted = canonical(file);
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i) {
        QTreeWidgetItem *item = m_tree->topLevelItem(i);
        if (canonical(item->data(0, FileRole).toString()) == wanted) {
            m_tree->setCurrentItem(item);
            return true;
        }
    }
    return false;
}

simulator::ScenarioProgram TestsPanel::documentProgram() const {
    simulator::ScenarioProgram out;
    std::vector<model::Diagnostic> errors;
    for (const model::Diagnostic &d : m_document->listing().problems)
        if (d.severity == model::Severity::Error)
            errors.push_back(d);
    if (errors.empty())
        for (const model::Diagnostic &d : m_document->diagnostics())
            if (d.severity == model::Severity::Error)
                errors.push_back(d);
    model::CheckOptions options;
    options.model = m_document->modelVariant();
    if (errors.empty()) {
        const simulator::CompileResult compiled =
            simulator::prepareProgram(m_document->listing().list, options);
        for (const model::Diagnostic &d : compiled.diagnostics)
            if (d.severity == model::Severity::Error)
                errors.push_back(d);
        out.program = compiled.program;
    }
    for (const model::Diagnostic &d : errors)
        out.errors << tr("the open program has errors: %1").arg(d.message);
    if (!errors.empty())
        out.program.reset();
    return out;
}

void TestsPanel::run(const QStringList &files) {
    if (running())
        return;
    join();
    const QStringList todo = files.isEmpty() ? m_files : files;
    if (todo.isEmpty()) {
        emit message(tr("No scenario test names this project"));
        return;
    }
    // The program as it is in the window (unsaved edits too), compiled here: the worker gets
    // an immutable program and file names, nothing of the window.
    const simulator::ScenarioProgram open = documentProgram();
    const QString self = canonical(m_document->path());
    const model::Target *target = &m_document->target();
    m_done = false;
    for (QToolButton *b : {m_runAll, m_runOne})
        b->setEnabled(false);
    m_worker = std::thread([this, todo, open, self, target] {
        std::vector<simulator::ScenarioResult> results;
        for (const QString &file : todo) {
            QByteArray bytes;
            QString error;
            if (const model::ReadStatus status =
                    model::readAtMost(file, kMaxScenarioBytes, &bytes, &error);
                status != model::ReadStatus::Ok) {
                simulator::ScenarioResult r;
                r.file = file;
                r.errors.push_back({0, model::readFailure(status, file, kMaxScenarioBytes, error)});
                results.push_back(r);
                continue;
            }
            results.push_back(simulator::runScenario(
                QString::fromUtf8(bytes), file,
                [&](const QString &path, const QString &targetId, const QString &) {
                    if (canonical(path) == self)
                        return open;
                    return programFromFile(path, targetId, *target);
                }));
        }
        QMetaObject::invokeMethod(
            this,
            [this, results = std::move(results)]() mutable {
                for (simulator::ScenarioResult &r : results) {
                    const auto same = std::find_if(
                        m_results.begin(), m_results.end(),
                        [&r](const simulator::ScenarioResult &o) { return o.file == r.file; });
                    if (same != m_results.end())
                        *same = std::move(r);
                    else
                        m_results.push_back(std::move(r));
                }
                m_done = true;
                join();
                for (QToolButton *b : {m_runAll, m_runOne})
                    b->setEnabled(true);
                showResults();
                emit runFinished();
            },
            Qt::QueuedConnection);
    });
}

void TestsPanel::showResults() {
    m_tree->clear();
    int passed = 0;
    int failed = 0;
    for (const QString &file : m_files) {
        auto *top = new QTreeWidgetItem(m_tree);
        top->setText(0, QFileInfo(file).fileName());
        top->setToolTip(0, QDir::toNativeSeparators(file));
        top->setData(0, FileRole, file);
        const auto r =
            std::find_if(m_results.begin(), m_results.end(),
                         [&file](const simulator::ScenarioResult &x) { return x.file == file; });
        if (r == m_results.end()) {
            top->setText(1, tr("not run"));
            continue;
        }
        // Words first: the colour only adds to them.
        const QColor red(0xb0, 0x00, 0x20);
        const QColor green(0x00, 0x6d, 0x2c);
        if (r->passed()) {
            ++passed;
            top->setText(1, tr("passed: %n expectation(s)", nullptr,
                               static_cast<int>(r->expectations.size())));
            top->setForeground(1, green);
        } else {
            ++failed;
            top->setText(1, r->ran ? tr("FAILED: %n expectation(s)", nullptr,
                                        static_cast<int>(r->failures.size()))
                                   : tr("did not run"));
            top->setForeground(1, red);
            top->setExpanded(true);
        }
        for (const simulator::ScenarioError &e : r->errors) {
            auto *item = new QTreeWidgetItem(top);
            item->setText(0, tr("line %1").arg(e.line));
            item->setText(1, tr("error: %1").arg(e.message));
            item->setForeground(1, red);
        }
        for (const simulator::ScenarioResult::Expectation &x : r->expectations) {
            auto *item = new QTreeWidgetItem(top);
            item->setText(0, tr("line %1: %2").arg(x.line).arg(x.statement));
            const auto f = std::find_if(
                r->failures.begin(), r->failures.end(),
                [&x](const simulator::ScenarioFailure &y) { return y.line == x.line; });
            if (f == r->failures.end()) {
                item->setText(1, tr("ok"));
                item->setForeground(1, green);
            } else {
                item->setText(1, tr("FAILED: %1 (double-click: the timing chart)").arg(f->message));
                item->setForeground(1, red);
                item->setData(0, FailureRole,
                              QVariant::fromValue<qulonglong>(
                                  static_cast<qulonglong>(f - r->failures.begin())));
            }
            item->setToolTip(1, item->text(1));
        }
    }
    if (!m_results.empty())
        emit message(tr("Scenario tests: %1 passed, %2 failed").arg(passed).arg(failed));
}

void TestsPanel::showFailure(const QString &file, std::size_t index) {
    const auto r =
        std::find_if(m_results.begin(), m_results.end(),
                     [&file](const simulator::ScenarioResult &x) { return x.file == file; });
    if (r == m_results.end() || index >= r->failures.size())
        return;
    const simulator::ScenarioFailure failure = r->failures[index];
    QByteArray bytes;
    QString error;
    if (model::readAtMost(file, kMaxScenarioBytes, &bytes, &error) != model::ReadStatus::Ok)
        return;
    std::vector<simulator::ScenarioError> errors;
    const simulator::Scenario scenario =
        simulator::parseScenario(QString::fromUtf8(bytes), file, &errors);
    const simulator::ScenarioProgram program = documentProgram();
    if (!program.program) {
        emit message(program.errors.value(0));
        return;
    }
    // The run again, recording the devices of the expectation, in a chart of its own: the
    // window's chart keeps showing the simulation.
    QDialog dialog(this);
    dialog.setWindowTitle(
        tr("Timing chart of %1, line %2").arg(QFileInfo(file).fileName()).arg(failure.line));
    auto *layout = new QVBoxLayout(&dialog);
    auto *what = new QLabel(tr("line %1: %2").arg(failure.line).arg(failure.message));
    what->setWordWrap(true);
    layout->addWidget(what);
    auto *trace = new simulator::ScenarioTrace(scenario, program.program, failure.devices, &dialog);
    auto *chart = new editor::TimingChart(m_document);
    chart->setMonitorSource(trace);
    QStringList devices;
    for (const model::Address &a : failure.devices)
        devices << model::formatAddress(m_document->target(), a);
    chart->addDevices(devices);
    layout->addWidget(chart, 1);
    auto *close = new QDialogButtonBox(QDialogButtonBox::Close);
    connect(close, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    layout->addWidget(close);
    dialog.resize(1100, 520);
    fitTitle(&dialog);
    chart->centreOn(failure.timeMs);
    chart->placeCursor(0, failure.timeMs);
    dialog.exec();
}

} // namespace rung::app
