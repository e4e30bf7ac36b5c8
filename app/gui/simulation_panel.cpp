#include "simulation_panel.h"

#include "simulation_controller.h"
#include "wheel_guard.h"

#include "simulator/history_source.h"
#include "simulator/scan_history.h"
#include "simulator/session.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>

#include <climits>
#include <limits>

namespace rung::app {

namespace {

constexpr double kSpeeds[] = {0.1, 0.5, 1.0, 2.0, 5.0, 10.0, 100.0, 1000.0, 0.0};

QString micro(qint64 ns) {
    return QString::number(static_cast<double>(ns) / 1000.0, 'f', 1);
}

} // namespace

SimulationPanel::SimulationPanel(SimulationController *simulation, QWidget *parent)
    : QWidget(parent)
    , m_simulation(simulation) {
    auto *layout = new QVBoxLayout(this);

    m_runGroup = new QGroupBox;
    auto *run = new QFormLayout(m_runGroup);
    m_scansLabel = new QLabel;
    m_scans = new QSpinBox;
    m_scans->setObjectName(QStringLiteral("runScansCount"));
    m_scans->setRange(1, 100000000);
    m_scans->setValue(QSettings().value(QStringLiteral("simulation/runScans"), 100).toInt());
    m_runScans = new QPushButton;
    m_durationLabel = new QLabel;
    m_duration = new QDoubleSpinBox;
    m_duration->setObjectName(QStringLiteral("runForSeconds"));
    m_duration->setDecimals(2);
    m_duration->setRange(0.01, 24.0 * 3600.0);
    m_duration->setValue(
        QSettings().value(QStringLiteral("simulation/runForSeconds"), 10.0).toDouble());
    m_runFor = new QPushButton;
    m_speedLabel = new QLabel;
    m_speed = new QComboBox;
    m_speed->setObjectName(QStringLiteral("simulationSpeed"));
    // The dock is a narrow column beside the ladder: the combo takes the width it is given
    // (its list opens as wide as its longest entry).
    m_speed->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_speed->setMinimumContentsLength(8);
    m_periodLabel = new QLabel;
    m_period = new QSpinBox;
    m_period->setObjectName(QStringLiteral("simulationPeriod"));
    m_period->setRange(1, 100);
    m_powerCycle = new QPushButton;
    // Each button under its field, not beside it, and a label over its field where the
    // column is too narrow for both: the dock is a column beside the ladder (dock_layout.h),
    // and Hungarian and Italian labels and buttons are long.
    run->setRowWrapPolicy(QFormLayout::WrapLongRows);
    run->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    run->addRow(m_scansLabel, m_scans);
    run->addRow(m_runScans);
    run->addRow(m_durationLabel, m_duration);
    run->addRow(m_runFor);
    run->addRow(m_speedLabel, m_speed);
    run->addRow(m_periodLabel, m_period);
    run->addRow(m_powerCycle);
    layout->addWidget(m_runGroup);

    m_statsGroup = new QGroupBox;
    auto *stats = new QVBoxLayout(m_statsGroup);
    m_stats = new QLabel;
    m_stats->setObjectName(QStringLiteral("simulationStatistics"));
    m_stats->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_stats->setWordWrap(true); // a narrow column: the lines wrap rather than scroll
    stats->addWidget(m_stats);
    layout->addWidget(m_statsGroup);

    m_historyGroup = new QGroupBox;
    auto *history = new QVBoxLayout(m_historyGroup);
    m_window = new QLabel;
    m_window->setObjectName(QStringLiteral("historyWindow"));
    m_window->setWordWrap(true);
    history->addWidget(m_window);
    m_slider = new QSlider(Qt::Horizontal);
    m_slider->setObjectName(QStringLiteral("historySlider"));
    history->addWidget(m_slider);
    auto *row = new QHBoxLayout;
    m_historyScanLabel = new QLabel;
    m_historyScan = new QSpinBox;
    m_historyScan->setObjectName(QStringLiteral("historyScan"));
    m_historyScan->setRange(0, std::numeric_limits<int>::max());
    m_historyScan->setKeyboardTracking(false);
    m_live = new QPushButton;
    m_live->setObjectName(QStringLiteral("returnToLive"));
    row->addWidget(m_historyScanLabel);
    row->addWidget(m_historyScan, 1);
    history->addLayout(row);
    history->addWidget(m_live); // under the scan: the column is narrow
    m_historyMark = new QLabel;
    m_historyMark->setObjectName(QStringLiteral("historyMark"));
    // Marked so it cannot be taken for the live state: bold on amber, as the status bar.
    m_historyMark->setStyleSheet(QStringLiteral(
        "QLabel { background: #ffd54f; color: #3e2700; font-weight: bold; padding: 2px 6px; }"));
    m_historyMark->hide();
    history->addWidget(m_historyMark);
    layout->addWidget(m_historyGroup);
    layout->addStretch(1);
    guardWheel(this); // scrolling the dock never changes the speed or the period

    connect(m_runScans, &QPushButton::clicked, this, [this] {
        QSettings().setValue(QStringLiteral("simulation/runScans"), m_scans->value());
        m_simulation->runScans(static_cast<quint64>(m_scans->value()));
    });
    connect(m_runFor, &QPushButton::clicked, this, [this] {
        QSettings().setValue(QStringLiteral("simulation/runForSeconds"), m_duration->value());
        m_simulation->runFor(static_cast<qint64>(m_duration->value() * 1000.0 + 0.5));
    });
    connect(m_speed, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (!m_updating && index >= 0)
            m_simulation->setSpeed(m_speed->itemData(index).toDouble());
    });
    connect(m_period, &QSpinBox::valueChanged, this, [this](int ms) {
        if (!m_updating)
            m_simulation->setPeriodMs(ms);
    });
    connect(m_powerCycle, &QPushButton::clicked, simulation, &SimulationController::powerCycle);
    connect(m_slider, &QSlider::valueChanged, this, [this](int scan) {
        if (!m_updating)
            showScan(scan);
    });
    connect(m_historyScan, &QSpinBox::valueChanged, this, [this](int scan) {
        if (!m_updating)
            showScan(scan);
    });
    connect(m_live, &QPushButton::clicked, simulation, &SimulationController::returnToLive);
    connect(simulation, &SimulationController::statusChanged, this, &SimulationPanel::refresh);
    retranslate();
}

void SimulationPanel::showScan(int scan) {
    m_simulation->showHistoryScan(static_cast<quint64>(std::max(0, scan)));
}

void SimulationPanel::retranslate() {
    m_updating = true;
    m_runGroup->setTitle(tr("Run"));
    m_scansLabel->setText(tr("Scans:"));
    m_runScans->setText(tr("Run Scans"));
    m_durationLabel->setText(tr("Simulated time:"));
    //: seconds of simulated time
    m_duration->setSuffix(tr(" s"));
    m_runFor->setText(tr("Run For"));
    m_speedLabel->setText(tr("Speed:"));
    m_speed->clear();
    for (const double factor : kSpeeds)
        m_speed->addItem(factor > 0 ? tr("x%1 real time").arg(factor) : tr("As fast as possible"),
                         factor);
    m_periodLabel->setText(tr("Scan period:"));
    //: milliseconds
    m_period->setSuffix(tr(" ms"));
    // Short: the dock is a narrow column; what it keeps is in the tooltip.
    m_powerCycle->setText(tr("Power Cycle"));
    m_powerCycle->setToolTip(
        tr("Off and on again: the retentive areas keep their values, the rest starts as at "
           "power-on"));
    m_statsGroup->setTitle(tr("Statistics"));
    m_historyGroup->setTitle(tr("History"));
    m_historyScanLabel->setText(tr("Show scan:"));
    m_live->setText(tr("Return to Live"));
    m_updating = false;
    refresh();
}

QString SimulationPanel::statisticsText() const {
    return m_stats->text();
}

QString SimulationPanel::historyLabel() const {
    return m_historyMark->isHidden() ? QString() : m_historyMark->text();
}

void SimulationPanel::refresh() {
    m_updating = true;
    for (int k = 0; k < m_speed->count(); ++k)
        if (qFuzzyCompare(m_speed->itemData(k).toDouble() + 1, m_simulation->speed() + 1))
            m_speed->setCurrentIndex(k);
    m_period->setValue(static_cast<int>(m_simulation->periodMs()));

    simulator::SimulatorSession *session = m_simulation->session();
    const auto snapshot = session ? session->snapshot() : nullptr;
    if (!snapshot) {
        m_stats->setText(tr("The simulation is off: Run, Single Scan or Run Scans starts it."));
    } else {
        const model::ScanStatistics &s = snapshot->statistics;
        //: the statistics block: simulated time, scans, the scan period, the evaluation time
        //: of the last scan on this computer (current, minimum..maximum)
        m_stats->setText(tr("Simulated time: %1\nScans: %2\nScan period: %3 ms\n"
                            "Evaluation: %4 µs (%5..%6)")
                             .arg(SimulationController::clockText(s.timeMs))
                             .arg(s.scans)
                             .arg(s.periodMs)
                             .arg(micro(s.execNsCurrent), micro(s.execNsMin), micro(s.execNsMax)));
    }

    m_window->setText(m_simulation->historyWindowText());
    const bool haveHistory = session != nullptr;
    m_slider->setEnabled(haveHistory);
    m_historyScan->setEnabled(haveHistory);
    if (session) {
        const simulator::ScanHistory::Window w = session->scanHistory()->window();
        const int first = static_cast<int>(std::min<quint64>(w.firstScan, INT_MAX));
        const int last =
            static_cast<int>(std::min<quint64>(std::max(w.lastScan, w.firstScan), INT_MAX));
        if (!m_slider->isSliderDown()) {
            m_slider->setRange(first, last);
            m_historyScan->setRange(first, last);
        }
    }
    const bool history = m_simulation->historyShown();
    m_live->setEnabled(history);
    m_historyMark->setVisible(history);
    m_historyMark->setText(m_simulation->historyText());
    if (history && !m_slider->isSliderDown()) {
        if (const auto shown = m_simulation->historySource()->snapshot()) {
            m_slider->setValue(static_cast<int>(shown->statistics.scans));
            if (!m_historyScan->hasFocus())
                m_historyScan->setValue(static_cast<int>(shown->statistics.scans));
        }
    } else if (!history) {
        m_slider->setValue(m_slider->maximum());
        if (!m_historyScan->hasFocus())
            m_historyScan->setValue(m_historyScan->maximum());
    }
    m_updating = false;
}

} // namespace rung::app
