#pragma once

// Two ladders side by side, rung against rung as model::compareProjects pairs them (File >
// Compare With...). Each pair stands on one row; a rung only in one program faces an empty,
// hatched place. What differs is marked so that it reads without colour and on paper: the
// row's band has a pattern and a sign beside its words (= the same, ~ changed, + inserted,
// - deleted, an up-down arrow moved), and each changed element is framed with a dashed line and its
// sign; the colours (Okabe-Ito's, told apart by every common colour vision) only add to that.

#include "ladder_painter.h"

#include "model/compare/compare.h"

#include <QAbstractScrollArea>

class QPagedPaintDevice;

namespace rung::editor {

class CompareView : public QAbstractScrollArea {
    Q_OBJECT

public:
    explicit CompareView(QWidget *parent = nullptr);

    // A and B and their comparison; the view keeps copies.
    void setComparison(const model::Project &a, const model::Project &b,
                       const model::Comparison &comparison);
    const model::Comparison &comparison() const { return m_comparison; }

    // The difference shown as current (an index into Comparison::rungs), -1 for none.
    int current() const { return m_current; }
    void setCurrent(int difference);
    // To the next (previous) rung that differs from the current one; false when there is none
    // further (the current stays).
    bool nextChange(bool backwards);
    int changeCount() const;

    // The sign and the words of a status, as the bands show them ("~ changed").
    static QString statusMark(model::RungStatus status);
    static QString statusText(model::RungStatus status);
    // The pattern and colour of a status's band and frames.
    static Qt::BrushStyle statusPattern(model::RungStatus status);
    static QColor statusColor(model::RungStatus status);

    // Prints every row, as many to a page as fit, the page's width taking both sides.
    void print(QPagedPaintDevice *device) const;

signals:
    void currentChanged(int difference);

protected:
    void paintEvent(QPaintEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    void relayout();
    LadderMetrics metricsFor(double zoom) const;
    double rowHeight(std::size_t difference, const LadderMetrics &m) const;
    void paintRow(QPainter &p, std::size_t difference, double top, double height,
                  const LadderMetrics &m, bool current) const;
    void paintSide(QPainter &p, const model::Project &project, int rung, QPointF origin,
                   double width, double height, const LadderMetrics &m,
                   const model::RungDifference &d, bool sideA) const;

    model::Project m_a, m_b;
    model::Comparison m_comparison;
    int m_current = -1;
    double m_zoom = 1.0;
    std::vector<double> m_top;           // each row's top, and the end
    static constexpr double kBand = 150; // the status band between the two sides (unzoomed)
    static constexpr double kHeader = 22;
};

} // namespace rung::editor
