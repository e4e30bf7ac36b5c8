#pragma once

// A device image for the slave's tests, with its devices named as a listing writes them.

#include "comms/protocol/protocol_error.h"
#include "comms/slave/memory_image.h"
#include "comms/transport/transport.h"
#include "model/target/address.h"

#include <QDeadlineTimer>

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

// Writes a request as a master does and feeds what comes back to the decoder until it has a
// whole reply or `ms` pass.
template <typename Decoder>
FrameStatus exchange(Transport &t, const QByteArray &request, Decoder &d, int ms = 2000) {
    QString error;
    EXPECT_TRUE(t.write(request, QDeadlineTimer(1000), &error)) << error.toStdString();
    const QDeadlineTimer deadline(ms);
    while (d.status() == FrameStatus::NeedMore) {
        const ReadResult r = t.read(deadline);
        if (r.status != ReadResult::Status::Data)
            break;
        d.feed(r.bytes);
    }
    return d.status();
}

} // namespace rung::comms::test
