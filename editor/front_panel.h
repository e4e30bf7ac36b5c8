#pragma once

// The PLC's front panel (issue 30) as the manuals describe it (model::FrontPanel): the Vigor
// VB's 4-digit display and its variable resistors, the PL110-2A's OLED terminal with its keys
// and the PL110's lamps, the CPM1's analog settings and lamps, the VPC console's I/O window.
// It draws model::panelView of a MonitorSource's snapshot (any source: the simulation, a
// network station's), repaints on each snapshot, and writes through the source when the user
// turns a knob, types its number or presses a key (mouse, or the keyboard on the focused panel).

#include "model/image/monitor_source.h"
#include "model/image/panel_view.h"

#include <QElapsedTimer>
#include <QPointer>
#include <QTimer>
#include <QWidget>

#include <optional>
#include <vector>

class QDial;
class QLabel;
class QToolButton;
class QSpinBox;
class QVBoxLayout;

namespace rung::editor {

class FlowLayout;
class PanelDisplay;
class PanelLamp;

class FrontPanel : public QWidget {
    Q_OBJECT

public:
    explicit FrontPanel(QWidget *parent = nullptr);

    // The PLC the panel is of: its table and model (null target: none).
    void setPlc(const model::Target *target, const QString &modelName);
    // The source whose image the panel shows and to which its knobs and keys write (null:
    // none; the panel then says how to start).
    void setMonitorSource(model::MonitorSource *source);
    model::MonitorSource *monitorSource() const { return m_source; }
    // What the PLC holds beside its memory, as the project or the network station running it
    // says (its program's name, its ports' protocols: the PL110's system page 3); none: not
    // known, and the page says so.
    void setContext(std::optional<model::PanelContext> context);

    // What the panel shows now (for tests and for the keyboard's user: the display as text).
    const model::PanelView &view() const { return m_view; }
    // What the terminal's keys are doing (a field being edited, the password page).
    const model::TerminalState &terminal() const { return m_terminal; }
    // The parts, by the label the manual gives them (for tests and accessibility).
    QDial *knob(const QString &label) const;
    QSpinBox *knobNumber(const QString &label) const;
    QToolButton *key(const QString &label) const;
    PanelLamp *lamp(const QString &label) const;
    PanelDisplay *display() const { return m_display; }
    // The sentence shown when there is no panel or nothing runs (empty otherwise).
    QString hint() const;

signals:
    void message(const QString &text);

protected:
    void changeEvent(QEvent *event) override; // LanguageChange
    void keyPressEvent(QKeyEvent *event) override;
    void keyReleaseEvent(QKeyEvent *event) override;

private:
    struct Knob {
        QString label;
        QDial *dial = nullptr;
        QSpinBox *number = nullptr;
    };
    void rebuild(); // the PLC changed
    void refresh(); // a snapshot, a run state, the blinking
    void retranslate();
    void writeKnob(std::size_t index, int value);
    void pressKey(std::size_t index, bool down);
    int keyIndexFor(int qtKey) const;

    const model::Target *m_target = nullptr;
    QString m_modelName;
    QPointer<model::MonitorSource> m_source;
    std::optional<model::PanelContext> m_context;
    model::PanelView m_view;
    model::TerminalState m_terminal; // the keys' editing, the standby (model/image/panel_keys.h)
    QElapsedTimer m_clock;
    QTimer m_blink;
    QLabel *m_hint;
    QLabel *m_caption;
    PanelDisplay *m_display;
    QWidget *m_parts;
    FlowLayout *m_lampRow = nullptr;
    FlowLayout *m_keyRow = nullptr;
    FlowLayout *m_knobRow = nullptr;
    std::vector<PanelLamp *> m_lamps;
    std::vector<QToolButton *> m_keys;
    std::vector<Knob> m_knobs;
    std::vector<model::Address> m_watched; // told the source (setWatched)
};

// A lamp: a coloured disc, lit or dark, its label as printed on the PLC beside it; the
// manual's meaning as its tooltip.
class PanelLamp : public QWidget {
    Q_OBJECT

public:
    PanelLamp(const QString &label, model::LampColour colour, QWidget *parent = nullptr);
    void setState(bool lit, int blinkMs);
    bool isLit() const { return m_lit; }
    int blinkMs() const { return m_blinkMs; }
    QSize sizeHint() const override;

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    QString m_label;
    model::LampColour m_colour;
    bool m_lit = false;
    int m_blinkMs = 0;
};

// The display: the Vigor's digits, the PL110's rows of characters, the VPC's I/O lines, in
// the widget's own font scaled (readable at any font size), never clipped: its size hint is
// what the text needs.
class PanelDisplay : public QWidget {
    Q_OBJECT

public:
    explicit PanelDisplay(QWidget *parent = nullptr);
    void setView(const model::PanelView *view);
    // What it shows, as plain text (one line a row), for tests and screen readers.
    QString text() const;
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override { return sizeHint(); }

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    QFont displayFont() const;
    QStringList rows() const;
    const model::PanelView *m_view = nullptr;
};

} // namespace rung::editor
