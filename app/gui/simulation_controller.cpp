#include "simulation_controller.h"

#include "editor/document.h"
#include "simulator/compiler.h"
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

// Virtual time as hours:minutes:seconds.hundredths; the same in every language.
QString clockText(qint64 ms) {
    const qint64 hundredths = ms / 10;
    return QStringLiteral("%1:%2:%3.%4")
        .arg(hundredths / 360000)
        .arg(hundredths / 6000 % 60, 2, 10, QLatin1Char('0'))
        .arg(hundredths / 100 % 60, 2, 10, QLatin1Char('0'))
        .arg(hundredths % 100, 2, 10, QLatin1Char('0'));
}

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

SimulationController::~SimulationController() = default;

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
    m_session->setSpeed(m_speed);
    m_session->setPeriodMs(m_periodMs);
    connect(m_session.get(), &model::MonitorSource::snapshotChanged, this,
            &SimulationController::statusChanged);
    connect(m_session.get(), &model::MonitorSource::runStateChanged, this,
            &SimulationController::statusChanged);
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
    emit statusChanged();
    return true;
}

void SimulationController::dropSession() {
    if (!m_session)
        return;
    // Readers let go first: they hold the session as their source.
    emit sessionChanged(nullptr);
    m_session.reset();
    m_running.clear();
    emit statusChanged();
}

void SimulationController::programChanged() {
    if (!m_session || sameProgram(m_running, m_document->listing().list.instructions))
        return; // symbols, watch lists or comments changed, not what runs
    const bool active = runState() != model::MonitorSource::RunState::Stopped;
    dropSession();
    if (active)
        emit message(tr("The program was edited: the simulation stopped. Run starts the edited "
                        "program from power-on"));
}

bool SimulationController::run() {
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
    if (m_session)
        m_session->stop();
}

bool SimulationController::singleScan() {
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
    return statusText(m_session->runState(), m_speed, snapshot.get());
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
    //: %1 run state, %2 simulated time h:mm:ss.cc, %3 scans, %4 scan period in ms,
    //: %5 %6 %7 time the last scan took to evaluate: current, minimum, maximum, in µs
    return tr("%1 | %2 | %3 scans | scan %4 ms | evaluation %5 µs (%6..%7)")
        .arg(what, clockText(s.timeMs), QString::number(s.scans))
        .arg(s.periodMs)
        .arg(microseconds(s.execNsCurrent), microseconds(s.execNsMin), microseconds(s.execNsMax));
}

} // namespace rung::app
