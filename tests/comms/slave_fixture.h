#pragma once

// A device image for the slave's tests, with its devices named as a listing writes them.

#include "comms/slave/memory_image.h"
#include "model/target/address.h"

#include <gtest/gtest.h>

#include <memory>

namespace rung::comms::test {

inline model::Address device(const model::Target &t, const char *text) {
    const auto parsed = model::parseAddress(t, QString::fromLatin1(text));
    EXPECT_TRUE(std::holds_alternative<model::Address>(parsed)) << text;
    return std::holds_alternative<model::Address>(parsed) ? std::get<model::Address>(parsed)
                                                          : model::Address{};
}

struct Image {
    const model::Target &target;
    std::shared_ptr<slave::MemoryImage> image;

    explicit Image(const model::Target &t, slave::OperatingMode mode = slave::OperatingMode::Run)
        : target(t)
        , image(std::make_shared<slave::MemoryImage>(t, mode)) {}

    void set(const char *dev, qint64 value) {
        const model::Address a = device(target, dev);
        const bool isBit = image->snapshot()->layout->bit(a).valid() &&
                           (a.bit >= 0 || image->snapshot()->layout->word(a) < 0);
        const auto kind =
            isBit ? model::DeviceCommand::Kind::WriteBit : model::DeviceCommand::Kind::WriteWord;
        const auto done = image->apply({{kind, a, value}}, QDeadlineTimer(1000));
        EXPECT_TRUE(done.done()) << dev;
    }
    bool bit(const char *dev) const { return image->snapshot()->bit(device(target, dev)); }
    std::int32_t value(const char *dev) const {
        return image->snapshot()->value(device(target, dev));
    }
};

} // namespace rung::comms::test
