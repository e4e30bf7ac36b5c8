#pragma once

// Draws rungs with QPainter: the screen, print, PDF, SVG and PNG export share it, so every
// output looks the same and stays crisp at any scale.

#include "model/image/power_flow.h"

#include "model/checks/diagnostic.h"
#include "model/project/project.h"

#include <QFont>
#include <QFontMetricsF>
#include <QPainter>
#include <QStringList>

#include <algorithm>
#include <optional>
#include <set>

namespace rung::editor {

struct LadderMetrics {
    double cellWidth = 66;
    double rowHeight = 52;
    double gutter = 56;       // rung number and step address
    double outputWidth = 150; // the coil / box column
    double commentHeight = 20;
    double rungGap = 10;
    int gridColumns = 11; // contact columns before the output column (aligned for all rungs)
    // Contacts per drawn line, as the vendor editor has it (Vigor: 11): a longer rung goes on
    // in blocks below, each row ending and starting with a continuation mark. 0: no folding.
    int foldColumns = 0;
    static constexpr double kRightMargin = 12; // not zoomed

    // The sizes at a zoom (1: as above) in whole pixels: rails, wires and cell borders fall on
    // the pixel grid and stay crisp; the cell sizes round down, so fit-to-width never
    // overshoots. The one rule of the ladder and of the compare view.
    void zoomTo(double zoom);
    double rungHeight(const model::Rung &rung) const;
    // Drawn contact columns per line, and the blocks a rung takes.
    int shownColumns() const {
        return foldColumns > 0 ? std::min(gridColumns, foldColumns) : gridColumns;
    }
    int blocks(const model::Rung &rung) const {
        return foldColumns > 0 && rung.columns > foldColumns
                   ? (rung.columns + foldColumns - 1) / foldColumns
                   : 1;
    }
    // Drawn lines from one block to the next: a folded rung leaves a line between its blocks
    // (where a new branch row goes).
    int blockStride(const model::Rung &rung) const {
        return blocks(rung) > 1 ? rung.rows + 1 : rung.rows;
    }
    double commentBlock(const model::Rung &rung) const;
    // The pixel sizes of the drawing's text at this row height: the device labels, the small
    // text (symbol names, comments, rung numbers, step addresses, box operands) and the letter
    // inside a coil. The painter draws with these, and Fit to Width shrinks no further than
    // minReadableZoom(), so one rule decides what is readable.
    struct FontSizes {
        int label;
        int small;
        int mark;
    };
    FontSizes fontSizes() const;
    static constexpr int kMinReadableLabel = 10;
    static constexpr int kMinReadableSmall = 9;
    // The smallest zoom (of a 100 % row of 52 px) at which fontSizes() keeps both floors.
    static double minReadableZoom();
    double width() const {
        return gutter + shownColumns() * cellWidth + outputWidth + kRightMargin;
    }
};

struct RungDecorations {
    int cursorRow = -1;
    int cursorColumn = -1;                  // grid column; >= gridColumns: the output column
    std::set<std::pair<int, int>> marked;   // cells (row, column) in error (reverse current)
    std::set<std::pair<int, int>> selected; // cells (row, column) the user selected
    bool hasError = false;
    bool hasWarning = false;
    int firstStep = -1;
    // Simulation: a breakpoint on the rung (a filled dot in the gutter; conditional: a ring),
    // and where a stopped scan is: the element (row, column) it stops before, or the rung
    // only (-1, -1) for ANB, ORB, MPS..., drawn with an arrow in the gutter.
    enum class Breakpoint : std::uint8_t { None, Plain, Conditional };
    Breakpoint breakpoint = Breakpoint::None;
    bool stopped = false;
    std::pair<int, int> stoppedAt{-1, -1};
    // The live overlay (a running simulation, an online PLC): power flow, states, values and
    // forced devices drawn over the rung; null when nothing is monitored.
    const model::RungOverlay *overlay = nullptr;
};

class LadderPainter {
public:
    LadderPainter(const model::Project &project, const LadderMetrics &metrics);

    // Paints rung `index` with its top-left corner at `origin`.
    void paintRung(QPainter &p, QPointF origin, int index,
                   const RungDecorations &decorations) const;

    // Cell geometry within a rung drawn at (0, 0); column >= gridColumns is the output column.
    QRectF cellRect(const model::Rung &rung, int row, int column) const;
    QRectF outputRect(const model::Rung &rung, int row) const;
    const LadderMetrics &metrics() const { return m_m; }
    // Symbol names above the elements and the addresses small below them (where a device
    // has a name), instead of the other way round.
    void setNamesFirst(bool on) { m_namesFirst = on; }

    // Where the overlay's colours and weights come from, for the legend and the tests.
    static QColor energisedColor();
    static QColor forcedColor();
    static QColor staleColor();
    // The values under a box's instruction, as lines that fit `width` in `metrics`: one
    // line when it fits (compacted if need be), else a device a line.
    static QStringList valueLines(const QString &live, const QFontMetricsF &metrics, double width);
    // Words (an instruction's operands) on at most maxLines lines of `width`, broken between
    // words; what still does not fit is elided at the end of the last line.
    static QStringList wrappedLines(const QString &text, const QFontMetricsF &metrics, double width,
                                    int maxLines);
    // A box's inner rectangle (where its text goes) in an output area, and the badge of a
    // forced contact in its cell: for the tests of what fits.
    QRectF boxTextRect(const QRectF &area) const;
    QFont liveFont() const; // a box's values: the small font, bold
    QRectF contactForceBadge(const QRectF &cell) const;

private:
    // `live`: the monitored value to show under the element (compare contacts).
    void paintContact(QPainter &p, const QRectF &cell, const model::Contact &contact,
                      const QString &live = QString()) const;
    void paintContinuation(QPainter &p, QPointF at, int mark, int row) const;
    void paintDebug(QPainter &p, const model::Rung &rung, const RungDecorations &d,
                    double commentH) const;
    // `live`: the monitored value to show in the box under its instruction.
    void paintOutput(QPainter &p, const QRectF &area, const model::Instruction &ins,
                     const QString &live = QString()) const;
    // The arrow of an edge contact, centred at (cx, y), h its half height.
    static void paintEdgeArrow(QPainter &p, double cx, double y, double h, bool up);
    // The vertical links below `row` (those whose node is ON in `powered`; null: all).
    void paintLinks(QPainter &p, const model::Rung &rung, int row, double commentH,
                    const model::RungOverlay *powered) const;
    // The wire from the row's last contact column to the output column, where it has one.
    std::optional<QLineF> outputWire(const model::Rung &rung, int row) const;
    // The overlay over a painted rung (ladder_painter_overlay.cpp).
    void paintOverlay(QPainter &p, const model::Rung &rung,
                      const model::RungOverlay &overlay) const;
    void paintContactState(QPainter &p, const QRectF &cell, const model::Contact &contact,
                           const model::RungOverlay &o, int row, int column) const;
    void paintOutputState(QPainter &p, const QRectF &area, const model::Instruction &ins,
                          const model::RungOverlay::Output &out, bool stale) const;
    // A forced element: a dashed outline round it and the "F" badge in `badge`.
    void paintForced(QPainter &p, const QRectF &element, const QRectF &badge, bool stale) const;
    double forceBadgeSize() const;
    // The badge of a contact or coil: right of its symbol, on the wire, inside the cell.
    QRectF forceBadgeBeside(const QRectF &cell, double symbolRight) const;
    QPen livePen(bool stale) const;
    // Shared geometry of the drawing and its overlay.
    bool isCoil(const model::Instruction &ins) const;
    QRectF boxRect(const QRectF &area) const;
    double coilCenterX(const QRectF &area) const { return area.left() + area.width() * 0.4; }
    QString deviceLabel(const model::Operand &operand) const;
    QString symbolLabel(const model::Operand &operand) const;
    QString primaryLabel(const model::Operand &operand) const;
    QString secondaryLabel(const model::Operand &operand) const;
    // Pixel-grid geometry: the wire of a row whose top is `rowTop`, and a line position for
    // a pen of `width`, so lines cover whole pixels (no blur, no seams where they meet).
    double wireY(double rowTop) const;
    static double snap(double v, double width);
    QPen inkPen() const;

    const model::Project &m_project;
    LadderMetrics m_m;
    QFont m_font;
    QFont m_small;
    QFont m_mark; // the letter inside a coil (S, R, P, F, /): bold, to read at a glance
    bool m_namesFirst = false;
    double m_pen = 2; // wire width: 1.6 at 100 %, rounded to whole pixels
};

} // namespace rung::editor
