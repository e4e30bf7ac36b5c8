#include "network_traffic_view.h"

#include "file_dialogs.h"
#include "network/station.h"
#include "network/traffic.h"
#include "network_traffic_model.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QEvent>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QSaveFile>
#include <QScrollBar>
#include <QSortFilterProxyModel>
#include <QStyle>
#include <QTableView>
#include <QTextStream>
#include <QVBoxLayout>

namespace rung::app {

// The rows the choosers let through: a wire, a station (the frame's sender or receiver) and
// the frames with an error code, a problem or a fault's note.
class NetworkTrafficFilter : public QSortFilterProxyModel {
public:
    using QSortFilterProxyModel::QSortFilterProxyModel;
    void set(const QString &wire, const QString &station, bool errorsOnly) {
        if (wire == m_wire && station == m_station && errorsOnly == m_errorsOnly)
            return;
        m_wire = wire;
        m_station = station;
        m_errorsOnly = errorsOnly;
        // One new mapping and one layoutChanged: invalidateRowsFilter() would remove the rows
        // range by range, a signal each, and a filter that keeps every other of 100,000 rows
        // took the header seconds to follow.
        invalidate();
    }
    QString wire() const { return m_wire; }
    QString station() const { return m_station; }
    bool errorsOnly() const { return m_errorsOnly; }

protected:
    bool filterAcceptsRow(int row, const QModelIndex &parent) const override {
        const QModelIndex index = sourceModel()->index(row, 0, parent);
        if (!m_wire.isEmpty() && index.data(NetworkTrafficModel::WireRole).toString() != m_wire)
            return false;
        if (!m_station.isEmpty() &&
            !index.data(NetworkTrafficModel::OwnersRole).toStringList().contains(m_station))
            return false;
        return !m_errorsOnly || index.data(NetworkTrafficModel::FailedRole).toBool();
    }

private:
    QString m_wire;
    QString m_station;
    bool m_errorsOnly = false;
};

NetworkTrafficView::NetworkTrafficView(QWidget *parent)
    : QWidget(parent)
    , m_model(new NetworkTrafficModel(this))
    , m_filter(new NetworkTrafficFilter(this))
    , m_wire(new QComboBox(this))
    , m_station(new QComboBox(this))
    , m_errorsOnly(new QCheckBox(this))
    , m_wireLabel(new QLabel(this))
    , m_stationLabel(new QLabel(this))
    , m_status(new QLabel(this))
    , m_save(new QPushButton(this))
    , m_table(new QTableView(this)) {
    m_filter->setSourceModel(m_model);
    m_wire->setObjectName(QStringLiteral("trafficWire"));
    m_station->setObjectName(QStringLiteral("trafficStation"));
    m_errorsOnly->setObjectName(QStringLiteral("trafficErrorsOnly"));
    m_save->setObjectName(QStringLiteral("trafficSave"));
    m_status->setObjectName(QStringLiteral("trafficStatus"));
    m_table->setObjectName(QStringLiteral("trafficTable"));
    m_wire->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_station->setSizeAdjustPolicy(QComboBox::AdjustToContents);

    m_wireLabel->setBuddy(m_wire);
    m_stationLabel->setBuddy(m_station);
    auto *bar = new QHBoxLayout;
    bar->addWidget(m_wireLabel);
    bar->addWidget(m_wire);
    bar->addSpacing(8);
    bar->addWidget(m_stationLabel);
    bar->addWidget(m_station);
    bar->addSpacing(8);
    bar->addWidget(m_errorsOnly);
    bar->addSpacing(8);
    bar->addWidget(m_status, 1);
    bar->addWidget(m_save);

    m_table->setModel(m_filter);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setWordWrap(false);
    m_table->setAlternatingRowColors(false);
    m_table->verticalHeader()->hide();
    // One fixed row height: the table never measures 100,000 rows.
    m_table->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 6);
    QHeaderView *header = m_table->horizontalHeader();
    header->setSectionResizeMode(QHeaderView::Interactive);
    header->setStretchLastSection(true);
    header->setHighlightSections(false);
    connect(header, &QHeaderView::sectionResized, this, [this](int column) {
        if (!m_sizing && column < int(m_byHand.size()))
            m_byHand[std::size_t(column)] = true;
    });
    // The table samples its first rows for the columns' widths (fitColumns); the long
    // texts (data, error, note) stop at a width that leaves the bytes in sight.
    m_table->horizontalHeader()->setResizeContentsPrecision(200);
    fitColumns();

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(bar);
    layout->addWidget(m_table, 1);

    m_wire->addItem(QString(), QString());
    m_station->addItem(QString(), QString());
    retranslate();

    connect(m_wire, &QComboBox::currentIndexChanged, this, &NetworkTrafficView::chooserChanged);
    connect(m_station, &QComboBox::currentIndexChanged, this, &NetworkTrafficView::chooserChanged);
    connect(m_errorsOnly, &QCheckBox::toggled, this, &NetworkTrafficView::chooserChanged);
    connect(m_save, &QPushButton::clicked, this, &NetworkTrafficView::save);
    connect(m_model, &NetworkTrafficModel::rowsDropped, this, &NetworkTrafficView::updateStatus);
    connect(m_filter, &QAbstractItemModel::rowsInserted, this,
            [this](const QModelIndex &, int first, int last) {
                growColumns(first, last);
                updateStatus();
                if (m_follow)
                    m_table->scrollToBottom();
            });
    connect(m_filter, &QAbstractItemModel::modelReset, this, &NetworkTrafficView::updateStatus);
    connect(m_filter, &QAbstractItemModel::rowsRemoved, this, &NetworkTrafficView::updateStatus);
    connect(m_table->verticalScrollBar(), &QScrollBar::valueChanged, this,
            [this](int value) { m_follow = value >= m_table->verticalScrollBar()->maximum(); });
    connect(m_table->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex &current) {
                if (current.isValid())
                    emit frameChosen(current.data(NetworkTrafficModel::StartUsRole).toLongLong());
            });
    updateStatus();
}

NetworkTrafficView::~NetworkTrafficView() {
    // Closing a window hides its children before they go: the scroll bar and the selection
    // would still call into this view while its members are gone.
    for (QObject *child : findChildren<QObject *>())
        disconnect(child, nullptr, this, nullptr);
    disconnect(m_table->selectionModel(), nullptr, this, nullptr);
    disconnect(m_filter, nullptr, this, nullptr);
}

void NetworkTrafficView::retranslate() {
    m_wireLabel->setText(tr("&Wire:"));
    m_stationLabel->setText(tr("S&tation:"));
    m_errorsOnly->setText(tr("&Errors only"));
    m_errorsOnly->setToolTip(
        tr("Only the frames with an error code, a problem (a wrong sum or CRC, a frame cut "
           "short) or a fault's note"));
    m_save->setText(tr("&Save..."));
    m_save->setToolTip(tr("Save the frames shown as CSV or as text"));
    m_wire->setItemText(0, tr("All wires"));
    m_station->setItemText(0, tr("All stations"));
    updateStatus();
}

void NetworkTrafficView::changeEvent(QEvent *event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        m_model->retranslate();
        fitColumns();
    }
    QWidget::changeEvent(event);
}

void NetworkTrafficView::setNetwork(const network::Network &network, const QString &file) {
    m_file = file.isEmpty() ? network.description().file : file;
    m_model->setNetwork(network);
    const QSignalBlocker wireBlock(m_wire);
    const QSignalBlocker stationBlock(m_station);
    while (m_wire->count() > 1)
        m_wire->removeItem(1);
    for (const auto &wire : network.wires())
        m_wire->addItem(wire->name, wire->name);
    while (m_station->count() > 1)
        m_station->removeItem(1);
    m_wire->setCurrentIndex(0);
    m_station->setCurrentIndex(0);
    for (const auto &station : network.stations())
        m_station->addItem(station->name(), station->name());
    for (const network::DeviceDescription &device : network.description().devices)
        m_station->addItem(device.name, device.name);
    m_filter->set({}, {}, m_errorsOnly->isChecked());
    m_follow = true;
    updateStatus();
}

void NetworkTrafficView::append(std::vector<network::TrafficRecord> records) {
    const bool first = m_model->rowCount() == 0;
    m_model->append(std::move(records));
    if (first && m_model->rowCount() > 0)
        fitColumns();
}

int NetworkTrafficView::columnCap(int column) const {
    const int em = m_table->fontMetrics().horizontalAdvance(QLatin1Char('M'));
    switch (column) {
    case NetworkTrafficModel::Sender:
    case NetworkTrafficModel::Receiver:
    case NetworkTrafficModel::Address:
        return 14 * em;
    case NetworkTrafficModel::Command:
        return 20 * em;
    case NetworkTrafficModel::Data:
    case NetworkTrafficModel::Note:
        return 12 * em;
    case NetworkTrafficModel::Error: // what went wrong: readable before the bytes
        return 24 * em;
    default:
        return 1 << 20;
    }
}

void NetworkTrafficView::fitColumns() {
    m_sizing = true;
    m_table->resizeColumnsToContents();
    const int em = m_table->fontMetrics().horizontalAdvance(QLatin1Char('M'));
    for (int column = 0; column < NetworkTrafficModel::Bytes; ++column)
        m_table->setColumnWidth(column, std::min(m_table->columnWidth(column), columnCap(column)));
    for (int column :
         {NetworkTrafficModel::Data, NetworkTrafficModel::Error, NetworkTrafficModel::Note})
        m_table->setColumnWidth(column, std::max(m_table->columnWidth(column), 5 * em));
    m_byHand.assign(NetworkTrafficModel::ColumnCount, false);
    m_sizing = false;
}

void NetworkTrafficView::growColumns(int first, int last) {
    if (m_byHand.empty())
        return;
    // A long run's batch may hold thousands of rows: the last ones are as wide as any (the
    // time grows, the texts repeat), and measuring them all would cost the UI its frames.
    first = std::max(first, last - 63);
    const QFontMetrics metrics = m_table->fontMetrics();
    const int padding = 2 * m_table->style()->pixelMetric(QStyle::PM_FocusFrameHMargin) + 8;
    m_sizing = true;
    for (int column = 0; column < NetworkTrafficModel::Bytes; ++column) {
        if (m_byHand[std::size_t(column)] || m_table->isColumnHidden(column))
            continue;
        int widest = 0;
        for (int row = first; row <= last; ++row)
            widest = std::max(
                widest, metrics.horizontalAdvance(m_filter->index(row, column).data().toString()));
        const int wanted = std::min(widest + padding, columnCap(column));
        if (wanted > m_table->columnWidth(column))
            m_table->setColumnWidth(column, wanted);
    }
    m_sizing = false;
}

void NetworkTrafficView::clear() {
    m_model->clear();
}

void NetworkTrafficView::setWireFilter(const QString &wire) {
    const int i = m_wire->findData(wire);
    m_wire->setCurrentIndex(std::max(0, i));
}

void NetworkTrafficView::setStationFilter(const QString &station) {
    const int i = m_station->findData(station);
    m_station->setCurrentIndex(std::max(0, i));
}

void NetworkTrafficView::setErrorsOnly(bool on) {
    m_errorsOnly->setChecked(on);
}

int NetworkTrafficView::shownRows() const {
    return m_filter->rowCount();
}

void NetworkTrafficView::chooserChanged() {
    m_filter->set(m_wire->currentData().toString(), m_station->currentData().toString(),
                  m_errorsOnly->isChecked());
    updateStatus();
}

void NetworkTrafficView::updateStatus() {
    const QLocale locale;
    QString text =
        m_filter->rowCount() == m_model->rowCount()
            ? tr("%n frame(s)", "", m_model->rowCount())
            : tr("%1 of %2 frames")
                  .arg(locale.toString(m_filter->rowCount()), locale.toString(m_model->rowCount()));
    if (m_model->droppedRows() > 0)
        text +=
            QStringLiteral("; ") +
            tr("%1 older frames were let go (the view keeps the last %2)")
                .arg(locale.toString(m_model->droppedRows()), locale.toString(m_model->maxRows()));
    m_status->setText(text);
    m_save->setEnabled(m_filter->rowCount() > 0);
}

bool NetworkTrafficView::saveCsv(const QString &path, QString *error) const {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) {
        *error = tr("Cannot write %1: %2").arg(QDir::toNativeSeparators(path), file.errorString());
        return false;
    }
    QTextStream out(&file);
    const auto quote = [](const QString &cell) {
        if (!cell.contains(u',') && !cell.contains(u'"') && !cell.contains(u'\n'))
            return cell;
        return u'"' + QString(cell).replace(u'"', QStringLiteral("\"\"")) + u'"';
    };
    QStringList header;
    for (int c = 0; c < NetworkTrafficModel::ColumnCount; ++c)
        header << quote(m_model->headerData(c, Qt::Horizontal).toString());
    out << header.join(u',') << '\n';
    for (int row = 0; row < m_filter->rowCount(); ++row) {
        const int source = m_filter->mapToSource(m_filter->index(row, 0)).row();
        QStringList cells;
        for (int c = 0; c < NetworkTrafficModel::ColumnCount; ++c)
            cells << quote(m_model->text(source, c));
        out << cells.join(u',') << '\n';
    }
    out.flush();
    if (!file.commit()) {
        *error = tr("Cannot write %1: %2").arg(QDir::toNativeSeparators(path), file.errorString());
        return false;
    }
    return true;
}

bool NetworkTrafficView::saveText(const QString &path, QString *error) const {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) {
        *error = tr("Cannot write %1: %2").arg(QDir::toNativeSeparators(path), file.errorString());
        return false;
    }
    QTextStream out(&file);
    out << network::trafficHeader(QFileInfo(m_file).fileName()) << '\n';
    // What the file does not hold, it says (the view's cap, the filters).
    if (m_model->droppedRows() > 0)
        out << "# "
            << tr("%1 older frames were let go before these (the view keeps the last %2)")
                   .arg(m_model->droppedRows())
                   .arg(m_model->maxRows())
            << '\n';
    if (m_filter->rowCount() != m_model->rowCount())
        out << "# "
            << tr("%1 of %2 frames: wire %3, station %4%5")
                   .arg(m_filter->rowCount())
                   .arg(m_model->rowCount())
                   .arg(m_filter->wire().isEmpty() ? tr("all") : m_filter->wire(),
                        m_filter->station().isEmpty() ? tr("all") : m_filter->station(),
                        m_filter->errorsOnly() ? tr(", errors only") : QString())
            << '\n';
    for (int row = 0; row < m_filter->rowCount(); ++row) {
        const int source = m_filter->mapToSource(m_filter->index(row, 0)).row();
        out << network::formatTraffic(m_model->record(source)) << '\n';
    }
    out.flush();
    if (!file.commit()) {
        *error = tr("Cannot write %1: %2").arg(QDir::toNativeSeparators(path), file.errorString());
        return false;
    }
    return true;
}

void NetworkTrafficView::save() {
    const QString start = m_file.isEmpty() ? QString()
                                           : QFileInfo(m_file).absolutePath() + u'/' +
                                                 QFileInfo(m_file).completeBaseName() +
                                                 QStringLiteral("-traffic.csv");
    QString path = askSaveFile(this, tr("Save Traffic"), start,
                               tr("CSV (*.csv);;Text, as rungstudio-cli writes it (*.txt)"));
    if (path.isEmpty())
        return;
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix != QStringLiteral("csv") && suffix != QStringLiteral("txt")) {
        path += QStringLiteral(".csv");
        if (QFileInfo::exists(path) &&
            QMessageBox::question(
                this, tr("Save Traffic"),
                tr("%1 already exists. Replace it?").arg(QDir::toNativeSeparators(path))) !=
                QMessageBox::Yes)
            return;
    }
    QString error;
    const bool saved = QFileInfo(path).suffix().toLower() == QStringLiteral("txt")
                           ? saveText(path, &error)
                           : saveCsv(path, &error);
    if (!saved)
        QMessageBox::warning(this, tr("Save Traffic"), error);
    else
        rememberFileDialogFolder(path);
}

} // namespace rung::app
