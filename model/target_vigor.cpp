#include "target_data.h"

namespace rung::model::detail {

Target makeVigorTarget()
{
    Target t;
    t.family = Family::Vigor;
    t.id = QStringLiteral("vigor");
    t.displayName = QStringLiteral("Vigor");
    t.models.push_back(ModelVariant{QStringLiteral("Vigor"), {}, 0});
    return t;
}

} // namespace rung::model::detail
