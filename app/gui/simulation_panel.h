#pragma once

// The Simulation dock: run N scans, run for a duration of simulated time, speed, scan
// period, power cycle; the statistics (simulated time, scans, scan period, evaluation time
// current/min/max); and the history: how much is recorded, a slider and a scan number to show
// a past scan in every view (read-only, marked "History: scan N (time)"), Return to Live.

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSlider;
class QSpinBox;
class QGroupBox;

namespace rung::app {

class SimulationController;

class SimulationPanel : public QWidget {
    Q_OBJECT

public:
    explicit SimulationPanel(SimulationController *simulation, QWidget *parent = nullptr);

    void refresh();
    void retranslate();

    // For tests and the menu's entries.
    QSpinBox *scansBox() const { return m_scans; }
    QDoubleSpinBox *durationBox() const { return m_duration; }
    QComboBox *speedBox() const { return m_speed; }
    QSpinBox *periodBox() const { return m_period; }
    QSlider *historySlider() const { return m_slider; }
    QSpinBox *historyScanBox() const { return m_historyScan; }
    QPushButton *liveButton() const { return m_live; }
    QString statisticsText() const;
    QString historyLabel() const;

private:
    void showScan(int scan);

    SimulationController *m_simulation;
    QGroupBox *m_runGroup;
    QGroupBox *m_statsGroup;
    QGroupBox *m_historyGroup;
    QLabel *m_scansLabel;
    QSpinBox *m_scans;
    QPushButton *m_runScans;
    QLabel *m_durationLabel;
    QDoubleSpinBox *m_duration;
    QPushButton *m_runFor;
    QLabel *m_speedLabel;
    QComboBox *m_speed;
    QLabel *m_periodLabel;
    QSpinBox *m_period;
    QPushButton *m_powerCycle;
    QLabel *m_stats;
    QLabel *m_window;
    QSlider *m_slider;
    QLabel *m_historyScanLabel;
    QSpinBox *m_historyScan;
    QLabel *m_historyMark;
    QPushButton *m_live;
    bool m_updating = false;
};

} // namespace rung::app
