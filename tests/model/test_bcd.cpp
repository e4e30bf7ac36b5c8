// The one BCD rule (model/image/bcd.h) that the simulator, the Host Link driver and
// responder, the watch table and the overlay share.

#include "model/image/bcd.h"

#include <gtest/gtest.h>

using namespace rung;

// W353's example: MOV(21) #0012 DM 0000 stores 0012h, which a timer reads as 12.
static_assert(model::toBcd(12) == 0x0012);
static_assert(model::fromBcd(0x0012) == 12);

TEST(Bcd, ADigitANibbleBothWays) {
    EXPECT_EQ(model::toBcd(0), 0);
    EXPECT_EQ(model::toBcd(1234), 0x1234);
    EXPECT_EQ(model::toBcd(9999), 0x9999);
    EXPECT_EQ(model::toBcd(12345678), 0x12345678);
    EXPECT_EQ(model::fromBcd(0x0150), 150);
    EXPECT_EQ(model::fromBcd(0x99999999), 99999999);
    for (std::int64_t n = 0; n <= 9999; ++n)
        ASSERT_EQ(model::fromBcd(model::toBcd(n)), n);
}

TEST(Bcd, AWordThatIsNotBcdHasNoNumber) {
    EXPECT_EQ(model::fromBcd(0x12A4), std::nullopt);
    EXPECT_EQ(model::fromBcd(0x000F), std::nullopt);
    EXPECT_EQ(model::fromBcd(0xF000), std::nullopt);
    EXPECT_EQ(model::fromBcd(-1), std::nullopt);
}
