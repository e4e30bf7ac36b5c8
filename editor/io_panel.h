#pragma once

// The inputs and outputs panel: the chosen model's terminals as its terminal strip groups
// them (ModelVariant::terminals: Vigor X0..X7, X10..X17; CPM1 channel 000 bits 00..11; PL110
// I1..I8; VPC i00..i07 ...), inputs as switches or push buttons, outputs as lamps, analog
// inputs as a slider with a number box, analog outputs as a bar with the value. Further
// inputs and outputs the program uses (an expansion unit's) follow in groups of their own.
// It reads a MonitorSource only: the simulation now, an online PLC later.

#include "model/image/monitor_source.h"

#include <QMap>
#include <QPointer>
#include <QWidget>

#include <vector>

class QComboBox;
class QLabel;
class QVBoxLayout;

namespace rung::editor {

class Document;
class InputTerminal;
class Lamp;
class AnalogTerminal;

class IoPanel : public QWidget {
    Q_OBJECT

public:
    explicit IoPanel(Document *document, QWidget *parent = nullptr);

    // The source whose image the terminals show and whose inputs they write (null: none; the
    // terminals are then disabled and say how to start).
    void setMonitorSource(model::MonitorSource *source);
    model::MonitorSource *monitorSource() const { return m_source; }

    // The terminals, by device as the target writes it (for tests and keyboard users).
    InputTerminal *input(const QString &device) const;
    Lamp *lamp(const QString &device) const;
    AnalogTerminal *analog(const QString &device) const;
    // Every input acts as a switch or as a push button (each can be changed on its own with
    // the right button).
    void setAllPushButtons(bool pushButtons);

signals:
    void message(const QString &text);

protected:
    void changeEvent(QEvent *event) override;       // LanguageChange: titles and hints again
    void resizeEvent(QResizeEvent *event) override; // a narrow dock: rows of 4, not 8

private:
    struct Terminal {
        model::Address address;
        QString device;
        QWidget *widget = nullptr;
        bool bcd = false; // analog: the word holds BCD digits
    };
    void rebuild(); // the model or the program changed
    void retranslate();
    void showValues();
    void tellWatched();
    void addBlock(QLayout *strip, const QString &title, const std::vector<model::Address> &devices,
                  bool input, int lowest, int highest, bool bcd);
    QString symbolOf(const model::Address &address) const;

    Document *m_document;
    QPointer<model::MonitorSource> m_source;
    QLabel *m_hint;
    QComboBox *m_mode;
    QWidget *m_content = nullptr;
    QVBoxLayout *m_layout = nullptr;
    std::vector<Terminal> m_terminals;
    QMap<QString, bool> m_pushButtons; // device -> acts as a push button
    QString m_shape;                   // the model and the devices the panel was built for
    int m_perRow = 8;                  // terminals in a row of a group
};

} // namespace rung::editor
