#include "model/image/memory_layout.h"

#include <algorithm>

namespace rung::model {

MemoryLayout::MemoryLayout(const Target &target)
    : m_target(&target) {
    m_areas.reserve(target.areas.size());
    for (const Area &a : target.areas) {
        AreaLayout l;
        l.kind = a.kind;
        l.first = a.first;
        l.count = a.last >= a.first ? a.last - a.first + 1 : 0;
        l.wordBits = a.wordBits;
        l.retentive = a.retentive;
        switch (a.kind) {
        case AreaKind::Bit:
            l.bitBase = m_words;
            m_words += (l.count + 15) / 16;
            break;
        case AreaKind::Word:
        case AreaKind::Channel:
            if (a.presetsOf || a.doubleWordsOf)
                break; // the words of another area, placed below
            l.wordBase = m_words;
            m_words += l.count;
            break;
        case AreaKind::Timer:
        case AreaKind::Counter:
            l.bitBase = m_words;
            m_words += (l.count + 15) / 16;
            l.wordBase = m_words;
            m_words += l.count;
            l.setBase = m_words;
            m_words += l.count;
            l.stateBase = m_states;
            m_states += l.count;
            break;
        }
        m_areas.push_back(l);
    }
    // A preset area is a second name of the set values (PL110 PT/PV), element for element.
    for (std::size_t k = 0; k < target.areas.size(); ++k) {
        const Area &a = target.areas[k];
        if (!a.presetsOf)
            continue;
        for (std::size_t j = 0; j < target.areas.size(); ++j) {
            AreaLayout &of = m_areas[j];
            if (target.areas[j].key != QLatin1String(a.presetsOf) || of.setBase < 0)
                continue;
            AreaLayout &l = m_areas[k];
            const int skip = a.first - of.first;
            if (skip < 0)
                continue;
            l.count = std::clamp(of.count - skip, 0, l.count);
            l.wordBase = of.setBase + skip;
            of.presetsAddressable = true;
        }
    }
    // A double-word area is a second name of two words of a word area (PL110 VD0 = V0:V1).
    for (std::size_t k = 0; k < target.areas.size(); ++k) {
        const Area &a = target.areas[k];
        if (!a.doubleWordsOf)
            continue;
        for (std::size_t j = 0; j < target.areas.size(); ++j) {
            const AreaLayout &of = m_areas[j];
            if (target.areas[j].key != QLatin1String(a.doubleWordsOf) || of.wordBase < 0)
                continue;
            AreaLayout &l = m_areas[k];
            const int skip = a.first - of.first;
            if (skip < 0)
                continue;
            l.count = std::clamp(of.count - 1 - skip, 0, l.count);
            l.wordBase = of.wordBase + skip;
            l.doubleWords = true;
            l.wordBits = 32;
        }
    }
}

std::int32_t MemoryLayout::value(const std::vector<std::int32_t> &words,
                                 const Address &address) const {
    const int w = word(address);
    auto at = [&words](int i) {
        return i >= 0 && static_cast<std::size_t>(i) < words.size()
                   ? words[static_cast<std::size_t>(i)]
                   : 0;
    };
    if (w >= 0 && area(address.area).doubleWords)
        return static_cast<std::int32_t>((static_cast<std::uint32_t>(at(w)) << 16) |
                                         (static_cast<std::uint32_t>(at(w + 1)) & 0xFFFFu));
    return at(w);
}

bool MemoryLayout::inRange(const Address &address) const {
    if (address.area < 0 || address.area >= areaCount())
        return false;
    const AreaLayout &l = area(address.area);
    return address.index >= l.first && address.index - l.first < l.count;
}

BitRef MemoryLayout::bit(const Address &address) const {
    if (!inRange(address))
        return {};
    const AreaLayout &l = area(address.area);
    const int i = address.index - l.first;
    switch (l.kind) {
    case AreaKind::Bit:
    case AreaKind::Timer:
    case AreaKind::Counter:
        if (l.kind == AreaKind::Bit || address.bit < 0)
            return {l.bitBase + i / 16, 1u << (i % 16)};
        [[fallthrough]];
    case AreaKind::Word:
    case AreaKind::Channel:
        if (address.bit < 0 || address.bit >= l.wordBits || address.bit >= 32)
            return {};
        return {l.wordBase + i, 1u << address.bit};
    }
    return {};
}

int MemoryLayout::word(const Address &address) const {
    if (!inRange(address))
        return -1;
    const AreaLayout &l = area(address.area);
    if (l.kind == AreaKind::Bit) {
        // A bit area read as a word: the 16 bits starting at a multiple of 16 (PL110 I/Q words).
        const int i = address.index - l.first;
        return i % 16 == 0 ? l.bitBase + i / 16 : -1;
    }
    return l.wordBase + (address.index - l.first);
}

int MemoryLayout::setValueWord(const Address &address) const {
    if (!inRange(address) || area(address.area).setBase < 0)
        return -1;
    const AreaLayout &l = area(address.area);
    return l.setBase + (address.index - l.first);
}

int MemoryLayout::elementState(const Address &address) const {
    if (!inRange(address) || area(address.area).stateBase < 0)
        return -1;
    const AreaLayout &l = area(address.area);
    return l.stateBase + (address.index - l.first);
}

bool MemoryLayout::presetAddressable(const Address &address) const {
    return inRange(address) && area(address.area).presetsAddressable;
}

int MemoryLayout::wordBits(const Address &address) const {
    if (address.area < 0 || address.area >= areaCount())
        return 16;
    const AreaLayout &l = area(address.area);
    return l.kind == AreaKind::Bit ? 16 : l.wordBits;
}

} // namespace rung::model
