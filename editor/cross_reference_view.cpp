#include "cross_reference_view.h"

#include "device_mime.h"

#include <QEvent>

#include "model/target/address.h"
#include "model/target/target_lists.h"

#include <QHeaderView>
#include <QLineEdit>
#include <QStyle>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <map>
#include <optional>
#include <vector>

namespace rung::editor {

namespace {

constexpr int kDeviceRole = Qt::UserRole + 1;

// The uses' tree: a device row drags its device to the watch table or the timing chart.
class DeviceTree : public QTreeWidget {
public:
    using QTreeWidget::QTreeWidget;

protected:
    QMimeData *mimeData(const QList<QTreeWidgetItem *> &items) const override {
        QStringList devices;
        for (const QTreeWidgetItem *item : items) {
            const QTreeWidgetItem *device = item->parent() ? item->parent() : item;
            const QString text = device->data(0, kDeviceRole).toString();
            if (!text.isEmpty() && !devices.contains(text))
                devices << text;
        }
        return devices.isEmpty() ? nullptr : deviceMimeData(devices);
    }
    QStringList mimeTypes() const override { return {deviceMimeType()}; }
};

enum class Use { Contact, Coil, Box };

struct Place {
    int rung;
    int step;
    Use use;
    QString instruction;
};

Use useOf(model::Op op) {
    switch (op) {
    case model::Op::Load:
    case model::Op::And:
    case model::Op::Or:
        return Use::Contact;
    case model::Op::Out:
    case model::Op::Set:
    case model::Op::Reset:
    case model::Op::PulseRise:
    case model::Op::PulseFall:
        return Use::Coil;
    default:
        return Use::Box;
    }
}

} // namespace

void CrossReferenceView::retranslate() {
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
    // The rung rows under a device say "rung N" themselves: the first title names the device
    // only ("Device / rung" took the room of a column and a half in Hungarian).
    m_tree->setHeaderLabels({tr("Device"), tr("Step"), tr("Use"), tr("Instruction")});
    fitColumns();
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
        const QString title = m_tree->headerItem()->text(c);
        const int titleWidth = header->fontMetrics().horizontalAdvance(title) +
                               2 * header->style()->pixelMetric(QStyle::PM_HeaderMargin) + 8;
        width[static_cast<std::size_t>(c)] =
            std::max({header->sectionSizeHint(c), titleWidth, c == 1 ? digits : 0});
        used += width[static_cast<std::size_t>(c)];
    }
    const int extra = std::max(0, m_tree->viewport()->width() - used);
    const int sharers[] = {0, 2, 3};
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
    , m_document(document) {
    auto *layout = new QVBoxLayout(this);
    m_filter = new QLineEdit(this);
    m_filter->setObjectName(QStringLiteral("crossReferenceFilter"));
    m_filter->setClearButtonEnabled(true);
    m_tree = new DeviceTree(this);
    m_tree->setDragEnabled(true);
    m_tree->setDragDropMode(QAbstractItemView::DragOnly);
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
    connect(m_filter, &QLineEdit::textChanged, this, &CrossReferenceView::refresh);
    connect(document, &Document::programChanged, this, [this] {
        retranslate(); // another target has other devices
        m_stale = true;
        if (m_onScreen)
            refresh();
    });
    connect(m_tree, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem *item) {
        const QVariant rung = item->data(0, Qt::UserRole);
        if (rung.isValid())
            emit rungActivated(rung.toInt());
    });
}

void CrossReferenceView::setOnScreen(bool onScreen) {
    m_onScreen = onScreen;
    if (onScreen && m_stale)
        refresh();
}

void CrossReferenceView::refresh() {
    m_stale = false;
    m_tree->clear();
    const model::Target &t = m_document->target();
    const QString filter = m_filter->text().trimmed();
    // A whole device shows only its uses; otherwise the text is a prefix of the names.
    std::optional<model::Address> exact;
    if (!filter.isEmpty()) {
        auto parsed = model::parseAddress(t, filter, m_document->modelVariant());
        if (auto *a = std::get_if<model::Address>(&parsed))
            exact = *a;
    }
    std::map<model::Address, std::vector<Place>> uses;
    int count = 0;
    const model::ToListingResult &listing = m_document->listing();
    for (std::size_t r = 0; r + 1 < listing.rungFirst.size() && count < kMaxUses; ++r) {
        for (int i = listing.rungFirst[r]; i < listing.rungFirst[r + 1]; ++i) {
            const model::Instruction &ins = listing.list.instructions[static_cast<std::size_t>(i)];
            for (const model::Operand &o : ins.operands) {
                if (o.kind != model::Operand::Kind::Device)
                    continue;
                if (exact ? !(o.address == *exact)
                          : !model::formatAddress(t, o.address)
                                 .startsWith(filter, Qt::CaseInsensitive))
                    continue;
                auto &places = uses[o.address];
                if (places.empty() || places.back().step != ins.step) {
                    places.push_back({static_cast<int>(r), ins.step, useOf(ins.op()),
                                      model::printInstruction(t, ins)});
                    ++count;
                }
            }
        }
    }
    const QString useText[] = {tr("contact"), tr("coil"), tr("box")};
    for (const auto &[address, places] : uses) {
        auto *device = new QTreeWidgetItem(m_tree);
        const model::Symbol *symbol = m_document->project().symbol(address);
        const QString name = model::formatAddress(t, address);
        device->setData(0, kDeviceRole, name);
        device->setText(0, symbol && !symbol->name.isEmpty()
                               ? QStringLiteral("%1  %2").arg(name, symbol->name)
                               : name);
        device->setToolTip(0, device->text(0)); // a long name ends in "..." in a narrow dock
        int counts[3] = {0, 0, 0};
        for (const Place &p : places) {
            ++counts[static_cast<int>(p.use)];
            auto *item = new QTreeWidgetItem(device);
            item->setText(0, tr("rung %1").arg(p.rung + 1));
            item->setText(1, QStringLiteral("%1").arg(p.step, 4, 10, QLatin1Char('0')));
            item->setText(2, useText[static_cast<int>(p.use)]);
            item->setText(3, p.instruction);
            item->setData(0, Qt::UserRole, p.rung);
        }
        QStringList summary;
        for (int k = 0; k < 3; ++k)
            if (counts[k] > 0)
                summary << QStringLiteral("%1 × %2").arg(counts[k]).arg(useText[k]);
        device->setText(2, summary.join(QStringLiteral(", ")));
        device->setToolTip(2, device->text(2));
        if (symbol && !symbol->comment.isEmpty()) {
            device->setText(3, symbol->comment);
            device->setToolTip(3, symbol->comment);
        }
        device->setExpanded(exact.has_value() || uses.size() <= 3);
    }
    if (count >= kMaxUses) {
        auto *more = new QTreeWidgetItem(m_tree);
        more->setText(
            0, tr("The first %1 uses; type a device or a prefix for the rest").arg(kMaxUses));
        more->setFirstColumnSpanned(true);
    }
}

} // namespace rung::editor
