#pragma once

// A virtual PLC in the test's own process: a program file loaded as `serve` loads it, served
// by VirtualPlc over a new pseudo-terminal or TCP loopback.

#include "app/cli/cli_load_program.h"
#include "app/virtual_plc/virtual_plc.h"
#include "comms/slave/device_image.h"
#include "comms/transport/pty_transport.h"
#include "model/image/snapshot.h"
#include "tests/eventually.h"

#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <memory>
#include <thread>

namespace rung::test {

using waits::eventually;
using waits::kPatienceMs;

// Two programs for a virtual PLC whose outputs follow what a master writes.
// PL110: Q1 follows I1, Q2 follows M1, V1 follows V0.
inline constexpr const char *kFollowerPl110 =
    "; target: pl110\nLD I1\nOUT Q1\nLD M1\nOUT Q2\nLD SM0.0\nMOV V0 V1\nEND\n";
// Vigor: Y0 follows M0; D1 = D0 + 1.
inline constexpr const char *kFollowerVigor =
    "; target: vigor\nLD M0\nOUT Y0\nLD M9000\nADD D0 K1 D1\nEND\n";

struct VirtualPlcUnderTest {
    QTemporaryDir dir;
    std::unique_ptr<app::VirtualPlc> plc;
    QString path; // the pty a master opens, or empty over TCP
    quint16 port = 0;

    // `listing` is the program; over TCP when tcp, else over a pty.
    VirtualPlcUnderTest(const char *listing, comms::slave::SlaveOptions options, bool tcp,
                        const char *suffix = "il") {
        const QString file = dir.filePath(QStringLiteral("plc.") + QLatin1String(suffix));
        QFile f(file);
        EXPECT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(listing);
        f.close();
        QString errText;
        QTextStream err(&errText);
        app::LoadedProgram loaded;
        EXPECT_EQ(app::loadProgram({file, {}, {}}, &loaded, err), 0) << errText.toStdString();
        if (!loaded.program)
            return;
        app::VirtualPlc::Options o;
        o.slave = std::move(options);
        o.periodMs = 10;
        plc = std::make_unique<app::VirtualPlc>(loaded.program, o);
        QString error;
        if (tcp) {
            EXPECT_TRUE(plc->listen(QHostAddress::LocalHost, 0, &error)) << error.toStdString();
            port = plc->port();
            return;
        }
        auto pty = comms::PtyTransport::createPair(&error);
        EXPECT_TRUE(pty) << error.toStdString();
        if (!pty)
            return;
        path = pty->peerPath();
        EXPECT_TRUE(plc->serve(std::move(pty), &error)) << error.toStdString();
    }
    bool ready() const { return plc && (!path.isEmpty() || port != 0); }
    // A PLC answers from its I/O image, which holds the program's results from the end of
    // the first scan on; a test that reads them first waits for that scan (on a loaded
    // machine the session's thread may not have run it yet when a master asks).
    bool scanned(int ms = 5000) const;
};

inline bool VirtualPlcUnderTest::scanned(int ms) const {
    return plc && eventually(
                      [this] {
                          const auto snapshot = plc->image()->snapshot();
                          return snapshot && snapshot->statistics.scans > 0;
                      },
                      ms);
}

} // namespace rung::test
