#pragma once

// The builders of the four families' tables (target_vpc.cpp, target_vigor.cpp,
// target_cpm1.cpp, target_pl110.cpp). Only target.cpp calls them.

#include "target.h"

namespace rung::model::detail {

Target makeVpcTarget();
Target makeVigorTarget();
Target makeCpm1Target();
Target makePl110Target();

} // namespace rung::model::detail
