// Tests > Record...: a scenario from the simulation's history, or from an online PLC between
// Record... and Stop Recording... (docs/scenario-tests.md "Recording").

#include "tests_panel.h"

#include "dialogs.h"
#include "file_dialogs.h"

#include "editor/document.h"

#include "simulator/scenario_record.h"

#include <QDir>
#include <QFileInfo>
#include <QMessageBox>
#include <QSaveFile>
#include <QToolButton>

#include <algorithm>

namespace rung::app {

namespace {

// The program's physical bits of one direction, as its instructions name them: the outputs
// its coils drive (writable) or the inputs its contacts read.
std::vector<model::Address> physicalBits(const editor::Document &document, bool outputs) {
    const model::Target &t = document.target();
    std::vector<model::Address> out;
    for (const model::Instruction &ins : document.listing().list.instructions) {
        if (model::isOutput(ins.op()) != outputs)
            continue;
        for (const model::Operand &o : ins.operands) {
            if (o.kind != model::Operand::Kind::Device || o.modified())
                continue;
            const model::Area &area = t.area(o.address.area);
            const bool bit = area.kind == model::AreaKind::Bit || o.address.bit >= 0;
            if (area.physical && area.writable == outputs && bit &&
                std::find(out.begin(), out.end(), o.address) == out.end())
                out.push_back(o.address);
            if (outputs)
                break; // a coil's device; its other operands are no outputs
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace

bool TestsPanel::recordingOnline() const {
    return m_recordingFrom >= 0 && (m_recordSource || m_recordKept);
}

void TestsPanel::keepOnlineRecording() {
    if (m_recordingFrom < 0 || !m_recordSource)
        return;
    const auto snapshot = m_recordSource->snapshot();
    m_recordingTo = snapshot ? snapshot->statistics.timeMs : m_recordingFrom;
    m_recordSource->readHistory([this](const model::HistoryRecorder &history) {
        m_recordKept = std::make_unique<model::HistoryRecorder>(history);
    });
    m_recordSource->setWatched(&m_recordReader, {});
    m_recordSource = nullptr;
    emit message(tr("Offline: the recording ends here; Stop Recording... writes it"));
}

void TestsPanel::updateRecordButton() {
    const bool on = recordingOnline();
    m_record->setText(on ? tr("Stop Recording...") : tr("Record..."));
    m_record->setToolTip(
        on ? tr("Writes the scenario of what the PLC did since Record...: its inputs and "
                "outputs as each refresh read them")
           : tr("Writes a scenario of the simulation so far: the inputs as you worked them, the "
                "outputs as they were seen; online, records what the PLC's inputs and outputs "
                "do until Stop Recording..."));
}

bool TestsPanel::startOnlineRecording(QString *error) {
    model::MonitorSource *source = m_onlineSource ? m_onlineSource() : nullptr;
    if (!source) {
        *error = tr("Not online: go online to record what a PLC does");
        return false;
    }
    m_recordInputs = physicalBits(*m_document, false);
    m_recordOutputs = physicalBits(*m_document, true);
    std::vector<model::Address> devices = m_recordInputs;
    devices.insert(devices.end(), m_recordOutputs.begin(), m_recordOutputs.end());
    if (devices.empty()) {
        *error = tr("The program reads no input and drives no output: nothing to record");
        return false;
    }
    for (const model::Address &a : devices)
        if (!source->watchHistory(a)) {
            *error = tr("This PLC's session keeps no history: it cannot be recorded");
            return false;
        }
    // Read at every refresh while recording, whatever the views show.
    source->setWatched(&m_recordReader, devices);
    const auto snapshot = source->snapshot();
    m_recordingFrom = snapshot ? snapshot->statistics.timeMs : 0;
    m_recordSource = source;
    updateRecordButton();
    emit message(tr("Recording the PLC's inputs and outputs: Stop Recording... writes the "
                    "scenario"));
    return true;
}

void TestsPanel::stopOnlineRecording() {
    if (m_recordSource)
        m_recordSource->setWatched(&m_recordReader, {});
    m_recordSource = nullptr;
    m_recordKept.reset();
    m_recordingFrom = -1;
    m_recordingTo = -1;
    updateRecordButton();
}

QString TestsPanel::programLine(const QString &path) const {
    const QString program =
        QFileInfo(path).dir().relativeFilePath(QFileInfo(m_document->path()).absoluteFilePath());
    return program.contains(QLatin1Char(' ')) ? QLatin1Char('"') + program + QLatin1Char('"')
                                              : program;
}

QString TestsPanel::recordedText(const QString &path, QString *error, QStringList *notes) const {
    const model::Target &t = m_document->target();
    if (recordingOnline()) {
        std::optional<simulator::RecordedScenario> recorded;
        const auto write = [&](const model::HistoryRecorder &history, qint64 to) {
            recorded = simulator::recordObservedScenario(
                history, t, programLine(path), m_recordInputs, m_recordOutputs, m_recordingFrom, to,
                model::ScanStatistics{}.periodMs, error); // the engine's period
        };
        if (m_recordKept) {
            write(*m_recordKept, m_recordingTo);
        } else {
            const auto snapshot = m_recordSource->snapshot();
            const qint64 to = snapshot ? snapshot->statistics.timeMs : m_recordingFrom;
            m_recordSource->readHistory(
                [&](const model::HistoryRecorder &history) { write(history, to); });
        }
        if (!recorded)
            return {};
        *notes = recorded->notes;
        return recorded->text;
    }
    const auto history = m_history ? m_history() : nullptr;
    if (!history) {
        *error = tr("Nothing to record: start a simulation and work its inputs first");
        return {};
    }
    // The outputs the program drives: the expectations.
    const auto recorded = simulator::recordScenario(*history, t, programLine(path),
                                                    physicalBits(*m_document, true), error);
    if (!recorded)
        return {};
    *notes = recorded->notes;
    return recorded->text;
}

void TestsPanel::record() {
    const QString project = m_document->path();
    if (project.isEmpty()) {
        messageBox(QMessageBox::Information, this, tr("Record a Scenario"),
                   tr("Save the project first: a scenario names the project's file."));
        return;
    }
    QString error;
    // Online, the first Record... starts recording what the PLC does; the second writes it.
    if (!recordingOnline() && m_onlineSource && m_onlineSource()) {
        if (!startOnlineRecording(&error))
            messageBox(QMessageBox::Information, this, tr("Record a Scenario"), error);
        return;
    }
    QStringList notes;
    // Asked first, so that a simulation that has nothing to record says so before a file is
    // chosen for nothing.
    if (recordedText(project, &error, &notes).isEmpty()) {
        messageBox(QMessageBox::Information, this, tr("Record a Scenario"), error);
        stopOnlineRecording();
        return;
    }
    QString path = askSaveFile(this, tr("Record a Scenario"), QFileInfo(project).absolutePath(),
                               tr("Scenario tests (*.rungtest)"));
    if (path.isEmpty())
        return; // online, still recording: Stop Recording... again writes it
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".rungtest");
    const QString text = recordedText(path, &error, &notes);
    stopOnlineRecording();
    if (text.isEmpty()) {
        messageBox(QMessageBox::Warning, this, tr("Record a Scenario"), error);
        return;
    }
    QSaveFile out(path);
    const QByteArray bytes = text.toUtf8();
    if (!out.open(QIODevice::WriteOnly) || out.write(bytes) != bytes.size() || !out.commit()) {
        messageBox(QMessageBox::Critical, this, tr("Record a Scenario"),
                   QStringLiteral("%1: %2").arg(QDir::toNativeSeparators(path), out.errorString()));
        return;
    }
    if (!notes.isEmpty())
        messageBox(QMessageBox::Information, this, tr("Record a Scenario"),
                   recordingNotes(path, notes));
    refresh();
    emit message(tr("Recorded %1").arg(QDir::toNativeSeparators(path)));
}

QString TestsPanel::recordingNotes(const QString &path, const QStringList &notes) {
    QStringList lines{tr("%1 is written. What it does not hold:").arg(QFileInfo(path).fileName())};
    for (QString note : notes) {
        // The notes are also the scenario's comments, which begin in lower case.
        if (!note.isEmpty())
            note[0] = note[0].toUpper();
        lines << QStringLiteral("\u2022 ") + note;
    }
    return lines.join(QLatin1Char('\n'));
}

} // namespace rung::app
