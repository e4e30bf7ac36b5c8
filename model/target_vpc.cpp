#include "target_data.h"

namespace rung::model::detail {

Target makeVpcTarget()
{
    Target t;
    t.family = Family::Vpc;
    t.id = QStringLiteral("vpc");
    t.displayName = QStringLiteral("VPC");
    t.models.push_back(ModelVariant{QStringLiteral("VPC"), {}, 0});
    return t;
}

} // namespace rung::model::detail
