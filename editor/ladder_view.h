#pragma once

// The ladder editor: paints only the visible rungs, moves a cell cursor with the keyboard,
// and edits as the vendor tools do: F5 normally open contact, F6 normally closed, F7 coil,
// F8 instruction, F9 wire, Shift+F9 vertical link, with Shift/Alt/Ctrl the parallel and edge
// contacts and deleting wires and links (ladder_view_keys.cpp), typing a mnemonic with its
// operand ("LD X0", "OUT Y1", "TMR T0 K10") into the cell, Insert/Delete for cells, rows and
// rungs.

#include "document.h"
#include "ladder_painter.h"

#include "model/image/monitor_source.h"

#include <QAbstractScrollArea>
#include <QKeySequence>
#include <QPointer>

#include <map>
#include <memory>

class QLabel;
class QLineEdit;
class QMenu;

class QStringListModel;

namespace rung::editor {

class MonitorCommands;

struct CellCursor {
    int rung = 0;
    int row = 0;
    int column = 0; // grid column; == gridColumns: the output column
    friend bool operator==(const CellCursor &, const CellCursor &) = default;
};

class LadderView : public QAbstractScrollArea {
    Q_OBJECT

public:
    explicit LadderView(Document *document, QWidget *parent = nullptr);

    CellCursor cursor() const { return m_cursor; }
    void setCursor(const CellCursor &cursor);
    double zoom() const { return m_zoom; }
    void setZoom(double zoom); // the user's zoom: ends fit-to-width
    // Fit to width: the zoom follows the view's width (never above 100 %), so the output
    // column is never cut off, e.g. beside the instruction list.
    bool fitWidth() const { return m_fitWidth; }
    void setFitWidth(bool on);
    // Symbol names in place of the addresses (the address small below), where a name exists.
    bool namesFirst() const { return m_namesFirst; }
    void setNamesFirst(bool on);
    // The comment above the rung under the cursor; one undo step.
    void setRungComment(const QString &comment);
    LadderMetrics metrics() const;

    // Places what one instruction text says at the cursor ("LD X0", "ANI X2", "OUT Y1");
    // false with *error when the text is not one instruction of the target.
    bool enterInstruction(const QString &text, QString *error = nullptr);
    void placeWire();
    void toggleLink();
    void clearCell();
    void deleteWire(); // Ctrl+F9
    void deleteLink(); // Ctrl+F10: the link at the cursor's left node, down to the next row
    void insertColumn();
    void insertRow();
    void deleteRow();
    void insertRung();
    void deleteRung(); // the selected rungs
    // The selected rungs as (first, count): a Shift+Up/Down range, else the cursor's rung.
    std::pair<int, int> selectedRungs() const;
    void selectRungs(int first, int last);
    void clearSelection(); // rungs and cells
    // A run of cells in one row (Shift+Left/Right): copy, cut, paste and Delete act on it.
    struct CellRun {
        int rung = -1;
        int row = 0;
        int first = 0;
        int last = -1;
        bool valid() const { return rung >= 0 && last >= first; }
    };
    CellRun selectedCells() const;
    void selectCells(int first, int last); // in the cursor's row
    // The selected cells as a one-row rung (a fragment to paste elsewhere).
    model::Rung copyCells() const;
    void clearCells(); // the selected cells, one undo step
    // Writes a one-row fragment from the cursor cell on, one undo step.
    void pasteCells(const model::Rung &fragment);
    void openEditor(const QString &initial);
    QLineEdit *inlineEditor() const { return m_editor; }
    // The device of the element under the cursor (contact or output), as the target writes
    // it; empty on a wire or an empty cell.
    QString deviceAtCursor() const;
    // Moves the cursor to the next (previous) element that uses the device, wrapping round;
    // false, with a message, when nothing uses it (ladder_view_find.cpp).
    bool findDevice(const model::Address &device, bool backwards = false);
    // A line across the top of the drawing (the list has errors and the ladder shows the
    // last valid program); empty: none.
    void setNotice(const QString &text);
    QString notice() const;
    // What the cell editor's completer offers for the text typed so far.
    QStringList completions() const;
    // The tooltip of an element: its devices with their symbol names and comments.
    QString elementHelp(const CellCursor &cell) const;

    // A palette tool picked with the mouse: each click on a cell then does there what the
    // tool's function key does at the cursor (F5 contact, Shift+F9 link...), until Esc, a
    // right click or armTool({}) puts it away (ladder_view_mouse.cpp).
    void armTool(const QKeySequence &key);
    QKeySequence armedTool() const { return m_tool; }

    // Simulation: the rungs with a breakpoint (-> conditional), and where a stopped scan is
    // (rung -1: nowhere; row -1: the rung as a whole).
    void setBreakpointRungs(const std::map<int, bool> &rungs);
    const std::map<int, bool> &breakpointRungs() const { return m_breakpoints; }
    void setStoppedAt(const CellCursor &at);
    CellCursor stoppedAt() const { return m_stoppedAt; }

    // The rung geometry, for navigation and tests.
    QRect cellRectOnScreen(const CellCursor &cell) const;

    // The live overlay (ladder_view_monitor.cpp): while a source is set, its snapshots are
    // drawn over the rungs (power flow, states, values, forced devices) and the context menu
    // (right button, the Menu key or Shift+F10) forces and writes the devices of an element.
    // Each snapshot repaints only the rungs on screen whose overlay changed. Null: none.
    void setMonitorSource(model::MonitorSource *source);
    model::MonitorSource *monitorSource() const { return m_source; }
    // The overlay of a rung as the view draws it now; empty (no rows) while nothing is
    // monitored or the snapshot is of another target.
    model::RungOverlay overlay(int rung) const;
    // The context menu's entries for the element at a cell (the device commands); nullptr
    // where the cell holds no device. Enabled only while a source is set.
    QMenu *monitorMenu(const CellCursor &cell, QWidget *parent);

signals:
    void cursorMoved(const rung::editor::CellCursor &cursor);
    void message(const QString &text);
    void fitWidthChanged(bool on);
    void toolArmed(const QKeySequence &key); // empty: the select tool
    // A click on the left of a rung's gutter: set or clear a breakpoint there.
    void breakpointToggleRequested(int rung);

protected:
    void paintEvent(QPaintEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    bool eventFilter(QObject *watched, QEvent *event) override; // the cell editor's keys
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseDoubleClickEvent(QMouseEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;
    bool viewportEvent(QEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    void contextMenuEvent(QContextMenuEvent *event) override;
    void scrollContentsBy(int dx, int dy) override;
    void changeEvent(QEvent *event) override; // LanguageChange: its own texts again

private:
    void relayout();
    void placeNotice();
    bool functionKey(QKeyEvent *event);     // F5..F10 with their modifiers; false: not one
    bool applyTool(const CellCursor &cell); // the armed tool's key at a clicked cell
    LadderMetrics metricsAt(double zoom) const;
    // The cell under a viewport position; rung -1 where there is none.
    CellCursor cellAt(QPointF position) const;
    // Whether the mouse went past the drag distance since the press: less is a click.
    bool draggedFarEnough(QPointF position) const;
    // Wires along a row or vertical links down a column, from one cell to another of a rung.
    void drawDrag(const CellCursor &from, const CellCursor &to);
    void applyZoom(double zoom);
    void fitZoomToWidth();
    void updateCompletions(const QString &text);
    // The last contact column the cursor reaches in a rung before the output column (the end
    // of its last block when the rung is folded).
    int lastColumn(int rung) const;
    int rungAt(double y) const;
    void ensureCursorVisible();
    model::Rung currentRung() const;
    void commitEditor();
    QString mnemonicFor(model::Op op, model::ContactMode mode = model::ContactMode::Normal) const;
    // The overlay (ladder_view_monitor.cpp).
    void snapshotArrived();
    // The snapshot drawn now, when it is of the document's target.
    std::shared_ptr<const model::Snapshot> monitoredSnapshot() const;
    bool staleValues() const;
    std::pair<int, int> visibleRungs() const; // [first, last)
    void showMonitorMenu(const CellCursor &cell, QPoint globalPos);
    QString liveHelp(const CellCursor &cell) const;    // the tooltip's values
    QString toolTipText(const CellCursor &cell) const; // elementHelp, then liveHelp
    // Tells the source the devices of the rungs on screen (an online source polls only those).
    void tellWatched();

    Document *m_document;
    CellCursor m_cursor;
    double m_zoom = 1.0;
    bool m_fitWidth = false;
    bool m_namesFirst = false;
    QStringListModel *m_completions = nullptr;
    CellCursor m_dragFrom{-1, 0, 0}; // where the left button went down
    // The tooltip this view shows, so that its values follow the snapshots while it is up.
    CellCursor m_tipCell{-1, 0, 0};
    QPoint m_tipAt;
    QString m_tipText;
    QPointF m_pressAt;     // the viewport position of that press
    QString m_pressDevice; // the device of the pressed cell: a drag out of the view carries it
    // How far the pressed cell moved on screen when the press moved the cursor (the spare row
    // follows the cursor's rung): later positions of the same gesture are shifted by it so
    // they are read in the layout the press was read in.
    QPointF m_pressShift;
    // The cell a right press chose: its context menu is that cell's, though the layout moved
    // under the pointer when the press moved the cursor (and the spare row) to its rung.
    CellCursor m_contextCell{-1, 0, 0};
    quint64 m_shownRevision = 0; // the document's rungsRevision() the cursor was last placed in
    QKeySequence m_tool;         // the armed palette tool, empty: select
    int m_anchorRung = -1;       // where a rung selection started; -1: none
    int m_anchorColumn = -1;     // where a cell selection in the cursor's row started
    std::vector<double> m_top;   // y of each rung at zoom 1, plus the total height at the end
    QLineEdit *m_editor = nullptr;
    QLabel *m_notice = nullptr;
    std::map<int, bool> m_breakpoints;
    CellCursor m_stoppedAt{-1, -1, -1};
    QPointer<model::MonitorSource> m_source;
    MonitorCommands *m_commands = nullptr;
    // The overlays of the rungs on screen, from m_shown; a rung absent is computed when drawn.
    std::shared_ptr<const model::Snapshot> m_shown;
    std::map<int, model::RungOverlay> m_overlays;
    std::vector<model::Address> m_watched; // what tellWatched last told
};

} // namespace rung::editor
