#include "comms/slave/memory_image.h"

#include "model/target/address.h"

#include <QCoreApplication>

namespace rung::comms::slave {

namespace {

using Kind = model::DeviceCommand::Kind;

// Applies one command to the words; false when the address names nothing of its kind here.
bool applyOne(model::Snapshot &s, const model::DeviceCommand &c) {
    const model::MemoryLayout &layout = *s.layout;
    auto at = [&s](int index) -> std::uint32_t & {
        return reinterpret_cast<std::uint32_t &>(s.words[static_cast<std::size_t>(index)]);
    };
    auto keepForced = [&s](int index, std::uint32_t value) {
        const auto i = static_cast<std::size_t>(index);
        return (value & ~s.forceMask[i]) | (s.forceValue[i] & s.forceMask[i]);
    };
    switch (c.kind) {
    case Kind::WriteBit:
    case Kind::Force:
    case Kind::Release: {
        const model::BitRef r = layout.bit(c.address);
        if (!r.valid())
            return false;
        const auto i = static_cast<std::size_t>(r.word);
        if (c.kind == Kind::Release) {
            s.forceMask[i] &= ~r.mask;
            return true;
        }
        if (c.kind == Kind::Force) {
            s.forceMask[i] |= r.mask;
            s.forceValue[i] = c.value ? (s.forceValue[i] | r.mask) : (s.forceValue[i] & ~r.mask);
        }
        const std::uint32_t w = at(r.word);
        at(r.word) = keepForced(r.word, c.value ? (w | r.mask) : (w & ~r.mask));
        return true;
    }
    case Kind::WriteWord:
    case Kind::WriteSetValue: {
        const int w =
            c.kind == Kind::WriteWord ? layout.word(c.address) : layout.setValueWord(c.address);
        if (w < 0)
            return false;
        const auto v =
            static_cast<std::uint32_t>(model::wrapToWidth(c.value, layout.wordBits(c.address)));
        at(w) = keepForced(w, v);
        return true;
    }
    case Kind::ReleaseAll:
        std::fill(s.forceMask.begin(), s.forceMask.end(), 0u);
        return true;
    }
    return false;
}

} // namespace

MemoryImage::MemoryImage(const model::Target &target, OperatingMode mode)
    : m_mode(mode) {
    auto s = std::make_shared<model::Snapshot>();
    s->layout = std::make_shared<const model::MemoryLayout>(target);
    const auto words = static_cast<std::size_t>(s->layout->wordCount());
    s->words.assign(words, 0);
    s->forceMask.assign(words, 0);
    s->forceValue.assign(words, 0);
    s->coils.assign(static_cast<std::size_t>(s->layout->elementStateCount()), false); // no program
    m_snapshot = std::move(s);
}

std::shared_ptr<const model::Snapshot> MemoryImage::snapshot() const {
    std::lock_guard lock(m_mutex);
    return m_snapshot;
}

ImageChange MemoryImage::apply(const std::vector<model::DeviceCommand> &commands, QDeadlineTimer) {
    std::lock_guard lock(m_mutex);
    auto next = std::make_shared<model::Snapshot>(*m_snapshot);
    for (const model::DeviceCommand &c : commands)
        if (!applyOne(*next, c))
            return {ImageChange::Status::Refused,
                    QCoreApplication::translate("rung::comms::Protocol",
                                                "%1 cannot be written in this PLC's memory")
                        .arg(model::formatAddress(next->layout->target(), c.address))};
    m_snapshot = std::move(next); // all or nothing
    ++m_changes;
    return {};
}

OperatingMode MemoryImage::mode() const {
    std::lock_guard lock(m_mutex);
    return m_mode;
}

ImageChange MemoryImage::setMode(OperatingMode mode, QDeadlineTimer) {
    std::lock_guard lock(m_mutex);
    m_mode = mode;
    return {};
}

int MemoryImage::changes() const {
    std::lock_guard lock(m_mutex);
    return m_changes;
}

} // namespace rung::comms::slave
