#include "ladder_export.h"

#include "editor/document.h"
#include "editor/ladder_painter.h"

#include <QDate>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QLocale>
#include <QPainter>
#include <QPrinter>
#include <QSaveFile>
#include <QSvgGenerator>

#include <set>

namespace rung::app {

namespace {

// Paints every rung, one below the other, starting at `top`; a new page when needed.
// With `paint` false it only lays the rungs out on pages (to count them for the header).
template <typename NewPage>
void paintProgram(QPainter &p, const editor::Document &document, const editor::LadderMetrics &m,
                  bool namesFirst, double pageHeight, double top, NewPage newPage,
                  bool paint = true) {
    const model::Project &project = document.project();
    editor::LadderPainter painter(project, m);
    painter.setNamesFirst(namesFirst); // as the view shows it
    const model::ToListingResult &listing = document.listing();
    double y = top;
    for (int i = 0; i < static_cast<int>(project.program.rungs.size()); ++i) {
        const double h = m.rungHeight(project.program.rungs[static_cast<std::size_t>(i)]);
        if (pageHeight > 0 && y + h > pageHeight && y > top) {
            newPage();
            y = top;
        }
        if (!paint) {
            y += h;
            continue;
        }
        editor::RungDecorations d; // step addresses, as on screen
        const auto first =
            static_cast<std::size_t>(i) < listing.rungFirst.size()
                ? static_cast<std::size_t>(listing.rungFirst[static_cast<std::size_t>(i)])
                : listing.list.instructions.size();
        if (first < listing.list.instructions.size())
            d.firstStep = listing.list.instructions[first].step;
        painter.paintRung(p, QPointF(0, y), i, d);
        y += h;
    }
}

editor::LadderMetrics exportMetrics(const model::Project &project) {
    editor::LadderMetrics m;
    int widest = std::max(1, project.target->limits.contactsPerRow);
    for (const model::Rung &r : project.program.rungs)
        widest = std::max(widest, r.columns);
    m.gridColumns = widest;
    m.foldColumns = std::max(0, project.target->limits.contactsPerRow); // as on screen
    return m;
}

double programHeight(const model::Project &project, const editor::LadderMetrics &m) {
    double h = 0;
    for (const model::Rung &r : project.program.rungs)
        h += m.rungHeight(r);
    return h;
}

} // namespace

bool ProgramExport::ladder(const QString &path, QString *error) const {
    const QString format = QFileInfo(path).suffix().toLower();
    const model::Project &project = m_document.project();
    const editor::LadderMetrics m = exportMetrics(project);
    const QSize size(static_cast<int>(m.width()), static_cast<int>(programHeight(project, m)) + 20);
    auto fail = [&] {
        if (error)
            *error = tr("%1 could not be written").arg(QDir::toNativeSeparators(path));
        return false;
    };
    if (format == QLatin1String("png")) {
        QImage image(size, QImage::Format_ARGB32);
        image.fill(Qt::white);
        QPainter p(&image);
        paintProgram(p, m_document, m, m_namesFirst, 0, 10, [] {});
        p.end();
        return image.save(path) || fail();
    }
    if (format == QLatin1String("svg")) {
        QFile probe(path); // QSvgGenerator does not say when it cannot write
        if (!probe.open(QIODevice::WriteOnly))
            return fail();
        probe.close();
        QSvgGenerator svg;
        svg.setFileName(path);
        svg.setSize(size);
        svg.setViewBox(QRect(QPoint(0, 0), size));
        svg.setTitle(QFileInfo(m_document.path()).baseName());
        QPainter p(&svg);
        paintProgram(p, m_document, m, m_namesFirst, 0, 10, [] {});
        return true;
    }
    if (format == QLatin1String("pdf")) {
        // A PDF is the printout: pages with the header, rung numbers and comments.
        QPrinter printer(QPrinter::HighResolution);
        printer.setOutputFormat(QPrinter::PdfFormat);
        printer.setOutputFileName(path);
        printer.setPageSize(QPageSize(QPageSize::A4));
        printer.setPageOrientation(QPageLayout::Landscape);
        printer.setPageMargins(QMarginsF(12, 10, 12, 10), QPageLayout::Millimeter);
        printer.setDocName(QFileInfo(m_document.path()).baseName());
        return print(&printer) || fail();
    }
    if (error)
        *error = tr("%1: the ladder can be exported as PDF, SVG or PNG").arg(path);
    return false;
}

bool ProgramExport::print(QPrinter *printer) const {
    const model::Project &project = m_document.project();
    const editor::LadderMetrics m = exportMetrics(project);
    QPainter p;
    if (!p.begin(printer))
        return false;
    // The ladder fills the page's width between the margins; the page header is drawn in the
    // same units, so it scales with it.
    const QRect page = printer->pageLayout().paintRectPixels(printer->resolution());
    const double scale = page.width() / m.width();
    p.scale(scale, scale);
    const double pageHeight = page.height() / scale;
    constexpr double kTop = 40; // below the header and its rule
    int pages = 1;
    paintProgram(
        p, m_document, m, m_namesFirst, pageHeight, kTop, [&] { ++pages; }, false);
    const QString projectName = m_document.name();
    const QString target =
        tr("%1 %2").arg(project.target->displayName, m_document.modelVariant()->name);
    const QString date = QLocale().toString(QDate::currentDate(), QLocale::ShortFormat);
    int pageNumber = 1;
    QFont headerFont(QStringLiteral("DejaVu Sans"));
    headerFont.setPixelSize(13); // in the drawing's units, like the ladder's own text
    QFont bold = headerFont;
    bold.setBold(true);
    auto drawHeader = [&] {
        // Project on the left, PLC in the middle, date and page on the right, a rule below.
        const QRectF line(0, 0, m.width(), 24);
        p.setPen(Qt::black);
        p.setFont(bold);
        p.drawText(line, Qt::AlignLeft | Qt::AlignVCenter, projectName);
        p.setFont(headerFont);
        p.drawText(line, Qt::AlignHCenter | Qt::AlignVCenter, target);
        p.drawText(line, Qt::AlignRight | Qt::AlignVCenter,
                   tr("%1    page %2 of %3").arg(date).arg(pageNumber).arg(pages));
        p.setPen(QPen(Qt::darkGray, 1));
        p.drawLine(QPointF(0, 28), QPointF(m.width(), 28));
    };
    drawHeader();
    paintProgram(p, m_document, m, m_namesFirst, pageHeight, kTop, [&] {
        printer->newPage();
        ++pageNumber;
        drawHeader();
    });
    return p.end();
}

QString ProgramExport::listingBlockers(const std::vector<model::Diagnostic> &typedErrors) const {
    // A listing that leaves out what cannot be listed would be a shorter program than the
    // user made, without a word: refuse, and say what stands in the way.
    QStringList reasons;
    for (const model::Diagnostic &d : typedErrors)
        if (d.severity == model::Severity::Error)
            reasons << tr("Instruction list, line %1: %2").arg(d.location.line).arg(d.message);
    std::set<int> named; // rungs with a reason already
    for (const model::Diagnostic &d : m_document.listing().problems)
        if (d.severity == model::Severity::Error) {
            reasons << tr("Rung %1: %2").arg(d.location.rung + 1).arg(d.message);
            named.insert(d.location.rung);
        }
    // A contact on no path to an output is left out of the list (LD002): a warning while
    // drawing, a loss in a file that is the program.
    for (const model::Diagnostic &d : m_document.diagnostics())
        if (d.code == QLatin1String("LD002")) {
            reasons << tr("Rung %1: %2").arg(d.location.rung + 1).arg(d.message);
            named.insert(d.location.rung);
        }
    // Every other rung the list pane shows as a placeholder line (one with nothing to list).
    for (const editor::Document::Unlisted &u : m_document.unlistedRungs())
        if (!named.count(u.rung))
            reasons << tr("Rung %1 is not in the list: %2").arg(u.rung + 1).arg(u.reason);
    return reasons.isEmpty() ? QString()
                             : tr("Nothing was written: the instruction list would not hold the "
                                  "whole program.\n%1")
                                   .arg(reasons.join(u'\n'));
}

bool ProgramExport::listing(const QString &path, QString *error,
                            const std::vector<model::Diagnostic> &typedErrors) const {
    if (const QString blockers = listingBlockers(typedErrors); !blockers.isEmpty()) {
        if (error)
            *error = blockers;
        return false;
    }
    QSaveFile file(path);
    // The listing itself, never the text of the list pane: that one has placeholder lines.
    const QByteArray bytes = model::printListing(m_document.listing().list).text.toUtf8();
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit()) {
        if (error)
            *error = tr("%1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

} // namespace rung::app
