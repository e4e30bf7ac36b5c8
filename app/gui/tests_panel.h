#pragma once

// The Tests dock (docs/scenario-tests.md): the project's scenario tests (the .rungtest files in
// its folder and below whose `program` is this project), run one or all on a worker thread
// against the program as it is in the window (unsaved edits too); each expectation passed or
// failed, in words and colour. A failed one opens the timing chart of the run at its instant
// with the devices it names. Record... writes a scenario from the simulation's history.

#include "model/image/monitor_source.h"
#include "simulator/scan_history.h"
#include "simulator/scenario.h"

#include <QPointer>
#include <QWidget>

#include <atomic>

#include <functional>
#include <memory>
#include <thread>

class QLabel;
class QToolButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace rung::editor {
class Document;
}

namespace rung::app {

class ElidingLabel;

class TestsPanel : public QWidget {
    Q_OBJECT

public:
    explicit TestsPanel(editor::Document *document, QWidget *parent = nullptr);
    ~TestsPanel() override; // waits for a run under way

    // The scenarios found beside the project (absolute paths), in name order.
    QStringList scenarios() const { return m_files; }
    // The program a scenario file names, resolved against the file's folder, and the target
    // its `program` line gives (may be empty); empty with *error set when the file does not
    // read or names no program.
    static QString programOf(const QString &scenarioFile, QString *targetId, QString *error);
    // Looks for the project's scenarios again and makes `file` the current one; false when it
    // is not among them (it names another program).
    bool select(const QString &file);
    // Looks for them again (the project was saved elsewhere, a file was added).
    void refresh();
    // Runs these (all when empty); runFinished() follows on this thread.
    void run(const QStringList &files = {});
    bool running() const { return m_worker.joinable() && !m_done; }
    const std::vector<simulator::ScenarioResult> &results() const { return m_results; }
    QTreeWidget *tree() const { return m_tree; }
    // Opens the chart of a failed expectation (the result of `file`, its failure `index`).
    void showFailure(const QString &file, std::size_t index);

    // Where the simulation's record comes from, for Record... (the main window's simulation;
    // null while none runs).
    using HistoryGetter = std::function<std::shared_ptr<const simulator::ScanHistory>()>;
    void setHistory(HistoryGetter history) { m_history = std::move(history); }
    // The online PLC while the IDE is online (null otherwise): Record... then records what it
    // does until Stop Recording... (tests_panel_record.cpp).
    using SourceGetter = std::function<model::MonitorSource *()>;
    void setOnlineSource(SourceGetter source) { m_onlineSource = std::move(source); }
    void record();
    // Online: starts recording the PLC's inputs and outputs (those the program names), read
    // at every refresh; false with *error when not online or the program names none.
    bool startOnlineRecording(QString *error);
    bool recordingOnline() const;
    // The PLC's session is about to go (Go Offline, the connection closed): what it recorded
    // is kept, and Stop Recording... still writes it.
    void keepOnlineRecording();
    void stopOnlineRecording(); // forgets what was recorded
    // The scenario Record... writes to `path` (the program named relative to it): of the
    // online recording while one runs, else of the simulation; empty with *error; *notes says
    // what it holds otherwise than the run.
    QString recordedText(const QString &path, QString *error, QStringList *notes) const;
    // What the message box says after writing a recording: the file, then what the scenario
    // does not hold, a sentence each.
    static QString recordingNotes(const QString &path, const QStringList &notes);

signals:
    void runFinished();
    void message(const QString &text);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void updateRecordButton(); // Record... or Stop Recording..., with its tooltip
    QString programLine(const QString &path) const; // the program, relative to `path`
    void showResults();
    // The program as it is in the window, compiled, or why not.
    simulator::ScenarioProgram documentProgram() const;
    void join();

    editor::Document *m_document;
    // The folder searched, elided to the dock's width (whole in its tooltip); before the
    // project is saved, a wrapped hint instead. Neither may widen the dock: it is a tab beside
    // the timing chart, and its minimum width is the window's on a small screen.
    ElidingLabel *m_folder;
    QLabel *m_unsavedHint;
    QTreeWidget *m_tree;
    QToolButton *m_runAll;
    QToolButton *m_runOne;
    QToolButton *m_refresh;
    QToolButton *m_record;
    QStringList m_files;
    std::vector<simulator::ScenarioResult> m_results;
    std::thread m_worker;
    std::atomic<bool> m_done{true};
    HistoryGetter m_history;
    SourceGetter m_onlineSource;
    // The online recording: from the session's time m_recordingFrom (-1: none).
    QPointer<model::MonitorSource> m_recordSource;
    std::unique_ptr<model::HistoryRecorder> m_recordKept; // after the session went
    qint64 m_recordingFrom = -1;
    qint64 m_recordingTo = -1; // when kept: the session's last time
    std::vector<model::Address> m_recordInputs;
    std::vector<model::Address> m_recordOutputs;
    QObject m_recordReader; // what the recording watches, as a reader of the source
};

} // namespace rung::app
