#include "model/checks/checks_list_detail.h"

#include <algorithm>

namespace rung::model::detail {

// What keeps the listing from being drawn, as the conversion finds it, by the documented
// codes: an output with no condition (OC001), blocks left open or missing (BL001). MRD/MPP
// without MPS and MPS left open are ST002/ST003, which blocksAndStack() has reported.
void ListChecker::structure(const std::vector<Diagnostic> &drawing) {
    const auto reported = [this](const char *code, const Location &at) {
        return std::any_of(m_found.begin(), m_found.end(), [&](const Finding &f) {
            return f.diagnostic.code == QLatin1String(code) &&
                   (f.diagnostic.location.line == at.line ||
                    QLatin1String(code) == QLatin1String("ST003"));
        });
    };
    for (const Diagnostic &d : drawing) {
        const bool stack = d.code == QLatin1String("CV004");
        const bool open = d.code == QLatin1String("CV008");
        if ((stack && reported("ST002", d.location)) || (open && reported("ST003", d.location)))
            continue;
        Finding f;
        f.diagnostic = d;
        f.diagnostic.code = d.code == QLatin1String("CV006") ? QStringLiteral("OC001")
                            : stack                          ? QStringLiteral("ST002")
                            : open                           ? QStringLiteral("ST003")
                                                             : QStringLiteral("BL001");
        for (int i = 0; i < size(); ++i)
            if (at(i).line == d.location.line && at(i).column == d.location.column)
                f.instruction = i;
        m_found.push_back(std::move(f));
    }
}

} // namespace rung::model::detail
