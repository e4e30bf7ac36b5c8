#pragma once

#include <QLabel>

namespace rung::app {

// A status-bar label that gives way: a full status bar (a long run state at x10 beside the
// history and origin marks) elides its text instead of pushing the labels over each other.
// The whole text stays in the tooltip.
class ElidingLabel : public QLabel {
    Q_OBJECT
public:
    explicit ElidingLabel(QWidget *parent = nullptr);

    void setFullText(const QString &text);
    QString fullText() const { return m_full; }
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void resizeEvent(QResizeEvent *event) override;

private:
    void elide();
    QString m_full;
};

} // namespace rung::app
