#pragma once

// The simulation's CSV, one format for `rungstudio-cli simulate` (simulator/trace.h) and the
// timing chart's export (model/image/timing_data.h): a header "scan,time_ms,DEV1,DEV2,...", then
// rows of the devices' values after a scan. `scan` counts the scans run since power-on, the first
// being 1, and `time_ms` is the virtual time when that scan ended (10 ms scans: scan 1 ends
// at 10). These are the numbers the IDE shows for a scan (the statistics, the history, a
// trigger), and what a recorder of any source knows: a scan's end, not its start.

#include <QStringList>

class QTextStream;

namespace rung::model {

class ScanCsvWriter {
public:
    // Writes the header.
    ScanCsvWriter(QTextStream &out, const QStringList &devices);

    // One row: the values in the devices' order (an empty text where one is not known).
    void row(quint64 scan, qint64 timeMs, const QStringList &values);
    int rows() const { return m_rows; }

private:
    QTextStream &m_out;
    int m_rows = 0;
};

} // namespace rung::model
