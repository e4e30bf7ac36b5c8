#include "target_data.h"

namespace rung::model::detail {

Target makeCpm1Target()
{
    Target t;
    t.family = Family::Cpm1;
    t.id = QStringLiteral("cpm1");
    t.displayName = QStringLiteral("CPM1");
    t.models.push_back(ModelVariant{QStringLiteral("CPM1"), {}, 0});
    return t;
}

} // namespace rung::model::detail
