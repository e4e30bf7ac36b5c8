#include "about_dialog.h"

#include "dialogs.h"
#include "installed_files.h"

#include "model/target/target_lists.h"

#include <Qsci/qsciglobal.h>
#include <libserialport.h>

#include <QApplication>
#include <QDialogButtonBox>
#include <QDir>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPushButton>
#include <QSvgRenderer>
#include <QUrl>
#include <QVBoxLayout>

namespace rung::app {

QIcon applicationIcon() {
    // Each size rendered from its own drawing: QIcon's SVG engine keeps one file per mode, so
    // the small drawings would be lost if the SVGs were added as files.
    QIcon icon;
    for (int size : {16, 22, 24, 32, 48, 64, 128, 256}) {
        const QString file = size < 32
                                 ? QStringLiteral(":/icons/rungstudio-%1.svg").arg(size)
                                 : QStringLiteral(":/icons/io.github.rungstudio.RungStudio.svg");
        QSvgRenderer svg(file);
        QImage image(size, size, QImage::Format_ARGB32_Premultiplied);
        image.fill(Qt::transparent);
        QPainter painter(&image);
        svg.render(&painter);
        painter.end();
        icon.addPixmap(QPixmap::fromImage(image));
    }
    return icon;
}

QUrl AboutDialog::userGuideUrl() {
    const QString guide = userGuidePath();
    return guide.isEmpty() ? QUrl() : QUrl::fromLocalFile(guide);
}

AboutDialog::AboutDialog(QWidget *parent)
    : QDialog(parent) {
    setObjectName(QStringLiteral("aboutDialog"));
    setWindowTitle(tr("About Rung Studio"));

    auto *logo = new QLabel;
    logo->setPixmap(applicationIcon().pixmap(QSize(64, 64)));
    logo->setAlignment(Qt::AlignTop);

    const QString version = QStringLiteral(RUNG_VERSION);
    auto *title = new QLabel(QStringLiteral("<b style='font-size:large'>Rung Studio %1</b>")
                                 .arg(version.toHtmlEscaped()));
    title->setObjectName(QStringLiteral("aboutTitle"));
    auto *what = new QLabel(tr("Ladder and instruction-list editor for %1.")
                                .arg(model::targetDisplayNames().join(QStringLiteral(", "))));
    what->setWordWrap(true);

    auto *guide = new QLabel;
    guide->setObjectName(QStringLiteral("aboutGuide"));
    const QUrl url = userGuideUrl();
    if (url.isValid()) {
        guide->setText(QStringLiteral("<a href=\"%1\">%2</a>")
                           .arg(url.toString(QUrl::FullyEncoded).toHtmlEscaped(),
                                tr("User guide").toHtmlEscaped()));
        guide->setToolTip(QDir::toNativeSeparators(url.toLocalFile()));
        guide->setOpenExternalLinks(true);
        guide->setTextInteractionFlags(Qt::TextBrowserInteraction);
    } else {
        guide->setText(tr("The user guide is not installed beside the program."));
        guide->setWordWrap(true);
    }

    // The parts the program is built from, with the versions it runs with: Qt's and
    // libserialport's from the libraries loaded, QScintilla's from the headers it was built
    // against (it has no run-time query).
    const QString row = QStringLiteral("<tr><td>%1</td><td>&nbsp;%2&nbsp;</td><td>%3</td></tr>");
    QString parts = QStringLiteral("<table>");
    parts += row.arg(QStringLiteral("Rung Studio"), version, tr("GNU GPL, version 3 or later"));
    parts +=
        row.arg(QStringLiteral("Qt"), QString::fromLatin1(qVersion()), tr("GNU LGPL, version 3"));
    parts += row.arg(QStringLiteral("QScintilla"), QStringLiteral(QSCINTILLA_VERSION_STR),
                     tr("GNU GPL, version 3"));
    parts += row.arg(QStringLiteral("libserialport"),
                     QString::fromLatin1(sp_get_package_version_string()),
                     tr("GNU LGPL, version 3 or later"));
    parts += QStringLiteral("</table>");
    auto *builtWith = new QLabel(tr("Built with:"));
    auto *table = new QLabel(parts);
    table->setObjectName(QStringLiteral("aboutParts"));
    table->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto *texts = new QVBoxLayout;
    texts->addWidget(title);
    texts->addWidget(what);
    texts->addWidget(guide);
    texts->addSpacing(fontMetrics().height() / 2);
    texts->addWidget(builtWith);
    texts->addWidget(table);
    // Debian's copyright file: every part's licence in full.
    const QString copyright = installedDocument(QStringLiteral("copyright"));
    if (!copyright.isEmpty()) {
        auto *licences = new QLabel(
            QStringLiteral("<a href=\"%1\">%2</a>")
                .arg(QUrl::fromLocalFile(copyright).toString(QUrl::FullyEncoded).toHtmlEscaped(),
                     tr("Copyright and licences").toHtmlEscaped()));
        licences->setObjectName(QStringLiteral("aboutLicences"));
        licences->setToolTip(QDir::toNativeSeparators(copyright));
        licences->setOpenExternalLinks(true);
        licences->setTextInteractionFlags(Qt::TextBrowserInteraction);
        texts->addWidget(licences);
    }

    auto *top = new QHBoxLayout;
    top->addWidget(logo, 0, Qt::AlignTop);
    top->addSpacing(fontMetrics().height());
    top->addLayout(texts, 1);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    QPushButton *aboutQt = buttons->addButton(tr("About &Qt"), QDialogButtonBox::ActionRole);
    connect(aboutQt, &QPushButton::clicked, this, &QApplication::aboutQt);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(buttons);
    fitTitle(this);
}

} // namespace rung::app
