#pragma once

// Where the window's parts are: the ladder and the instruction list as tabs or side by side,
// the docks' first arrangement (dock_layout.h), the layout the user leaves restored at the
// next start, and View > Reset Window Layout, which brings every dock back to its first
// place. It knows the window's parts by their object names and nothing of what they show,
// so it works on any QMainWindow with those docks (its test uses one of its own).

#include <QObject>
#include <QPointer>
#include <QStringList>

class QAction;
class QMainWindow;
class QMenu;
class QSplitter;
class QTabWidget;
class QWidget;

namespace rung::app {

class LayoutController : public QObject {
    Q_OBJECT

public:
    // Makes the window's central widget: the two pages as tabs, or side by side in a
    // splitter. The docks must be the window's before arrange() or restore().
    LayoutController(QMainWindow *window, QWidget *ladder, QWidget *listing,
                     QObject *parent = nullptr);

    void setSideBySide(bool sideBySide); // remembered for the next start
    bool sideBySide() const { return m_sideBySide; }
    // Brings a page (the ladder or the list) to the front; side by side both are in front.
    void showPage(QWidget *page);

    // The docks where a first start puts them and the window as large as the screen lets it
    // be; then the geometry, docks and splitter the user left, when the settings have them.
    void restore();
    // Remembers the window's geometry, its docks and the splitter for the next start.
    void save() const;
    // Every dock back to its first place, docked; the docks a first start shows are shown
    // again (a dock the user has open stays open).
    void resetLayout();

    // View > Ladder and List Side by Side, Reset Window Layout (in the language installed).
    void addActions(QMenu *view);
    void retranslate(); // the tabs' titles

    // Whether the screen is wide enough for a column on each side of the ladder.
    bool wideScreen() const;

signals:
    void sideBySideChanged(bool sideBySide);

protected:
    // The docks' tab bars, as Qt makes them: whole titles (scrolled), never "P..." / "Si...".
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void place(bool sideBySide); // the pages in the tabs or the splitter

    QMainWindow *m_window;
    QWidget *m_ladder;
    QWidget *m_listing;
    QTabWidget *m_tabs;
    QSplitter *m_split;
    QPointer<QAction> m_sideAction;
    bool m_sideBySide = false;
    // The docks a first start shows (Reset Window Layout shows them again), by object name.
    QStringList m_shownAtStart;
};

} // namespace rung::app
