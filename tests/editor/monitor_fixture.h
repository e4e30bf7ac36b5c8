#pragma once

// A document and a real simulation of its program for the monitoring views' tests (the I/O
// panel, the watch table, the timing chart): the views meet the same SimulatorSession the
// IDE gives them, driven scan by scan from the test.

#include "editor/document.h"
#include "model/target/address.h"
#include "simulator/compiler.h"
#include "simulator/session.h"
#include "tests/eventually.h"

#include <QCoreApplication>
#include <QElapsedTimer>

#include <gtest/gtest.h>

#include <memory>

namespace rung::test {

using waits::eventually;
using waits::kPatienceMs;

struct MonitorFixture {
    editor::Document document;
    std::unique_ptr<simulator::SimulatorSession> session;

    void start(const model::Target &target, const QString &modelName, const char *listing) {
        document.reset(target, modelName);
        std::vector<model::Diagnostic> errors;
        ASSERT_TRUE(document.setListing(QString::fromLatin1(listing), &errors));
        startSession();
    }
    void startSession() {
        model::CheckOptions options;
        options.model = document.modelVariant();
        const auto compiled = simulator::prepareProgram(document.listing().list, options);
        ASSERT_TRUE(compiled.ok());
        session = std::make_unique<simulator::SimulatorSession>(compiled.program);
        ASSERT_TRUE(eventually([&] { return session->snapshot() != nullptr; }));
    }
    model::Address at(const char *device) const {
        const auto a = model::parseAddress(document.target(), QString::fromLatin1(device));
        EXPECT_TRUE(std::holds_alternative<model::Address>(a)) << device;
        return std::holds_alternative<model::Address>(a) ? std::get<model::Address>(a)
                                                         : model::Address{};
    }
    quint64 scans() const { return session->snapshot()->statistics.scans; }
    // One scan, and its snapshot delivered to the views (snapshotChanged).
    void scan() {
        const quint64 before = scans();
        session->singleScan();
        ASSERT_TRUE(eventually([&] {
            return scans() == before + 1 &&
                   session->runState() == model::MonitorSource::RunState::Paused;
        }));
        settle();
    }
    // Lets the commands posted so far be applied and the views repaint from the snapshot.
    void settle() {
        QElapsedTimer t;
        t.start();
        while (t.elapsed() < 80)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
    }
};

} // namespace rung::test
