#include "online_edit.h"

#include <algorithm>
#include <iterator>

namespace rung::simulator {

std::vector<model::Address> timersAndCounters(const Program &program) {
    const MemoryLayout &layout = *program.layout;
    std::vector<model::Address> elements;
    for (const Step &s : program.steps) {
        switch (s.code) {
        case Code::Timer:
        case Code::Counter:
        case Code::UpDownCounter:
        case Code::PlTimer:
        case Code::PlCounter:
            break;
        default:
            continue;
        }
        // The element state slot names the element: its area's stateBase + index.
        for (int a = 0; a < layout.areaCount(); ++a) {
            const AreaLayout &area = layout.area(a);
            if (area.stateBase >= 0 && s.slot >= area.stateBase &&
                s.slot < area.stateBase + area.count) {
                elements.push_back({a, area.first + (s.slot - area.stateBase), -1});
                break;
            }
        }
    }
    std::sort(elements.begin(), elements.end());
    elements.erase(std::unique(elements.begin(), elements.end()), elements.end());
    return elements;
}

EditImpact assessEdit(const Program &running, const Program &edited) {
    EditImpact impact;
    const MemoryLayout &a = *running.layout;
    const MemoryLayout &b = *edited.layout;
    impact.layoutDiffers = &a.target() != &b.target() || a.wordCount() != b.wordCount() ||
                           a.elementStateCount() != b.elementStateCount();
    if (impact.layoutDiffers)
        return impact;
    const std::vector<model::Address> before = timersAndCounters(running);
    const std::vector<model::Address> after = timersAndCounters(edited);
    std::set_difference(before.begin(), before.end(), after.begin(), after.end(),
                        std::back_inserter(impact.elementsGone));
    std::set_difference(after.begin(), after.end(), before.begin(), before.end(),
                        std::back_inserter(impact.elementsNew));
    return impact;
}

} // namespace rung::simulator
