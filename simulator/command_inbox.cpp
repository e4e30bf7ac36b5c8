#include "simulator/command_inbox.h"

#include "engine.h"
#include "model/target/address.h"
#include "simulator/tr.h"

#include <QCoreApplication>

namespace rung::simulator {

namespace {

QString name(const Engine &engine, const model::Address &address) {
    if (!address.valid())
        return CommandInboxTr::tr("(no device)");
    return model::formatAddress(engine.layout().target(), address);
}

} // namespace

CommandInbox::CommandInbox(Completion completion)
    : m_completion(std::move(completion)) {}

void CommandInbox::post(EngineCommand command) {
    std::lock_guard lock(m_mutex);
    m_queue.push_back(std::move(command));
    m_pending.store(true, std::memory_order_release);
}

CommandInbox::Applied
CommandInbox::apply(Engine &engine, const std::function<void(const EngineCommand &)> &before) {
    {
        std::lock_guard lock(m_mutex);
        m_taken.swap(m_queue);
        m_pending.store(false, std::memory_order_release);
    }
    Applied applied;
    applied.commands = static_cast<int>(m_taken.size());
    for (const EngineCommand &c : m_taken) {
        if (before)
            before(c);
        QString error;
        const bool ok = applyCommand(engine, c, &error);
        applied.reset = applied.reset || std::holds_alternative<Reset>(c.what);
        if (c.id != 0)
            m_results.push_back({c.id, ok, std::move(error)});
    }
    m_taken.clear();
    return applied;
}

void CommandInbox::complete() {
    if (m_completion)
        for (const Result &r : m_results)
            m_completion(r.id, r.ok, r.error);
    m_results.clear();
}

bool applyCommand(Engine &engine, const EngineCommand &command, QString *error) {
    if (std::holds_alternative<PowerCycle>(command.what)) {
        engine.powerCycle();
        return true;
    }
    if (std::holds_alternative<Reset>(command.what)) {
        engine.reset();
        return true;
    }
    if (const auto *edit = std::get_if<ReplaceProgram>(&command.what)) {
        const EditApplied applied = engine.replaceProgram(edit->program, edit->breakpoints);
        if (applied == EditApplied::LayoutDiffers && error)
            *error = CommandInboxTr::tr(
                "the edited program is for another memory layout (another PLC): it "
                "cannot take over the running image");
        return applied != EditApplied::LayoutDiffers;
    }
    using Kind = model::DeviceCommand::Kind;
    const auto &c = std::get<model::DeviceCommand>(command.what);
    bool ok = false;
    switch (c.kind) {
    case Kind::WriteBit:
        ok = engine.setBit(c.address, c.value != 0);
        break;
    case Kind::WriteWord:
        ok = engine.writeWord(c.address, c.value);
        break;
    case Kind::WriteSetValue:
        ok = engine.writeSetValue(c.address, c.value);
        if (!ok && error)
            *error =
                CommandInboxTr::tr("%1 has no set value to write").arg(name(engine, c.address));
        return ok;
    case Kind::Force:
        ok = engine.force(c.address, c.value != 0);
        break;
    case Kind::Release:
        ok = engine.release(c.address);
        break;
    case Kind::ReleaseAll:
        engine.releaseAll();
        return true;
    }
    if (!ok && error)
        *error = c.kind == Kind::WriteWord
                     ? CommandInboxTr::tr("%1 is not a word this PLC can write")
                           .arg(name(engine, c.address))
                     : CommandInboxTr::tr("%1 is not a bit this PLC can write")
                           .arg(name(engine, c.address));
    return ok;
}

} // namespace rung::simulator
