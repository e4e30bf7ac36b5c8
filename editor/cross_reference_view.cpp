#include "cross_reference_view.h"

#include "cross_reference_model.h"
#include "document.h"

#include "model/target/target_lists.h"

#include <QEvent>
#include <QHeaderView>
#include <QLineEdit>
#include <QStyle>
#include <QTreeView>
#include <QVBoxLayout>

#include <algorithm>
#include <vector>

namespace rung::editor {

void CrossReferenceView::retranslate() {
    setHint();
    m_model->retranslate();
    fitColumns();
}

void CrossReferenceView::setHint() {
    // The field is as narrow as the dock (about 300 px): the short text as its placeholder,
    // the whole one as its tooltip (in Hungarian the whole one was cut off).
    // The examples are the target's own: its first input and what it starts with.
    const QString device = model::exampleDevice(m_document->target());
    qsizetype letters = 0;
    while (letters < device.size() && device[letters].isLetter())
        ++letters;
    const QString prefix =
        letters > 0 ? device.left(letters) : device.section(QLatin1Char('.'), 0, 0);
    m_filter->setPlaceholderText(tr("Device or prefix (%1, %2)").arg(device, prefix));
    m_filter->setToolTip(tr("Device or prefix (%1, %2); empty: every device").arg(device, prefix));
}

void CrossReferenceView::fitColumns() {
    QHeaderView *header = m_tree->header();
    const int columns = header->count();
    std::vector<int> width(static_cast<std::size_t>(columns));
    // A step is written with four digits (these PLCs hold fewer than 10000 steps).
    const int digits = m_tree->fontMetrics().horizontalAdvance(QStringLiteral("0000")) +
                       2 * m_tree->style()->pixelMetric(QStyle::PM_FocusFrameHMargin) + 8;
    int used = 0;
    for (int c = 0; c < columns; ++c) {
        // The style's hint for a title leaves it a pixel short in some fonts: the text's own
        // width and the header's margins are the floor.
        const QString title = m_model->headerData(c, Qt::Horizontal).toString();
        const int titleWidth = header->fontMetrics().horizontalAdvance(title) +
                               2 * header->style()->pixelMetric(QStyle::PM_HeaderMargin) + 8;
        width[static_cast<std::size_t>(c)] =
            std::max({header->sectionSizeHint(c), titleWidth,
                      c == CrossReferenceModel::StepColumn ? digits : 0});
        used += width[static_cast<std::size_t>(c)];
    }
    const int extra = std::max(0, m_tree->viewport()->width() - used);
    const int sharers[] = {CrossReferenceModel::DeviceColumn, CrossReferenceModel::UseColumn,
                           CrossReferenceModel::InstructionColumn};
    for (int k = 0; k < 3 && sharers[k] < columns; ++k)
        width[static_cast<std::size_t>(sharers[k])] += extra / 3 + (k < extra % 3 ? 1 : 0);
    for (int c = 0; c < columns; ++c)
        header->resizeSection(c, width[static_cast<std::size_t>(c)]);
}

bool CrossReferenceView::eventFilter(QObject *watched, QEvent *event) {
    if (watched == m_tree->viewport() && event->type() == QEvent::Resize)
        fitColumns();
    return QWidget::eventFilter(watched, event);
}

void CrossReferenceView::changeEvent(QEvent *event) {
    // The rows follow the program's change that a new language brings (Document::recheck).
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

CrossReferenceView::CrossReferenceView(Document *document, QWidget *parent)
    : QWidget(parent)
    , m_document(document)
    , m_model(new CrossReferenceModel(document, this)) {
    auto *layout = new QVBoxLayout(this);
    m_filter = new QLineEdit(this);
    m_filter->setObjectName(QStringLiteral("crossReferenceFilter"));
    m_filter->setClearButtonEnabled(true);
    m_tree = new QTreeView(this);
    m_tree->setModel(m_model);
    m_tree->setDragEnabled(true);
    m_tree->setDragDropMode(QAbstractItemView::DragOnly);
    m_tree->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_tree->setObjectName(QStringLiteral("crossReferenceTree"));
    m_tree->setUniformRowHeights(true);
    m_tree->setAlternatingRowColors(true);
    // The uses fit the dock's width, no sideways scrolling (in Hungarian the use column ran
    // off the side), and no title is cut (Stretch cut them all in a narrow dock): fitColumns
    // gives each column its title's width, the step its digits', and shares the rest; a text
    // longer than its column ends in "..." with the whole of it as the tooltip.
    m_tree->header()->setStretchLastSection(false);
    m_tree->viewport()->installEventFilter(this);
    retranslate();
    layout->addWidget(m_filter);
    layout->addWidget(m_tree, 1);
    connect(m_filter, &QLineEdit::textChanged, m_model, &CrossReferenceModel::setFilter);
    connect(m_model, &QAbstractItemModel::modelReset, this, &CrossReferenceView::arrangeRows);
    // Another target has other devices: the hint's examples are its own.
    connect(document, &Document::programChanged, this, &CrossReferenceView::setHint);
    connect(m_tree, &QTreeView::activated, this, [this](const QModelIndex &index) {
        const QVariant rung = index.data(CrossReferenceModel::RungRole);
        if (rung.isValid())
            emit rungActivated(rung.toInt());
    });
}

void CrossReferenceView::arrangeRows() {
    const int rows = m_model->rowCount();
    const int devices = static_cast<int>(m_model->uses().devices.size());
    if (m_model->exact() || devices <= 3)
        m_tree->expandAll();
    if (m_model->capped())
        m_tree->setFirstColumnSpanned(rows - 1, {}, true);
}

void CrossReferenceView::setOnScreen(bool onScreen) {
    m_model->setFollowing(onScreen);
}

void CrossReferenceView::refresh() {
    m_model->refresh();
}

} // namespace rung::editor
