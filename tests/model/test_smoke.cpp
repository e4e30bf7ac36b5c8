#include "model/target/target.h"

#include <gtest/gtest.h>

using namespace rung::model;

TEST(Targets, EveryFamilyHasAnIdAndAModel) {
    for (Family f : Target::families()) {
        const Target &t = Target::get(f);
        EXPECT_FALSE(t.id.isEmpty());
        EXPECT_EQ(Target::byId(t.id), &t);
        EXPECT_FALSE(t.models.empty());
    }
}
