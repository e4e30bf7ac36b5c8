#include "comms/driver/driver.h"

#include "model/image/bcd.h"
#include "model/image/snapshot.h"
#include "model/target/address.h"
#include "model/target/target.h"

#include <QCoreApplication>

#include <algorithm>

namespace rung::comms {

namespace {

using K = DriverError::Kind;
using model::DevicePart;

bool isCounterOrTimer(const model::Area &area) {
    return area.kind == model::AreaKind::Timer || area.kind == model::AreaKind::Counter;
}

} // namespace

Driver::Driver(const model::Target &target, ProtocolKind kind, std::unique_ptr<Link> link)
    : m_target(target)
    , m_kind(kind)
    , m_link(std::move(link))
    , m_layout(std::make_shared<const model::MemoryLayout>(target)) {}

Driver::~Driver() = default;

std::unique_ptr<Driver> Driver::create(const model::Target &target, ProtocolKind protocol,
                                       std::unique_ptr<Transport> transport, int station,
                                       const LinkSettings &settings, QString *error) {
    const bool modbus = protocol == ProtocolKind::ModbusRtu || protocol == ProtocolKind::ModbusTcp;
    const int lowest = modbus ? 1 : 0;
    const int highest = protocol == ProtocolKind::HostLink ? 31 : 255;
    if (station < lowest || station > highest) {
        if (error)
            *error = modbus && station == 0
                         ? QCoreApplication::translate(
                               "rung::comms::Driver",
                               "station 0 is the Modbus broadcast address: no PLC answers it, "
                               "so nothing could be read and no write acknowledged; give the "
                               "PLC's own station (1..247, or 255 for any PL110)")
                         : QCoreApplication::translate("rung::comms::Driver",
                                                       "station %1 is outside %2's %3..%4")
                               .arg(station)
                               .arg(protocolName(protocol))
                               .arg(lowest)
                               .arg(highest);
        return nullptr;
    }
    std::unique_ptr<Driver> d(
        new Driver(target, protocol, std::make_unique<Link>(std::move(transport), settings)));
    d->m_protocol = makeProtocolDriver(protocol, *d->m_link, target, station, error);
    if (!d->m_protocol)
        return nullptr;
    d->m_segments = mappedSegments(target, d->m_protocol->map());
    if (!d->m_protocol->readsMode()) {
        // The RUN bit (PL110 SM0.0) tells and sets the mode; an "ON while running" bit
        // (Vigor M9000) tells it only.
        const model::Address run = model::systemAddress(target, model::SystemRole::Run);
        if (run.valid() && d->where(run, DevicePart::Bit)) {
            d->m_runDevice = d->m_runControl = run;
        } else {
            const model::Address on = model::systemAddress(target, model::SystemRole::AlwaysOn);
            if (on.valid() && d->where(on, DevicePart::Bit))
                d->m_runDevice = on;
        }
    }
    return d;
}

std::variant<model::Address, QString> Driver::parseDevice(QStringView text) const {
    auto parsed = model::parseAddress(m_target, text.trimmed());
    if (const auto *a = std::get_if<model::Address>(&parsed))
        return *a;
    return QCoreApplication::translate("rung::comms::Driver", "%1: %2")
        .arg(text.toString(), std::get<model::AddressError>(parsed).message);
}

QString Driver::deviceName(const model::Address &address) const {
    return model::formatAddress(m_target, address);
}

std::optional<model::ProtocolAddress> Driver::where(const model::Address &address,
                                                    DevicePart part) const {
    return model::toProtocol(m_target, m_protocol->map(), address, part);
}

std::vector<Driver::Placement> Driver::placementsOf(const model::Address &address,
                                                    QString *why) const {
    std::vector<Placement> out;
    if (!address.valid() || address.area >= int(m_target.areas.size()))
        return out;
    const model::Area &area = m_target.area(address.area);
    const auto bitOf = [&](const model::Address &a) {
        const auto pa = where(a, DevicePart::Bit);
        const model::BitRef ref = m_layout->bit(a);
        if (!pa || !ref.valid())
            return;
        out.push_back({{pa->space, pa->unit, 1}, pa->bit, ref.word, ref.mask, 1});
    };
    const auto valueOf = [&](const model::Address &a, int word) {
        const auto pa = where(a, DevicePart::Value);
        if (!pa || word < 0)
            return;
        out.push_back(
            {{pa->space, pa->unit, pa->units}, -1, word, 0, m_target.area(a.area).wordBits});
    };
    if (address.bit >= 0 || area.kind == model::AreaKind::Bit) {
        bitOf(address);
    } else if (area.holdsWords()) {
        valueOf(address, m_layout->word(address));
    } else if (isCounterOrTimer(area)) {
        bitOf(address);
        valueOf(address, m_layout->word(address));
        // The set value, where an area of the PLC holds it (PL110 PT / PV).
        for (std::size_t k = 0; k < m_target.areas.size(); ++k) {
            const model::Area &presets = m_target.areas[k];
            if (presets.presetsOf && area.key == QLatin1String(presets.presetsOf) &&
                address.index >= presets.first && address.index <= presets.last)
                valueOf({int(k), address.index, -1}, m_layout->setValueWord(address));
        }
    }
    if (out.empty() && why)
        *why = QCoreApplication::translate("rung::comms::Driver",
                                           "%1 has no address in %2, so it cannot be read "
                                           "over it")
                   .arg(deviceName(address),
                        QCoreApplication::translate("rung::model::Target",
                                                    m_protocol->map().description));
    return out;
}

Driver::Plan Driver::plan(const std::vector<model::Address> &devices) const {
    Plan p;
    std::vector<UnitSpan> needs;
    for (const model::Address &a : devices) {
        QString why;
        std::vector<Placement> placements = placementsOf(a, &why);
        if (placements.empty()) {
            p.unmapped.emplace_back(a, why);
            continue;
        }
        for (const Placement &pl : placements)
            needs.push_back(pl.source);
        p.devices.push_back(a);
        p.placements.push_back(std::move(placements));
    }
    const ReadCosts costs{
        [this](model::ProtocolSpace s) { return m_protocol->maxReadUnits(s); },
        [this](model::ProtocolSpace s, int n) { return m_protocol->readFrameBytes(s, n); }};
    p.reads = planReads(std::move(needs), costs, m_segments);
    return p;
}

QString Driver::describeFrame(const Plan &plan, const PlannedRead &read) const {
    QStringList names;
    int more = 0;
    for (std::size_t d = 0; d < plan.devices.size(); ++d) {
        const bool inFrame = std::any_of(
            plan.placements[d].begin(), plan.placements[d].end(), [&read](const Placement &p) {
                return p.source.space == read.span.space && p.source.start >= read.span.start &&
                       p.source.end() <= read.span.end();
            });
        if (!inFrame)
            continue;
        if (names.size() < 3)
            names << deviceName(plan.devices[d]);
        else
            ++more;
    }
    const QString list = more > 0
                             ? QCoreApplication::translate("rung::comms::Driver", "%1 and %2 more")
                                   .arg(names.join(QLatin1String(", ")))
                                   .arg(more)
                             : names.join(QLatin1String(", "));
    return QCoreApplication::translate("rung::comms::Driver", "reading %1 from %2")
        .arg(list, plcName());
}

DriverError Driver::refresh(const Plan &plan, std::vector<std::int32_t> &words,
                            std::vector<std::pair<model::Address, QString>> *refused) {
    struct Run {
        UnitSpan span;
        std::vector<std::uint32_t> units;
    };
    std::vector<Run> runs;
    std::vector<bool> bad(plan.devices.size(), false);
    const auto inside = [](const UnitSpan &part, const UnitSpan &whole) {
        return part.space == whole.space && part.start >= whole.start && part.end() <= whole.end();
    };
    for (const PlannedRead &read : plan.reads) {
        Run run{read.span, {}};
        DriverError e = m_protocol->readUnits(read.span.space, read.span.start, read.span.count,
                                              &run.units, describeFrame(plan, read));
        if (e.ok()) {
            runs.push_back(std::move(run));
            continue;
        }
        if (e.kind != K::Refused)
            return e;
        // The PLC refused the frame: read its devices one by one to name the one it lacks
        // (a model with fewer I/O than the family, an area the protocol does not reach).
        for (std::size_t d = 0; d < plan.devices.size(); ++d) {
            for (const Placement &p : plan.placements[d]) {
                if (bad[d] || !inside(p.source, read.span))
                    continue;
                Run alone{p.source, {}};
                const QString what =
                    QCoreApplication::translate("rung::comms::Driver", "reading %1 from %2")
                        .arg(deviceName(plan.devices[d]), plcName());
                DriverError one = m_protocol->readUnits(p.source.space, p.source.start,
                                                        p.source.count, &alone.units, what);
                if (one.ok()) {
                    runs.push_back(std::move(alone));
                } else if (one.kind == K::Refused) {
                    bad[d] = true;
                    if (refused)
                        refused->emplace_back(plan.devices[d], one.message);
                } else {
                    return one;
                }
            }
        }
    }
    for (std::size_t d = 0; d < plan.devices.size(); ++d) {
        if (bad[d])
            continue;
        for (const Placement &p : plan.placements[d]) {
            const auto run = std::find_if(runs.begin(), runs.end(),
                                          [&](const Run &r) { return inside(p.source, r.span); });
            if (run == runs.end() || p.word < 0 || std::size_t(p.word) >= words.size())
                continue;
            const std::size_t at = std::size_t(p.source.start - run->span.start);
            auto &word = words[std::size_t(p.word)];
            if (p.mask != 0) {
                const std::uint32_t unit = run->units[at];
                const bool on = p.bit < 0 ? unit != 0 : ((unit >> p.bit) & 1) != 0;
                word =
                    std::int32_t(on ? std::uint32_t(word) | p.mask : std::uint32_t(word) & ~p.mask);
                continue;
            }
            const int width = model::unitBits(p.source.space);
            std::uint64_t raw = 0;
            for (int i = 0; i < p.source.count; ++i)
                raw |= std::uint64_t(run->units[at + std::size_t(i)]) << (i * width);
            word = model::wrapToWidth(std::int64_t(raw), p.bits);
        }
    }
    return {};
}

DriverError Driver::read(const std::vector<model::Address> &devices, std::vector<qint64> *values) {
    const Plan p = plan(devices);
    if (!p.unmapped.empty())
        return {K::BadDevice, 0, p.unmapped.front().second};
    std::vector<std::int32_t> words(std::size_t(m_layout->wordCount()), 0);
    std::vector<std::pair<model::Address, QString>> refused;
    if (DriverError e = refresh(p, words, &refused); !e.ok())
        return e;
    if (!refused.empty())
        return {K::Refused, 0, refused.front().second};
    model::Snapshot image;
    image.layout = m_layout;
    image.words = std::move(words);
    values->clear();
    for (const model::Address &a : devices)
        values->push_back(number(image, a));
    return {};
}

bool Driver::keepsBcd(const model::Address &address) const {
    const auto pa = address.bit < 0 ? where(address, DevicePart::Value) : std::nullopt;
    return pa && m_protocol->bcdUnits(pa->space);
}

qint64 Driver::number(const model::Snapshot &image, const model::Address &device) const {
    const model::Area &area = m_target.area(device.area);
    if (device.bit >= 0 || area.kind == model::AreaKind::Bit)
        return image.bit(device) ? 1 : 0;
    const qint64 word = image.value(device);
    // Not BCD (a PLC that holds something else there): shown as it is, not as a wrong number.
    return keepsBcd(device) ? model::fromBcd(word).value_or(word) : word;
}

std::optional<qint64> Driver::wordOf(const model::Address &device, qint64 number,
                                     QString *why) const {
    if (!keepsBcd(device))
        return number; // execute() checks that it fits the word
    if (number < 0 || number > 9999) {
        if (why)
            *why =
                QCoreApplication::translate("rung::comms::Driver", "%1 does not fit %2 (0..9999)")
                    .arg(number)
                    .arg(deviceName(device));
        return std::nullopt;
    }
    return model::toBcd(number);
}

} // namespace rung::comms
