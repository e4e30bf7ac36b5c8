// Find a device in the ladder: the next (or previous) contact, coil or box that uses it, in
// reading order (rung by rung, row by row, the output after the row's contacts), wrapping
// round at the end. Also the notice above the drawing (the list has errors, the ladder shows
// the last valid program).

#include "ladder_view.h"

#include <QLabel>

#include <algorithm>
#include <tuple>

namespace rung::editor {

namespace {

bool uses(const std::vector<model::Operand> &operands, const model::Address &device) {
    for (const model::Operand &o : operands)
        if (o.kind == model::Operand::Kind::Device && o.address == device)
            return true;
    return false;
}

} // namespace

bool LadderView::findDevice(const model::Address &device, bool backwards) {
    const auto &rungs = m_document->ladder().rungs;
    const int output = metrics().gridColumns;
    // Every place that uses the device, in reading order.
    std::vector<CellCursor> places;
    for (int r = 0; r < static_cast<int>(rungs.size()); ++r) {
        const model::Rung &rung = rungs[static_cast<std::size_t>(r)];
        for (int row = 0; row < rung.rows; ++row) {
            for (int c = 0; c < rung.columns; ++c) {
                const model::Cell &cell = rung.cell(row, c);
                if (cell.kind == model::CellKind::Contact && uses(cell.contact.operands, device))
                    places.push_back({r, row, c});
            }
            const auto &out = rung.outputs[static_cast<std::size_t>(row)];
            if (out && uses(out->operands, device))
                places.push_back({r, row, output});
        }
    }
    if (places.empty()) {
        emit message(tr("%1 is not used in the program")
                         .arg(model::formatAddress(m_document->target(), device)));
        return false;
    }
    auto before = [](const CellCursor &a, const CellCursor &b) {
        return std::tie(a.rung, a.row, a.column) < std::tie(b.rung, b.row, b.column);
    };
    CellCursor next;
    if (backwards) {
        auto it = std::lower_bound(places.begin(), places.end(), m_cursor, before);
        next = it == places.begin() ? places.back() : *(it - 1);
    } else {
        auto it = std::upper_bound(places.begin(), places.end(), m_cursor, before);
        next = it == places.end() ? places.front() : *it;
    }
    clearSelection();
    setCursor(next);
    return true;
}

void LadderView::setNotice(const QString &text) {
    if (!m_notice) {
        m_notice = new QLabel(this);
        m_notice->setObjectName(QStringLiteral("ladderNotice"));
        m_notice->setWordWrap(true);
        m_notice->setAutoFillBackground(true);
        m_notice->setMargin(6);
        QPalette pal = m_notice->palette();
        pal.setColor(QPalette::Window, QColor(0xfd, 0xec, 0xc8));
        pal.setColor(QPalette::WindowText, QColor(0x5c, 0x3b, 0x00));
        m_notice->setPalette(pal);
    }
    m_notice->setText(text);
    m_notice->setVisible(!text.isEmpty());
    if (text.isEmpty())
        setViewportMargins(0, 0, 0, 0);
    placeNotice();
}

QString LadderView::notice() const {
    return m_notice && !m_notice->isHidden() ? m_notice->text() : QString();
}

void LadderView::placeNotice() {
    if (!m_notice || m_notice->isHidden())
        return;
    // A band above the drawing, which moves down to make room: nothing hides under it.
    const int height = m_notice->heightForWidth(viewport()->width());
    if (viewportMargins().top() != height)
        setViewportMargins(0, height, 0, 0);
    const QRect area = viewport()->geometry();
    m_notice->setGeometry(area.left(), area.top() - height, area.width(), height);
    m_notice->raise();
}

} // namespace rung::editor
