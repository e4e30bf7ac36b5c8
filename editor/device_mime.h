#pragma once

// Devices dragged between the views: from the ladder, the cross reference, the watch table
// to the watch table or the timing chart. One device per line, as the target writes it; the
// same text as plain text, so a drop into any text field types the devices.

#include <QMimeData>
#include <QRegularExpression>
#include <QStringList>

namespace rung::editor {

inline const QString &deviceMimeType() {
    static const QString type = QStringLiteral("application/x-rungstudio-devices");
    return type;
}

inline QMimeData *deviceMimeData(const QStringList &devices) {
    auto *data = new QMimeData;
    data->setData(deviceMimeType(), devices.join(QLatin1Char('\n')).toUtf8());
    data->setText(devices.join(QStringLiteral(", ")));
    return data;
}

// The devices (or ranges, "D0..D15") a drop carries: ours, else plain text split at commas,
// semicolons and line ends.
inline QStringList devicesFromMime(const QMimeData *data) {
    QString text;
    if (data->hasFormat(deviceMimeType()))
        text = QString::fromUtf8(data->data(deviceMimeType()));
    else if (data->hasText())
        text = data->text();
    QStringList out;
    for (const QString &part : text.split(QRegularExpression(QStringLiteral("[,;\\n]"))))
        if (!part.trimmed().isEmpty())
            out << part.trimmed();
    return out;
}

} // namespace rung::editor
