#pragma once

#include <QStatusBar>

namespace rung::app {

// The window's status bar: a message that does not fit before the permanent fields (the
// steps, the target, the run state) ends in "…" a gap before them, its whole text in the
// tooltip. Qt's own cuts it where the first field starts, so "Trying again." ran into
// "44 / 16000 steps" as "Trying again.44 / 16000".
class StatusBar : public QStatusBar {
    Q_OBJECT
public:
    explicit StatusBar(QWidget *parent = nullptr);

    // Where the message is drawn and how it reads there (elided when it does not fit).
    QRect messageArea() const;
    QString shownMessage() const;

protected:
    void paintEvent(QPaintEvent *event) override;
    bool event(QEvent *event) override;
};

} // namespace rung::app
