#include "network/shared_link.h"
#include "network/tr.h"

#include "network/station.h"

#include "model/target/address.h"

#include <QCoreApplication>

#include <array>
#include <limits>
#include <optional>
#include <span>
#include <variant>

namespace rung::network {

namespace {

using model::SystemRole;

// A station's words and bits of one share, by image index, as copy() copies them: runs of
// consecutive words of one width, and the bits by image word.
struct Share {
    struct WordRun {
        std::size_t first = 0;
        std::size_t count = 0;
        int width = 16;
    };
    std::vector<WordRun> wordRuns;
    std::vector<std::pair<std::size_t, std::uint32_t>> bitWords; // image word, mask
    // The blocks of the image the runs and bits are in (ImageWrites): what a copy marks
    // written, for the network's history.
    std::vector<std::uint64_t> blocks;

    void addWord(std::int32_t index, int width) {
        if (index < 0)
            return;
        const auto word = static_cast<std::size_t>(index);
        if (!wordRuns.empty() && wordRuns.back().width == width &&
            wordRuns.back().first + wordRuns.back().count == word)
            ++wordRuns.back().count;
        else
            wordRuns.push_back({word, 1, width});
    }
    void addBit(const model::BitRef &b) {
        if (!b.valid())
            return;
        const auto word = static_cast<std::size_t>(b.word);
        if (!bitWords.empty() && bitWords.back().first == word)
            bitWords.back().second |= b.mask;
        else
            bitWords.emplace_back(word, b.mask);
    }
};

Share shareOf(const Station &s, const model::SharedMode &mode, int number) {
    Share share;
    const model::Target &t = s.target();
    const model::MemoryLayout &l = s.engine().layout();
    for (const model::SharedArea &a : mode.areas) {
        const auto parsed = model::parseAddress(
            t, QString::fromLatin1(a.prefix) + QString::number(a.first + a.stride * number));
        const auto *first = std::get_if<model::Address>(&parsed);
        for (int k = 0; first && k < a.count; ++k) {
            const model::Address x = model::offsetAddress(t, *first, k);
            if (!x.valid())
                break;
            if (t.area(x.area).kind == model::AreaKind::Bit)
                share.addBit(l.bit(x));
            else
                share.addWord(l.word(x), l.wordBits(x));
        }
    }
    for (const Share::WordRun &run : share.wordRuns)
        ImageWrites::addBlocks(share.blocks, run.first, run.count);
    for (const auto &[word, mask] : share.bitWords)
        ImageWrites::addBlocks(share.blocks, word, 1);
    return share;
}

// The system devices of a role, `count` of them from the one the table names.
std::vector<model::Address> roleDevices(const model::Target &t, SystemRole role) {
    std::vector<model::Address> out;
    const model::SystemDevice *d = t.systemDevice(role);
    if (!d)
        return out;
    const auto parsed = model::parseAddress(t, d->device);
    if (const auto *a = std::get_if<model::Address>(&parsed))
        for (int k = 0; k < d->count; ++k)
            out.push_back(model::offsetAddress(t, *a, k));
    return out;
}

// A role's devices in a station's image, resolved once: an exchange writes them every network
// scan, and parsing their names each time cost seven times the stations' scans (bench_network).
struct Resolved {
    std::vector<model::BitRef> bits;
    std::vector<int> words;
};

struct Member {
    StationPort *port = nullptr;
    Station *station = nullptr;
    int number = 0;
    Share share;
    mutable std::vector<std::optional<Resolved>> roles; // by SystemRole
};

const Resolved &resolved(const Member &m, SystemRole role) {
    const auto index = static_cast<std::size_t>(role);
    if (index < m.roles.size() && m.roles[index])
        return *m.roles[index];
    if (m.roles.size() <= index)
        m.roles.resize(index + 1);
    Resolved r;
    const model::MemoryLayout &l = m.station->engine().layout();
    for (const model::Address &a : roleDevices(m.station->target(), role)) {
        r.bits.push_back(l.bit(a));
        r.words.push_back(l.word(a));
    }
    m.roles[index] = std::move(r);
    return *m.roles[index];
}

void setBit(const Member &m, SystemRole role, int k, bool on) {
    const Resolved &r = resolved(m, role);
    if (std::size_t(k) < r.bits.size() && r.bits[std::size_t(k)].valid()) {
        m.station->engine().storeImageBit(r.bits[std::size_t(k)], on);
        m.station->written().mark(std::size_t(r.bits[std::size_t(k)].word), 1);
    }
}

void setWord(const Member &m, SystemRole role, int k, std::int32_t value) {
    const Resolved &r = resolved(m, role);
    if (std::size_t(k) < r.words.size() && r.words[std::size_t(k)] >= 0) {
        m.station->engine().storeImageWord(std::size_t(r.words[std::size_t(k)]), value, 16);
        m.station->written().mark(std::size_t(r.words[std::size_t(k)]), 1);
    }
}

void copy(const Member &from, const Member &to) {
    const simulator::Engine &src = from.station->engine();
    simulator::Engine &dst = to.station->engine();
    // The same devices in every station: the same indices, the target being one.
    for (const Share::WordRun &run : from.share.wordRuns)
        dst.copyImageWords(src, run.first, run.count, run.width);
    for (const auto &[word, mask] : from.share.bitWords)
        dst.copyImageBits(src, word, mask);
    to.station->written().mark(from.share.blocks); // for the network's history
}

// CPU Link: station 0 polls slaves 1..n in "instant interrupt way" (B-3-4): every network
// scan time each station's area reaches every other station.
class CpuLink final : public Actor {
public:
    CpuLink(Network *network, Wire *wire, std::vector<Member> members)
        : m_network(network)
        , m_wire(wire)
        , m_members(std::move(members)) {
        for (const Member &m : m_members)
            if (m.number == 0)
                m_master = &m;
        const model::PortConfig &c =
            m_master ? m_master->port->config() : m_members.front().port->config();
        m_slaves = m_master ? c.slaves : 0;
        m_range = c.range;
        m_retries = c.retries;
        m_timeout = c.timeout;
        const model::SharedMode &mode =
            c.application->sharedModes[std::size_t(std::clamp(m_range, 1, 3) - 1)];
        m_cycleMs = mode.cycleMs[std::size_t(std::clamp(m_slaves + 1, 2, 8) - 2)];
        for (Member &m : m_members)
            m.share = shareOf(*m.station, mode, m.number);
        m_errors.assign(8, 0);
        m_next = qint64(m_cycleMs) * 1000;
        for (const Member &m : m_members)
            for (SystemRole role :
                 {SystemRole::CpuLinkFailed, SystemRole::CpuLinkErrorCount,
                  SystemRole::CpuLinkErrorCode, SystemRole::NetworkScanTime,
                  SystemRole::NetworkScanMax, SystemRole::CpuLinkTimeout, SystemRole::CpuLinkSlaves,
                  SystemRole::CpuLinkRange, SystemRole::CpuLinkRetries})
                resolved(m, role); // once, before the first exchange
    }
    qint64 nextUs() const override { return m_next; }
    void run(qint64 now) override {
        // Fixed arrays: an exchange runs every few ms of virtual time and allocates nothing.
        std::array<const Member *, 8> presentAt{};
        std::size_t presentCount = 0;
        std::array<int, 8> codes{}; // 0 none, 1 time-out, 5 sum error (D9212..)
        int failed = 0;
        for (int n = 0; n <= std::max(m_slaves, 0); ++n) {
            const Member *m = member(n);
            const bool there =
                m && !m_network->silent(m->station->name(), now) && !m_network->cut(*m_wire, now);
            // A corrupt fault counts this link's exchanges, one per station and cycle.
            const int frame = m_wire->frames++;
            bool corrupted = false;
            for (const FaultDescription &f : m_network->description().faults)
                corrupted = corrupted || (f.kind == FaultDescription::Kind::Corrupt &&
                                          f.wire == m_wire->name && f.frame == frame);
            if (there && !corrupted) {
                presentAt[presentCount++] = m;
                continue;
            }
            codes[std::size_t(n)] = there ? 5 : 1;
            ++m_errors[std::size_t(n)];
            ++failed;
        }
        if (!m_master) // no station 0: nobody polls, every station's link has failed
            codes[0] = 1;
        const auto present = std::span(presentAt).first(presentCount);
        // Station 0 drives the exchange: without it nothing moves.
        const bool polled = std::find(present.begin(), present.end(), m_master) != present.end();
        for (const Member *from : present)
            for (const Member *to : present)
                if (from != to && polled)
                    copy(*from, *to);
        // A station that does not answer costs the time-out once and each retry.
        const qint64 cycle = qint64(m_cycleMs) + qint64(failed) * m_timeout * 10 * (m_retries + 1);
        m_max = std::max<qint64>(m_max, cycle);
        // The status devices are the PLC's (the checks refuse a program that writes them):
        // written when what they show changes, not at every exchange (bench_network).
        const Shown shown{codes, m_errors, cycle, m_max};
        if (!m_shown || !(*m_shown == shown)) {
            m_shown = shown;
            for (const Member &s : m_members) {
                for (int n = 0; n < 8; ++n) {
                    setBit(s, SystemRole::CpuLinkFailed, n, codes[std::size_t(n)] != 0);
                    setWord(s, SystemRole::CpuLinkErrorCount, n, m_errors[std::size_t(n)]);
                    if (n > 0)
                        setWord(s, SystemRole::CpuLinkErrorCode, n - 1, codes[std::size_t(n)]);
                }
                setWord(s, SystemRole::NetworkScanTime, 0, std::int32_t(cycle));
                setWord(s, SystemRole::NetworkScanMax, 0, std::int32_t(m_max));
                setWord(s, SystemRole::CpuLinkTimeout, 0, m_timeout);
                setWord(s, SystemRole::CpuLinkSlaves, 0, m_slaves);
                setWord(s, SystemRole::CpuLinkRange, 0, m_range);
                setWord(s, SystemRole::CpuLinkRetries, 0, m_retries);
            }
        }
        if (m_network->recording()) {
            QStringList who;
            for (const Member *m : present)
                who << m->station->name();
            m_network->record(
                {now,
                 now + cycle * 1000,
                 m_wire->name,
                 m_master ? m_master->port->name : m_members.front().port->name,
                 {},
                 SharedLinkTr::tr("CPU Link exchange among %1 (%2 ms); no frames: the "
                                  "manual does not publish them")
                     .arg(who.isEmpty() ? SharedLinkTr::tr("no station")
                                        : who.join(QStringLiteral(", ")))
                     .arg(cycle)});
        }
        m_next = now + cycle * 1000;
    }

private:
    const Member *member(int number) const {
        for (const Member &m : m_members)
            if (m.number == number)
                return &m;
        return nullptr;
    }
    Network *m_network;
    Wire *m_wire;
    std::vector<Member> m_members;
    const Member *m_master = nullptr;
    int m_slaves = 0, m_range = 1, m_retries = 0, m_timeout = 5, m_cycleMs = 7;
    std::vector<int> m_errors;
    qint64 m_max = 0;
    struct Shown {
        std::array<int, 8> codes;
        std::vector<int> errors;
        qint64 cycle;
        qint64 max;
        bool operator==(const Shown &) const = default;
    };
    std::optional<Shown> m_shown; // what the status devices show
    qint64 m_next = 0;
};

// Parallel Link: a master and a slave exchange fixed areas after their programs (B-3-5).
class ParallelLink final : public Actor {
public:
    ParallelLink(Network *network, Wire *wire, std::vector<Member> members)
        : m_network(network)
        , m_wire(wire)
        , m_members(std::move(members)) {
        const Member *master = nullptr;
        for (const Member &m : m_members)
            if (m.port->config().parallelMaster)
                master = &m;
        const model::PortConfig &c = (master ? master : &m_members.front())->port->config();
        m_high = c.highSpeed;
        const model::SharedMode &mode = c.application->sharedModes[m_high ? 1 : 0];
        qint64 scans = 0;
        for (Member &m : m_members) {
            m.number = m.port->config().parallelMaster ? 0 : 1;
            m.share = shareOf(*m.station, mode, m.number);
            scans += m.station->periodMs();
        }
        // The manual's time is at 19200 bps; at another rate the line's part scales.
        const int baud = std::max(1, c.line.baud);
        m_cycleUs = qint64(mode.cycleMs.front()) * 1000 * 19200 / baud + scans * 1000;
        m_next = m_cycleUs;
    }
    qint64 nextUs() const override { return m_next; }
    void run(qint64 now) override {
        bool ok = m_members.size() == 2 && !m_network->cut(*m_wire, now);
        for (const Member &m : m_members)
            ok = ok && !m_network->silent(m.station->name(), now);
        const int frame = m_wire->frames++;
        for (const FaultDescription &f : m_network->description().faults)
            ok = ok && !(f.kind == FaultDescription::Kind::Corrupt && f.wire == m_wire->name &&
                         f.frame == frame);
        if (ok) {
            copy(m_members[0], m_members[1]);
            copy(m_members[1], m_members[0]);
        }
        for (const Member &m : m_members) {
            const Member &s = m;
            setBit(s, SystemRole::ParallelMaster, 0, m.number == 0);
            setBit(s, SystemRole::ParallelSlave, 0, m.number == 1);
            setBit(s, SystemRole::ParallelNormal, 0, ok);
            setBit(s, SystemRole::ParallelHighSpeed, 0, m_high);
            if (!ok) // M9063: "parallel operation ... error, PLC keeps running"
                setBit(s, SystemRole::CommError, 0, true);
        }
        if (m_network->recording())
            m_network->record(
                {now,
                 now + m_cycleUs,
                 m_wire->name,
                 m_members.front().port->name,
                 {},
                 ok ? SharedLinkTr::tr(
                          "Parallel Link exchange; no frames: the manual does not publish "
                          "them")
                    : SharedLinkTr::tr(
                          "Parallel Link: no exchange, the other station does not answer")});
        m_next = now + m_cycleUs;
    }

private:
    Network *m_network;
    Wire *m_wire;
    std::vector<Member> m_members;
    bool m_high = false;
    qint64 m_cycleUs = 0;
    qint64 m_next = 0;
};

} // namespace

bool makeSharedLinks(Network *network, std::vector<std::unique_ptr<Actor>> *groups,
                     QString *error) {
    for (const auto &wire : network->wires()) {
        std::vector<Member> cpu, parallel;
        for (Endpoint *e : wire->ends) {
            auto *port = dynamic_cast<StationPort *>(e);
            if (!port)
                continue;
            const int kind = port->config().application->sharedLink;
            Member m{port, network->station(port->owner), port->config().station, {}};
            if (kind == 1)
                cpu.push_back(m);
            else if (kind == 2)
                parallel.push_back(m);
        }
        if (!cpu.empty() && !parallel.empty()) {
            *error = SharedLinkTr::tr("wire %1: CPU Link and Parallel Link cannot share a wire")
                         .arg(wire->name);
            return false;
        }
        if (!cpu.empty()) {
            for (std::size_t i = 0; i < cpu.size(); ++i)
                for (std::size_t j = i + 1; j < cpu.size(); ++j)
                    if (cpu[i].number == cpu[j].number) {
                        *error = SharedLinkTr::tr("wire %1: %2 and %3 are both CPU Link station %4")
                                     .arg(wire->name, cpu[i].port->name, cpu[j].port->name)
                                     .arg(cpu[i].number);
                        return false;
                    }
            groups->push_back(std::make_unique<CpuLink>(network, wire.get(), std::move(cpu)));
        }
        if (!parallel.empty()) {
            int masters = 0;
            for (const Member &m : parallel)
                masters += m.port->config().parallelMaster ? 1 : 0;
            if (parallel.size() > 2 || masters != 1) {
                *error = SharedLinkTr::tr("wire %1: Parallel Link joins one master and one slave")
                             .arg(wire->name);
                return false;
            }
            groups->push_back(
                std::make_unique<ParallelLink>(network, wire.get(), std::move(parallel)));
        }
    }
    return true;
}

} // namespace rung::network
