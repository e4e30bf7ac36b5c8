#include "target_data.h"

namespace rung::model::detail {

Target makePl110Target() {
    Target t;
    t.family = Family::Pl110;
    t.id = QStringLiteral("pl110");
    t.displayName = QStringLiteral("PL110");
    t.models.push_back(ModelVariant{QStringLiteral("PL110"), {}, 0});
    return t;
}

} // namespace rung::model::detail
