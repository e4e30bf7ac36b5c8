#pragma once

// The pieces of the inputs and outputs panel (io_panel.h): a terminal strip's input as a
// switch or a push button, an output as a lamp, an analog value as a slider with a number
// box, and a layout that wraps the strip's groups to the panel's width. ON and OFF differ
// by fill and weight, not by colour alone, so they read for colour-blind users and in print.

#include <QAbstractButton>
#include <QLayout>
#include <QWidget>

class QPainter;
class QSlider;
class QSpinBox;
class QLabel;

namespace rung::editor {

// Lays its items out left to right and wraps them to the next line at the right edge.
class FlowLayout : public QLayout {
public:
    explicit FlowLayout(QWidget *parent = nullptr, int spacing = 6);
    ~FlowLayout() override;

    void addItem(QLayoutItem *item) override;
    int count() const override { return static_cast<int>(m_items.size()); }
    QLayoutItem *itemAt(int index) const override;
    QLayoutItem *takeAt(int index) override;
    Qt::Orientations expandingDirections() const override { return {}; }
    bool hasHeightForWidth() const override { return true; }
    int heightForWidth(int width) const override;
    QSize minimumSize() const override;
    QSize sizeHint() const override;
    void setGeometry(const QRect &rect) override;

private:
    int arrange(const QRect &rect, bool apply) const;
    QList<QLayoutItem *> m_items;
    int m_spacing;
};

// The face both terminals share: the device as the strip names it, the symbol's name under
// it (elided to the terminal's width), and a state that follows the PLC's image.
class TerminalFace : public QAbstractButton {
    Q_OBJECT
public:
    TerminalFace(const QString &device, const QString &symbol, QWidget *parent = nullptr);
    void setState(bool on, bool forced);
    bool isOn() const { return m_on; }
    bool isForced() const { return m_forced; }
    QString device() const { return m_device; }
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override { return sizeHint(); }

protected:
    // The symbol's rectangle, the name's, and the state's drawing area.
    QRect stateRect() const;
    void paintLabels(QPainter &painter) const;
    void paintForced(QPainter &painter) const;

    QString m_device;
    QString m_symbol;
    bool m_on = false;
    bool m_forced = false;
};

// An input terminal. A switch keeps the position it is put in (a click toggles it); a push
// button is ON only while held, with the mouse or with Space while it has focus.
class InputTerminal : public TerminalFace {
    Q_OBJECT
public:
    enum class Mode { Switch, PushButton };
    InputTerminal(const QString &device, const QString &symbol, QWidget *parent = nullptr);
    void setMode(Mode mode);
    Mode mode() const { return m_mode; }

signals:
    // The user wants the input at this state.
    void requested(bool on);

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    Mode m_mode = Mode::Switch;
};

// An output terminal: a lamp, filled and heavy when ON, hollow when OFF.
class Lamp : public TerminalFace {
    Q_OBJECT
public:
    Lamp(const QString &device, const QString &symbol, QWidget *parent = nullptr);

protected:
    void paintEvent(QPaintEvent *event) override;
};

// A word terminal: the device's name, a slider and a number box (an input), or the name and
// its value over a bar (an output).
class AnalogTerminal : public QWidget {
    Q_OBJECT
public:
    AnalogTerminal(const QString &device, const QString &symbol, int lowest, int highest,
                   bool input, QWidget *parent = nullptr);
    // The value the PLC holds; the slider stays where the user holds it.
    void setValue(int value);
    // The PLC's word reads as no number (a BCD channel with a nibble above 9): `text` says
    // what it holds, beside the value, until the next setValue().
    void setUnreadable(const QString &text);
    QString unreadable() const; // empty while the word reads
    int value() const;
    QString device() const { return m_device; }
    QSlider *slider() const { return m_slider; }
    QSpinBox *spinBox() const { return m_spin; }

signals:
    void requested(int value);

private:
    QString m_device;
    QSlider *m_slider = nullptr;
    QSpinBox *m_spin = nullptr;
    QLabel *m_shown = nullptr;      // an output's value
    QLabel *m_unreadable = nullptr; // what a word that reads as no number holds
    bool m_updating = false;
};

} // namespace rung::editor
