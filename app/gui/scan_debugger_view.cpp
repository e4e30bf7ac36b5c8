#include "scan_debugger_view.h"

#include "scan_debug_subject.h"
#include "simulation_controller.h"

#include "editor/document.h"
#include "simulator/session.h"

#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace rung::app {

namespace {

QString onOff(bool on) {
    return on ? ScanDebuggerView::tr("ON") : ScanDebuggerView::tr("OFF");
}

// A stack as list rows, top first (as a debugger shows a call stack), each with its depth.
void fillStack(QListWidget *list, const std::vector<bool> &stack) {
    list->clear();
    for (std::size_t k = stack.size(); k-- > 0;) {
        const QString text =
            k + 1 == stack.size()
                //: a stack entry: %1 depth (1 = bottom), %2 ON/OFF
                ? ScanDebuggerView::tr("%1: %2 (top)").arg(k + 1).arg(onOff(stack[k]))
                : ScanDebuggerView::tr("%1: %2").arg(k + 1).arg(onOff(stack[k]));
        list->addItem(text);
    }
    if (stack.empty())
        list->addItem(ScanDebuggerView::tr("(empty)"));
}

QStringList items(const QListWidget *list) {
    QStringList all;
    for (int k = list->count(); k-- > 0;) // bottom first
        all << list->item(k)->text();
    return all;
}

// The main window's simulation as a subject.
class SimulationDebugSubject final : public ScanDebugSubject {
public:
    SimulationDebugSubject(SimulationController *simulation, editor::Document *document,
                           QObject *parent)
        : ScanDebugSubject(parent)
        , m_simulation(simulation)
        , m_document(document) {
        connect(simulation, &SimulationController::breakpointsChanged, this,
                &ScanDebugSubject::breakpointsChanged);
        connect(simulation, &SimulationController::statusChanged, this,
                &ScanDebugSubject::stateChanged);
        connect(simulation, &SimulationController::stoppedAtChanged, this,
                &ScanDebugSubject::stateChanged);
    }
    editor::Document *document() const override { return m_document; }
    bool active() const override { return m_simulation->session() != nullptr; }
    std::shared_ptr<const model::Snapshot> snapshot() const override {
        const simulator::SimulatorSession *session = m_simulation->session();
        return session ? session->snapshot() : nullptr;
    }
    bool live() const override { return !m_simulation->historyShown(); }
    std::vector<BreakpointSpec> breakpoints() const override { return m_simulation->breakpoints(); }
    int instructionOf(const BreakpointSpec &b) const override {
        return m_simulation->instructionOf(b);
    }
    QString conditionText(const BreakpointSpec &b) const override {
        return m_simulation->conditionText(b);
    }
    void stepInstruction() override { m_simulation->stepInstruction(); }
    void finishScan() override { m_simulation->finishScan(); }
    void proceed() override { m_simulation->run(); }
    void removeBreakpoint(int instruction) override { m_simulation->removeBreakpoint(instruction); }
    void clearBreakpoints() override { m_simulation->clearBreakpoints(); }

private:
    SimulationController *m_simulation;
    editor::Document *m_document;
};

} // namespace

ScanDebuggerView::ScanDebuggerView(SimulationController *simulation, editor::Document *document,
                                   QWidget *parent)
    : QWidget(parent)
    , m_subject(new SimulationDebugSubject(simulation, document, this)) {
    build();
}

ScanDebuggerView::ScanDebuggerView(ScanDebugSubject *subject, QWidget *parent)
    : QWidget(parent)
    , m_subject(subject) {
    build();
}

void ScanDebuggerView::build() {
    auto *layout = new QVBoxLayout(this);
    m_position = new QLabel;
    m_position->setObjectName(QStringLiteral("debuggerPosition"));
    m_position->setWordWrap(true);
    m_position->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_position);
    auto *grid = new QGridLayout;
    m_resultCaption = new QLabel;
    m_result = new QLabel;
    m_result->setObjectName(QStringLiteral("debuggerResult"));
    QFont bold = m_result->font();
    bold.setBold(true);
    m_result->setFont(bold);
    grid->addWidget(m_resultCaption, 0, 0);
    grid->addWidget(m_result, 0, 1);
    m_gates = new QLabel;
    m_gates->setWordWrap(true);
    grid->addWidget(m_gates, 1, 0, 1, 2);
    m_blocksCaption = new QLabel;
    m_blocks = new QListWidget;
    m_blocks->setObjectName(QStringLiteral("debuggerBlockStack"));
    m_stackCaption = new QLabel;
    m_stack = new QListWidget;
    m_stack->setObjectName(QStringLiteral("debuggerMpsStack"));
    for (QListWidget *l : {m_blocks, m_stack})
        l->setMaximumHeight(fontMetrics().height() * 5);
    grid->addWidget(m_blocksCaption, 2, 0);
    grid->addWidget(m_stackCaption, 2, 1);
    grid->addWidget(m_blocks, 3, 0);
    grid->addWidget(m_stack, 3, 1);
    layout->addLayout(grid);
    auto *buttons = new QHBoxLayout;
    m_step = new QPushButton;
    m_finish = new QPushButton;
    m_continue = new QPushButton;
    for (QPushButton *b : {m_step, m_finish, m_continue})
        buttons->addWidget(b);
    layout->addLayout(buttons);
    m_breakpointsCaption = new QLabel;
    layout->addWidget(m_breakpointsCaption);
    m_breakpoints = new QTreeWidget;
    m_breakpoints->setObjectName(QStringLiteral("breakpointList"));
    m_breakpoints->setColumnCount(2);
    m_breakpoints->setRootIsDecorated(false);
    m_breakpoints->header()->setStretchLastSection(true);
    m_breakpoints->setWordWrap(true);
    layout->addWidget(m_breakpoints, 1);
    auto *bpButtons = new QHBoxLayout;
    m_condition = new QPushButton;
    m_remove = new QPushButton;
    m_removeAll = new QPushButton;
    for (QPushButton *b : {m_condition, m_remove, m_removeAll})
        bpButtons->addWidget(b);
    layout->addLayout(bpButtons);

    connect(m_step, &QPushButton::clicked, this, [this] { m_subject->stepInstruction(); });
    connect(m_finish, &QPushButton::clicked, this, [this] { m_subject->finishScan(); });
    connect(m_continue, &QPushButton::clicked, this, [this] { m_subject->proceed(); });
    auto selected = [this]() -> int {
        const QTreeWidgetItem *item = m_breakpoints->currentItem();
        return item ? item->data(0, Qt::UserRole).toInt() : -1;
    };
    connect(m_condition, &QPushButton::clicked, this, [this, selected] {
        if (selected() >= 0)
            emit editConditionRequested(selected());
    });
    connect(m_remove, &QPushButton::clicked, this, [this, selected] {
        if (selected() >= 0)
            m_subject->removeBreakpoint(selected());
    });
    connect(m_removeAll, &QPushButton::clicked, this, [this] { m_subject->clearBreakpoints(); });
    // Remove and Condition... act on the breakpoint chosen in the list: greyed, saying so,
    // while none is (a click that did nothing and said nothing left the user guessing).
    connect(m_breakpoints, &QTreeWidget::itemSelectionChanged, this,
            &ScanDebuggerView::updateButtons);
    connect(m_breakpoints, &QTreeWidget::itemDoubleClicked, this, [this](QTreeWidgetItem *item) {
        emit goToInstruction(item->data(0, Qt::UserRole).toInt());
    });
    connect(m_subject, &ScanDebugSubject::breakpointsChanged, this,
            &ScanDebuggerView::refreshBreakpoints);
    connect(m_subject, &ScanDebugSubject::stateChanged, this, &ScanDebuggerView::refresh);
    retranslate();
}

void ScanDebuggerView::retranslate() {
    m_resultCaption->setText(tr("Logic result:"));
    m_step->setText(tr("Step Instruction"));
    m_finish->setText(tr("Finish Scan"));
    m_continue->setText(tr("Continue"));
    m_breakpointsCaption->setText(tr("Breakpoints:"));
    m_breakpoints->setHeaderLabels({tr("Where"), tr("Stops")});
    m_condition->setText(tr("Condition..."));
    m_remove->setText(tr("Remove"));
    m_removeAll->setText(tr("Remove All"));
    refresh();
    refreshBreakpoints();
}

QString ScanDebuggerView::positionText() const {
    return m_position->text();
}

QString ScanDebuggerView::resultText() const {
    return m_result->text();
}

QStringList ScanDebuggerView::blockStack() const {
    return items(m_blocks);
}

QStringList ScanDebuggerView::memoryStack() const {
    return items(m_stack);
}

void ScanDebuggerView::refresh() {
    // The stacks in the family's words: a CPM1 user reads AND LD / OR LD, and only the
    // Vigor has a branch stack (MPS); the others branch through TR bits or none.
    const editor::Document *document = m_subject->document();
    const model::Target &target = document->target();
    const auto mnemonic = [&target](model::Op op) {
        const model::InstructionSpec *spec = target.findInstruction(op);
        return spec ? spec->mnemonic : QString();
    };
    m_blocksCaption->setText(tr("Block stack (%1 / %2):")
                                 .arg(mnemonic(model::Op::AndBlock), mnemonic(model::Op::OrBlock)));
    const QString push = mnemonic(model::Op::Push);
    m_stackCaption->setText(tr("%1 stack:").arg(push));
    m_stackCaption->setVisible(!push.isEmpty());
    m_stack->setVisible(!push.isEmpty());
    const bool session = m_subject->active();
    const auto snapshot = m_subject->snapshot();
    const bool inside = snapshot && snapshot->pause.has_value();
    const bool live = m_subject->live();
    m_step->setEnabled(live);
    m_finish->setEnabled(live && inside);
    m_continue->setEnabled(live && session);
    if (!inside) {
        m_position->setText(session ? tr("Not stopped inside a scan. Step Instruction starts a "
                                         "scan and stops before its first instruction; a "
                                         "breakpoint stops a running scan.")
                                    : tr("The simulation is off."));
        m_result->clear();
        m_gates->clear();
        fillStack(m_blocks, {});
        fillStack(m_stack, {});
        return;
    }
    const model::ScanPause &p = *snapshot->pause;
    const auto &list = document->listing().list.instructions;
    const auto &printed = document->printedListing();
    const auto &first = document->listing().rungFirst;
    QString what;
    if (p.instruction >= 0 && static_cast<std::size_t>(p.instruction) < list.size()) {
        const auto i = static_cast<std::size_t>(p.instruction);
        const int line = i < printed.instructionLine.size() ? printed.instructionLine[i] : 0;
        const auto rung =
            std::upper_bound(first.begin(), first.end(), p.instruction) - first.begin();
        //: %1 step, %2 line, %3 rung, %4 the instruction, e.g. "OUT Y0"
        what = tr("Stopped before step %1 (line %2, rung %3): %4")
                   .arg(list[i].step)
                   .arg(line)
                   .arg(rung)
                   .arg(model::printInstruction(target, list[i]));
    } else {
        what = tr("Stopped at the end of the program");
    }
    what += QLatin1Char('\n') + (p.breakpoint >= 0 ? tr("A breakpoint stopped the scan.")
                                                   : tr("Stepping one instruction at a time."));
    m_position->setText(what);
    m_result->setText(onOff(p.result));
    QStringList gates;
    if (!p.interlock)
        gates << tr("Inside an interlock (IL/MC) whose condition is OFF");
    if (!p.stepActive)
        gates << tr("Inside a step (STL) that is not active");
    m_gates->setText(gates.join(QLatin1Char('\n')));
    fillStack(m_blocks, p.blockStack);
    fillStack(m_stack, p.memoryStack);
}

void ScanDebuggerView::refreshBreakpoints() {
    // The breakpoint chosen stays chosen when the list is written again.
    const QTreeWidgetItem *current = m_breakpoints->currentItem();
    const int chosen =
        current && current->isSelected() ? current->data(0, Qt::UserRole).toInt() : -1;
    m_breakpoints->clear();
    const editor::Document *document = m_subject->document();
    const auto &list = document->listing().list.instructions;
    const auto &printed = document->printedListing();
    for (const SimulationController::BreakpointSpec &b : m_subject->breakpoints()) {
        const int at = m_subject->instructionOf(b);
        auto *item = new QTreeWidgetItem(m_breakpoints);
        item->setData(0, Qt::UserRole, at);
        if (at < 0) {
            item->setText(0, tr("Rung %1 (no longer there)").arg(b.rung + 1));
        } else {
            const auto i = static_cast<std::size_t>(at);
            const int line = i < printed.instructionLine.size() ? printed.instructionLine[i] : 0;
            //: %1 rung, %2 line, %3 the instruction
            item->setText(0, tr("Rung %1, line %2: %3")
                                 .arg(b.rung + 1)
                                 .arg(line)
                                 .arg(i < list.size()
                                          ? model::printInstruction(document->target(), list[i])
                                          : QString()));
        }
        item->setText(1, m_subject->conditionText(b));
    }
    // The place is the longer text: it takes what the condition leaves.
    m_breakpoints->resizeColumnToContents(0);
    m_breakpoints->setColumnWidth(
        0, std::min(m_breakpoints->columnWidth(0), m_breakpoints->viewport()->width() * 2 / 3));
    for (int i = 0; chosen >= 0 && i < m_breakpoints->topLevelItemCount(); ++i)
        if (m_breakpoints->topLevelItem(i)->data(0, Qt::UserRole).toInt() == chosen)
            m_breakpoints->setCurrentItem(m_breakpoints->topLevelItem(i));
    updateButtons();
}

void ScanDebuggerView::updateButtons() {
    const bool any = !m_subject->breakpoints().empty();
    const QTreeWidgetItem *item = m_breakpoints->currentItem();
    const bool chosen = item && item->isSelected() && item->data(0, Qt::UserRole).toInt() >= 0;
    const QString why = !any      ? tr("No breakpoint is set: Ctrl+B sets one where the cursor is")
                        : !chosen ? tr("Choose a breakpoint in the list first")
                                  : QString();
    for (QPushButton *b : {m_condition, m_remove}) {
        b->setEnabled(chosen);
        b->setToolTip(why);
    }
    m_removeAll->setEnabled(any);
}

} // namespace rung::app
