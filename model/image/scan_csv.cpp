#include "model/image/scan_csv.h"

#include <QTextStream>

namespace rung::model {

ScanCsvWriter::ScanCsvWriter(QTextStream &out, const QStringList &devices)
    : m_out(out) {
    m_out << "scan,time_ms";
    for (const QString &d : devices)
        m_out << ',' << d;
    m_out << '\n';
}

void ScanCsvWriter::row(quint64 scan, qint64 timeMs, const QStringList &values) {
    m_out << scan << ',' << timeMs;
    for (const QString &v : values)
        m_out << ',' << v;
    m_out << '\n';
    ++m_rows;
}

} // namespace rung::model
