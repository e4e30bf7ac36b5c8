#pragma once

// A Driver over a FakeTransport, for the driver and planner tests.

#include "comms/driver/driver.h"
#include "model/target/target.h"
#include "tests/comms/fake_transport.h"

#include <gtest/gtest.h>

namespace rung::comms::test {

struct FakeDriver {
    FakeTransport *port = nullptr; // owned by the driver
    std::unique_ptr<Driver> driver;

    FakeDriver(model::Family family, ProtocolKind protocol, int station,
               LinkSettings settings = {40, 2, 5}) {
        auto transport = std::make_unique<FakeTransport>(QStringLiteral("/dev/ttyFAKE0"));
        port = transport.get();
        QString error;
        driver = Driver::create(model::Target::get(family), protocol, std::move(transport), station,
                                settings, &error);
        EXPECT_TRUE(driver) << error.toStdString();
        if (driver) {
            EXPECT_TRUE(driver->link().open(&error)) << error.toStdString();
        }
    }

    model::Address device(const char *name) const {
        const auto parsed = driver->parseDevice(QString::fromLatin1(name));
        EXPECT_TRUE(std::holds_alternative<model::Address>(parsed)) << name;
        return std::holds_alternative<model::Address>(parsed) ? std::get<model::Address>(parsed)
                                                              : model::Address{};
    }
    std::vector<model::Address> devices(std::initializer_list<const char *> names) const {
        std::vector<model::Address> out;
        for (const char *n : names)
            out.push_back(device(n));
        return out;
    }
    // Reads the devices; their values, or the error's message as a failure.
    std::vector<qint64> read(std::initializer_list<const char *> names, DriverError *error) {
        std::vector<qint64> values;
        *error = driver->read(devices(names), &values);
        return values;
    }
    DriverError execute(model::DeviceCommand::Kind kind, const char *name, qint64 value,
                        QString *notice = nullptr) {
        return driver->execute({kind, device(name), value}, notice);
    }
};

} // namespace rung::comms::test
