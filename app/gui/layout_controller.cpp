#include "layout_controller.h"

#include "dock_layout.h"

#include <QAction>
#include <QChildEvent>
#include <QDockWidget>
#include <QLayout>
#include <QMainWindow>
#include <QMenu>
#include <QScreen>
#include <QSettings>
#include <QSplitter>
#include <QTabBar>
#include <QTabWidget>
#include <QTimer>
#include <QToolBar>
#include <QVBoxLayout>

namespace rung::app {

namespace {

const QString kSideBySideKey = QStringLiteral("view/sideBySide");
const QString kSplitKey = QStringLiteral("view/split");
const QString kGeometryKey = QStringLiteral("window/geometry");
const QString kStateKey = QStringLiteral("window/state");

QList<QDockWidget *> docksOf(QMainWindow *window) {
    return window->findChildren<QDockWidget *>(Qt::FindDirectChildrenOnly);
}

} // namespace

LayoutController::LayoutController(QMainWindow *window, QWidget *ladder, QWidget *listing,
                                   QObject *parent)
    : QObject(parent)
    , m_window(window)
    , m_ladder(ladder)
    , m_listing(listing)
    , m_tabs(new QTabWidget)
    , m_split(new QSplitter(Qt::Horizontal)) {
    m_split->setObjectName(QStringLiteral("ladderListSplit"));
    auto *central = new QWidget;
    auto *layout = new QVBoxLayout(central);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_tabs);
    layout->addWidget(m_split);
    window->setCentralWidget(central);
    window->installEventFilter(this);
    place(false); // as tabs until restore() reads the user's choice
}

void LayoutController::setSideBySide(bool sideBySide) {
    const bool changed = sideBySide != m_sideBySide;
    QSettings().setValue(kSideBySideKey, sideBySide);
    place(sideBySide);
    if (m_sideAction && m_sideAction->isChecked() != sideBySide)
        m_sideAction->setChecked(sideBySide);
    if (changed)
        emit sideBySideChanged(sideBySide);
}

void LayoutController::place(bool sideBySide) {
    m_sideBySide = sideBySide;
    m_tabs->clear();
    if (sideBySide) {
        m_split->addWidget(m_ladder);
        m_split->addWidget(m_listing);
        // The list's comment lines want about 60 characters; the ladder keeps the larger part.
        m_split->setStretchFactor(0, 3);
        m_split->setStretchFactor(1, 2);
        // Out of the tabs the pages come hidden (a tab widget hides all but its current one).
        m_ladder->show();
        m_listing->show();
        m_split->show();
        m_tabs->hide();
    } else {
        m_tabs->addTab(m_ladder, QString());
        m_tabs->addTab(m_listing, QString());
        retranslate();
        m_tabs->show();
        m_split->hide();
    }
}

void LayoutController::showPage(QWidget *page) {
    if (!m_sideBySide)
        m_tabs->setCurrentWidget(page);
}

bool LayoutController::wideScreen() const {
    return m_window->screen()->availableGeometry().width() >= kWideScreen;
}

void LayoutController::restore() {
    m_shownAtStart.clear();
    for (QDockWidget *d : docksOf(m_window))
        if (!d->isHidden())
            m_shownAtStart << d->objectName();
    // Editing docks left, live ones together, findings below (dock_layout.h); a saved
    // layout, restored below, keeps the user's own.
    const bool wide = wideScreen();
    arrangeDocks(m_window, wide);
    // The layout took its minimum size while the docks were added one beside the other
    // (four below the ladder: wider than an 800 px screen); grouped, they need less, and the
    // resize below must not be held to the old minimum.
    m_window->layout()->activate();
    QSettings settings;
    setSideBySide(settings.value(kSideBySideKey, false).toBool());
    m_split->restoreState(settings.value(kSplitKey).toByteArray());
    // Roomy where the screen allows, never larger than it: on a 1366x768 laptop a 1400x900
    // window would hide the problems and the status bar below the screen's edge.
    const QSize available = m_window->screen()->availableGeometry().size();
    m_window->resize(QSize(1400, 900).boundedTo(available - QSize(16, 32)));
    if (auto *problems = m_window->findChild<QDockWidget *>(QStringLiteral("problemsDock")))
        m_window->resizeDocks({problems}, {150}, Qt::Vertical);
    if (auto *project = m_window->findChild<QDockWidget *>(QStringLiteral("projectDock")))
        m_window->resizeDocks({project}, {230}, Qt::Horizontal);
    m_window->restoreGeometry(settings.value(kGeometryKey).toByteArray());
    if (!m_window->restoreState(settings.value(kStateKey).toByteArray(), kDockLayoutVersion)) {
        // First start (or a layout of the docks before issue 31): the columns as wide as the
        // ladder leaves them. Docks take sizes once laid out.
        QTimer::singleShot(0, m_window, [window = m_window, wide] { sizeDocks(window, wide); });
    }
}

void LayoutController::save() const {
    QSettings settings;
    settings.setValue(kGeometryKey, m_window->saveGeometry());
    settings.setValue(kStateKey, m_window->saveState(kDockLayoutVersion));
    if (m_sideBySide)
        settings.setValue(kSplitKey, m_split->saveState());
}

void LayoutController::resetLayout() {
    // A floating dock re-docks where it belongs; the toolbars come back to the top.
    for (QDockWidget *d : docksOf(m_window))
        d->setFloating(false);
    for (QToolBar *bar : m_window->findChildren<QToolBar *>(Qt::FindDirectChildrenOnly)) {
        m_window->addToolBar(Qt::TopToolBarArea, bar);
        bar->show();
    }
    // Shown before they are arranged: arrangeDocks brings the project and the problems to
    // the front of their tabs, which a dock still closed cannot be.
    for (QDockWidget *d : docksOf(m_window))
        if (m_shownAtStart.contains(d->objectName()))
            d->show();
    const bool wide = wideScreen();
    arrangeDocks(m_window, wide);
    m_window->layout()->activate();
    sizeDocks(m_window, wide);
}

void LayoutController::addActions(QMenu *view) {
    QAction *side = view->addAction(tr("Ladder and List &Side by Side"));
    side->setObjectName(QStringLiteral("sideBySideAction"));
    side->setCheckable(true);
    side->setChecked(m_sideBySide);
    connect(side, &QAction::toggled, this, &LayoutController::setSideBySide);
    m_sideAction = side;
    QAction *reset =
        view->addAction(tr("&Reset Window Layout"), this, &LayoutController::resetLayout);
    reset->setObjectName(QStringLiteral("resetLayoutAction"));
    reset->setToolTip(tr("Every panel back to its first place, closed ones shown again"));
}

void LayoutController::retranslate() {
    if (m_tabs->count() == 2) {
        m_tabs->setTabText(0, tr("Ladder"));
        m_tabs->setTabText(1, tr("Instruction List"));
    }
}

bool LayoutController::eventFilter(QObject *watched, QEvent *event) {
    // Qt makes a tab bar for docks tabbed together when it lays them out, eliding the titles
    // to the dock's width: with the project, the cross reference, the terminals and the
    // simulation beside the ladder at 1366x768 every tab read "P...", "Si...". Whole titles
    // and scroll arrows tell each apart; polished is after Qt's own settings.
    if (watched == m_window && event->type() == QEvent::ChildPolished)
        if (auto *tabs = qobject_cast<QTabBar *>(static_cast<QChildEvent *>(event)->child())) {
            tabs->setElideMode(Qt::ElideNone);
            tabs->setUsesScrollButtons(true);
        }
    return QObject::eventFilter(watched, event);
}

} // namespace rung::app
