#include "simulation_controller.h"

#include "editor/document.h"
#include "model/target/address.h"
#include "simulator/compiler.h"
#include "simulator/history_source.h"
#include "simulator/online_edit.h"
#include "simulator/session.h"

#include <QSettings>

#include <algorithm>

namespace rung::app {

namespace {

bool sameProgram(const std::vector<model::Instruction> &a,
                 const std::vector<model::Instruction> &b) {
    return std::equal(
        a.begin(), a.end(), b.begin(), b.end(),
        [](const model::Instruction &x, const model::Instruction &y) { return x.sameAs(y); });
}

} // namespace

// Virtual time as hours:minutes:seconds.hundredths; the same in every language.
QString SimulationController::clockText(qint64 ms) {
    const qint64 hundredths = ms / 10;
    return QStringLiteral("%1:%2:%3.%4")
        .arg(hundredths / 360000)
        .arg(hundredths / 6000 % 60, 2, 10, QLatin1Char('0'))
        .arg(hundredths / 100 % 60, 2, 10, QLatin1Char('0'))
        .arg(hundredths % 100, 2, 10, QLatin1Char('0'));
}

namespace {

// Numbers as the rest of the window writes them (step counts, times): no group separators,
// whatever the system's locale, so the status reads the same in every language.
QString microseconds(qint64 ns) {
    return QString::number(static_cast<double>(ns) / 1000.0, 'f', 1);
}

std::vector<model::Diagnostic> onlyErrors(std::vector<model::Diagnostic> all) {
    std::erase_if(all,
                  [](const model::Diagnostic &d) { return d.severity != model::Severity::Error; });
    return all;
}

} // namespace

SimulationController::SimulationController(editor::Document *document, QObject *parent)
    : QObject(parent)
    , m_document(document)
    , m_speed(QSettings().value(QStringLiteral("simulation/speed"), 1.0).toDouble())
    , m_periodMs(std::max<qint64>(
          1, QSettings().value(QStringLiteral("simulation/periodMs"), 10).toLongLong())) {
    connect(document, &editor::Document::programChanged, this,
            &SimulationController::programChanged);
}

SimulationController::~SimulationController() {
    // The history reads the session's record: it goes first.
    m_historySource.reset();
}

model::MonitorSource *SimulationController::monitorSource() const {
    if (m_historySource)
        return m_historySource.get();
    return m_session.get();
}

model::MonitorSource::RunState SimulationController::runState() const {
    return m_session ? m_session->runState() : model::MonitorSource::RunState::Offline;
}

bool SimulationController::ensureSession() {
    if (m_session)
        return true;
    if (const QString why = m_blocker ? m_blocker() : QString(); !why.isEmpty()) {
        emit message(why);
        return false;
    }
    model::CheckOptions options;
    options.model = m_document->modelVariant();
    const model::InstructionList &list = m_document->listing().list;
    // What the ladder holds but the list cannot express is not in the list: simulating the
    // list would run less than the drawing shows. The checks' errors on the drawing come
    // next: they name rungs and cells. Then what only the compiler finds.
    std::vector<model::Diagnostic> errors = onlyErrors(m_document->listing().problems);
    if (errors.empty())
        errors = onlyErrors(m_document->diagnostics());
    simulator::CompileResult compiled;
    if (errors.empty()) {
        compiled = simulator::prepareProgram(list, options);
        errors = onlyErrors(compiled.diagnostics);
    }
    if (!compiled.ok()) {
        emit problems(errors);
        emit message(tr("The program has %n error(s): the simulation does not start; the "
                        "Problems list shows them",
                        nullptr, static_cast<int>(errors.size())));
        return false;
    }
    m_session = std::make_unique<simulator::SimulatorSession>(compiled.program);
    m_running = list.instructions;
    m_runningProgram = compiled.program;
    m_stale = false;
    sendBreakpoints();
    m_session->setSpeed(m_speed);
    m_session->setPeriodMs(m_periodMs);
    connect(m_session.get(), &model::MonitorSource::snapshotChanged, this,
            &SimulationController::statusChanged);
    connect(m_session.get(), &model::MonitorSource::runStateChanged, this,
            &SimulationController::statusChanged);
    connect(m_session.get(), &model::MonitorSource::snapshotChanged, this,
            &SimulationController::watchStoppedAt);
    connect(m_session.get(), &model::MonitorSource::runStateChanged, this,
            &SimulationController::watchStoppedAt);
    connect(m_session.get(), &model::MonitorSource::errorTextChanged, this,
            [this](const QString &text) {
                if (!text.isEmpty())
                    emit message(text);
            });
    // "Not simulated" warnings: the program runs, but the user hears what it skips.
    for (const model::Diagnostic &d : compiled.diagnostics)
        if (d.severity == model::Severity::Warning) {
            emit message(d.message);
            break;
        }
    emit sessionChanged(m_session.get());
    emit monitorSourceChanged(monitorSource());
    emit statusChanged();
    return true;
}

void SimulationController::dropSession() {
    if (!m_session)
        return;
    returnToLive();
    // Readers let go first: they hold the session as their source.
    emit sessionChanged(nullptr);
    emit monitorSourceChanged(nullptr);
    m_session.reset();
    m_running.clear();
    m_runningProgram.reset();
    m_stale = false;
    if (m_stoppedAt >= 0) {
        m_stoppedAt = -1;
        emit stoppedAtChanged(-1);
    }
    emit statusChanged();
}

// An edit while simulating is an online edit (the vendors' "online change"): the edited
// program takes over at the next scan boundary with the image kept. What cannot keep things
// as they are asks first; the status bar says what happened.
void SimulationController::programChanged() {
    if (!m_session || sameProgram(m_running, m_document->listing().list.instructions)) {
        emit breakpointsChanged(); // the rungs may have moved under the breakpoints
        return;                    // symbols, watch lists or comments changed, not what runs
    }
    using State = model::MonitorSource::RunState;
    const State state = runState();
    if (state == State::Stopped) { // nothing to keep: Run compiles the edited program
        dropSession();
        emit breakpointsChanged();
        return;
    }
    const bool wasRunning = state == State::Running;
    model::CheckOptions options;
    options.model = m_document->modelVariant();
    std::vector<model::Diagnostic> errors = onlyErrors(m_document->listing().problems);
    if (errors.empty())
        errors = onlyErrors(m_document->diagnostics());
    simulator::CompileResult compiled;
    if (errors.empty())
        compiled = simulator::prepareProgram(m_document->listing().list, options);
    if (!compiled.ok()) {
        // A PLC refuses an online edit with errors and goes on with its program: so does the
        // simulation, and it says so until the program is corrected or the simulation stops.
        m_stale = true;
        emit message(tr("The edited program has errors: the simulation goes on with the "
                        "program before the edit (stop it to simulate what is shown)"));
        emit breakpointsChanged();
        emit statusChanged();
        return;
    }
    const simulator::EditImpact impact =
        simulator::assessEdit(*m_runningProgram, *compiled.program);
    EditChoice choice = EditChoice::KeepImage;
    if (impact.layoutDiffers || impact.changesElements())
        choice = m_asker ? m_asker(editQuestion(impact), impact.keepsImage())
                         : (impact.keepsImage() ? EditChoice::KeepImage : EditChoice::Restart);
    if (choice == EditChoice::KeepImage && !impact.keepsImage())
        choice = EditChoice::Restart;
    if (choice == EditChoice::StopSimulation) {
        dropSession();
        emit breakpointsChanged();
        emit message(tr("The program was edited: the simulation stopped. Run starts the edited "
                        "program from power-on"));
        return;
    }
    if (choice == EditChoice::Restart) {
        dropSession();
        emit breakpointsChanged();
        if (wasRunning ? run() : singleScan())
            emit message(tr("Online edit: the edited program restarted from power-on"));
        return;
    }
    returnToLive();
    const bool insideScan = [this] {
        const auto s = m_session->snapshot();
        return s && s->pause.has_value();
    }();
    m_running = m_document->listing().list.instructions;
    m_runningProgram = compiled.program;
    m_stale = false;
    m_session->replaceProgram(compiled.program, engineBreakpoints());
    emit breakpointsChanged();
    emit message(insideScan ? tr("Online edit: the edited program takes over when the stopped "
                                 "scan ends; the memory is kept")
                            : tr("Online edit: the edited program runs from the next scan on; "
                                 "the memory is kept"));
    emit statusChanged();
}

QString SimulationController::editQuestion(const simulator::EditImpact &impact) const {
    if (impact.layoutDiffers)
        return tr("The edited program is for another memory layout: the running memory "
                  "cannot be kept. Restart it from power-on, or stop the simulation?");
    const model::Target &t = m_document->target();
    auto names = [&t](const std::vector<model::Address> &elements) {
        QStringList list;
        for (const model::Address &a : elements)
            list << model::formatAddress(t, a);
        return list.join(QStringLiteral(", "));
    };
    QStringList parts;
    if (!impact.elementsGone.empty())
        parts << tr("no longer uses %1 (their values stay as they are)")
                     .arg(names(impact.elementsGone));
    if (!impact.elementsNew.empty())
        parts << tr("now uses %1 (they start from the values the memory holds)")
                     .arg(names(impact.elementsNew));
    //: %1 what changed, e.g. "no longer uses T0 (...); now uses T5 (...)"
    return tr("The edited program %1. Apply it keeping the memory, restart it from power-on, "
              "or stop the simulation?")
        .arg(parts.join(QStringLiteral("; ")));
}

bool SimulationController::run() {
    returnToLive(); // what runs is what the views show
    if (!ensureSession())
        return false;
    m_session->run();
    return true;
}

void SimulationController::pause() {
    if (m_session)
        m_session->pause();
}

void SimulationController::stop() {
    returnToLive(); // the history starts afresh: the past it showed is gone
    if (m_session)
        m_session->stop();
}

bool SimulationController::singleScan() {
    returnToLive(); // what runs is what the views show
    if (!ensureSession())
        return false;
    m_session->singleScan();
    return true;
}

bool SimulationController::powerCycle() {
    if (!ensureSession())
        return false;
    m_session->powerCycle();
    return true;
}

bool SimulationController::runScans(quint64 count) {
    returnToLive(); // what runs is what the views show
    if (count == 0 || !ensureSession())
        return false;
    m_session->runScans(count);
    return true;
}

bool SimulationController::runFor(qint64 durationMs) {
    returnToLive(); // what runs is what the views show
    if (durationMs <= 0 || !ensureSession())
        return false;
    m_session->runFor(durationMs);
    return true;
}

void SimulationController::setSpeed(double factor) {
    m_speed = factor > 0 ? factor : 0.0;
    QSettings().setValue(QStringLiteral("simulation/speed"), m_speed);
    if (m_session)
        m_session->setSpeed(m_speed);
    emit statusChanged();
}

void SimulationController::setPeriodMs(qint64 periodMs) {
    m_periodMs = std::max<qint64>(1, periodMs);
    QSettings().setValue(QStringLiteral("simulation/periodMs"), m_periodMs);
    if (m_session)
        m_session->setPeriodMs(m_periodMs);
    emit statusChanged();
}

void SimulationController::releaseAll() {
    if (m_session)
        m_session->releaseAll();
}

QString SimulationController::statusText() const {
    if (!m_session)
        return statusText(model::MonitorSource::RunState::Offline, m_speed, nullptr);
    const std::shared_ptr<const model::Snapshot> snapshot = m_session->snapshot();
    QString text = statusText(m_session->runState(), m_speed, snapshot.get());
    if (m_stale)
        text += tr(" | the program before the edit");
    return text;
}

QString SimulationController::statusText(model::MonitorSource::RunState state, double speed,
                                         const model::Snapshot *snapshot) {
    using State = model::MonitorSource::RunState;
    QString what;
    switch (state) {
    case State::Offline:
        return tr("Simulation off");
    case State::Stopped:
        what = tr("Stopped");
        break;
    case State::Paused:
        what = tr("Paused");
        break;
    case State::Running:
        what = speed > 0 ? tr("Running x%1").arg(speed) : tr("Running at full speed");
        break;
    case State::Stepping:
        what = tr("Stepping");
        break;
    }
    if (!snapshot)
        return what;
    const model::ScanStatistics &s = snapshot->statistics;
    // The evaluation figures are the status line's tooltip and the Simulation dock's: beside
    // the history's and the origin's marks they were cut in every language (issue 31).
    //: %1 run state, %2 simulated time h:mm:ss.cc, %3 scans, %4 scan period in ms
    return tr("%1 | %2 | %3 scans | scan %4 ms")
        .arg(what, clockText(s.timeMs), QString::number(s.scans))
        .arg(s.periodMs);
}

QString SimulationController::evaluationText(const model::Snapshot *snapshot) {
    if (!snapshot)
        return {};
    const model::ScanStatistics &s = snapshot->statistics;
    //: the time the last scan took to evaluate on this computer: current, minimum, maximum
    return tr("Evaluation of a scan on this computer: %1 µs (%2..%3)")
        .arg(microseconds(s.execNsCurrent), microseconds(s.execNsMin), microseconds(s.execNsMax));
}

QString SimulationController::statusToolTip() const {
    const std::shared_ptr<const model::Snapshot> snapshot =
        m_session ? m_session->snapshot() : nullptr;
    const QString evaluation = evaluationText(snapshot.get());
    return evaluation.isEmpty() ? statusText() : statusText() + QLatin1Char('\n') + evaluation;
}

} // namespace rung::app
