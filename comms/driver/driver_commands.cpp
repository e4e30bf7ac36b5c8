// Driver: writes, forces, RUN / STOP (driver.h).

#include "comms/driver/driver.h"

#include "model/image/bcd.h"
#include "model/target/target.h"

#include <QCoreApplication>

namespace rung::comms {

namespace {

using K = DriverError::Kind;
using model::DevicePart;
using Kind = model::DeviceCommand::Kind;

QString onOff(bool on) {
    return on ? QCoreApplication::translate("rung::comms::Driver", "ON")
              : QCoreApplication::translate("rung::comms::Driver", "OFF");
}

} // namespace

DriverError Driver::prepareWrite(QString *notice) {
    QString said;
    DriverError e = m_protocol->prepareWrite(&said);
    if (notice && !said.isEmpty())
        *notice = said;
    return e;
}

DriverError Driver::writeValue(const model::Address &device, const model::Address &target,
                               qint64 value, const QString &what, QString *notice) {
    const auto pa = where(target, DevicePart::Value);
    if (!pa)
        return {
            K::BadDevice, 0,
            QCoreApplication::translate("rung::comms::Driver", "%1: %2 has no word address in %3")
                .arg(what, deviceName(device),
                     QCoreApplication::translate("rung::model::Target",
                                                 m_protocol->map().description))};
    const int bits = std::clamp(m_target.area(target.area).wordBits, 1, 32);
    // The word as the PLC keeps it (number() / wordOf()): where that is BCD digits (Host Link
    // RC / WC), the PLC answers any other word with end code 15, so it is not sent.
    if (m_protocol->bcdUnits(pa->space)) {
        if (value < 0 || value > 0x9999 || !model::fromBcd(value))
            return {K::BadDevice, 0,
                    QCoreApplication::translate("rung::comms::Driver",
                                                "%1: %2 holds four BCD digits (#0000..#9999); "
                                                "%3h is not one")
                        .arg(what, deviceName(device),
                             QString::number(value, 16).toUpper().rightJustified(4, u'0'))};
    }
    const qint64 lowest = -(qint64(1) << (bits - 1));
    const qint64 highest = (qint64(1) << bits) - 1;
    if (value < lowest || value > highest)
        return {
            K::BadDevice, 0,
            QCoreApplication::translate("rung::comms::Driver", "%1: %2 does not fit %3 (%4..%5)")
                .arg(what)
                .arg(value)
                .arg(deviceName(device))
                .arg(lowest)
                .arg(highest)};
    const auto raw = std::uint64_t(value);
    const int width = model::unitBits(pa->space);
    const std::uint64_t unitMask = (std::uint64_t(1) << width) - 1;
    std::vector<std::uint32_t> units;
    for (int i = 0; i < pa->units; ++i)
        units.push_back(std::uint32_t((raw >> (i * width)) & unitMask));
    if (DriverError e = prepareWrite(notice); !e.ok())
        return e;
    return m_protocol->writeUnits(pa->space, pa->unit, units, what);
}

DriverError Driver::execute(const model::DeviceCommand &command, QString *notice) {
    const model::Address &a = command.address;
    const QString name = a.valid() ? deviceName(a) : QString();
    const QString plc = plcName();
    const auto notABit = [&](const QString &what) {
        return DriverError{
            K::BadDevice, 0,
            QCoreApplication::translate("rung::comms::Driver", "%1: %2 is not a bit in %3")
                .arg(what, name,
                     QCoreApplication::translate("rung::model::Target",
                                                 m_protocol->map().description))};
    };
    switch (command.kind) {
    case Kind::WriteBit: {
        const QString what =
            QCoreApplication::translate("rung::comms::Driver", "setting %1 %2 on %3")
                .arg(name, onOff(command.value != 0), plc);
        const auto pa = where(a, DevicePart::Bit);
        if (!pa)
            return notABit(what);
        if (DriverError e = prepareWrite(notice); !e.ok())
            return e;
        return m_protocol->writeBit(*pa, command.value != 0, what);
    }
    case Kind::WriteWord: {
        const QString what =
            QCoreApplication::translate("rung::comms::Driver", "writing %1 = %2 to %3")
                .arg(name)
                .arg(command.value)
                .arg(plc);
        return writeValue(a, a, command.value, what, notice);
    }
    case Kind::WriteSetValue: {
        const QString what = QCoreApplication::translate("rung::comms::Driver",
                                                         "writing the set value of %1 = %2 to %3")
                                 .arg(name)
                                 .arg(command.value)
                                 .arg(plc);
        const model::Area &area = m_target.area(a.area);
        for (std::size_t k = 0; k < m_target.areas.size(); ++k) {
            const model::Area &presets = m_target.areas[k];
            if (!presets.presetsOf || area.key != QLatin1String(presets.presetsOf))
                continue;
            const model::Address preset{int(k), a.index, -1};
            if (!where(preset, DevicePart::Value))
                break;
            return writeValue(a, preset, command.value, what, notice);
        }
        return {K::Unsupported, 0,
                QCoreApplication::translate("rung::comms::Driver",
                                            "%1: the set value of %2 is a constant of the "
                                            "program in the PLC; %3 cannot change it (change "
                                            "the program, or make the set value a register)")
                    .arg(what, name,
                         QCoreApplication::translate("rung::model::Target",
                                                     m_protocol->map().description))};
    }
    case Kind::Force: {
        const QString what =
            QCoreApplication::translate("rung::comms::Driver", "forcing %1 %2 on %3")
                .arg(name, onOff(command.value != 0), plc);
        if (!m_protocol->canForce())
            return m_protocol->forceBit({}, false, what);
        const auto pa = where(a, DevicePart::Bit);
        if (!pa)
            return notABit(what);
        if (DriverError e = prepareWrite(notice); !e.ok())
            return e;
        DriverError e = m_protocol->forceBit(*pa, command.value != 0, what);
        if (e.ok())
            m_forced[a] = command.value != 0;
        return e;
    }
    case Kind::Release: {
        const QString what =
            QCoreApplication::translate("rung::comms::Driver", "releasing %1 on %2").arg(name, plc);
        if (!m_protocol->canForce())
            return m_protocol->forceBit({}, false, what);
        return {K::Unsupported, 0,
                QCoreApplication::translate("rung::comms::Driver",
                                            "%1: %2 has no command that releases one bit; "
                                            "release all forced bits instead (KC)")
                    .arg(what, protocolName(m_kind))};
    }
    case Kind::ReleaseAll: {
        const QString what =
            QCoreApplication::translate("rung::comms::Driver", "releasing every forced bit on %1")
                .arg(plc);
        if (m_protocol->canForce())
            if (DriverError e = prepareWrite(notice); !e.ok())
                return e;
        DriverError e = m_protocol->releaseAllForces(what);
        if (e.ok())
            m_forced.clear();
        return e;
    }
    }
    return {};
}

DriverError Driver::readMode(PlcMode *mode) {
    *mode = PlcMode::Unknown;
    if (m_protocol->readsMode())
        return m_protocol->readMode(mode);
    if (!m_runDevice.valid())
        return {};
    std::vector<qint64> values;
    if (DriverError e = read({m_runDevice}, &values); !e.ok())
        return e;
    *mode = values.front() != 0 ? PlcMode::Run : PlcMode::Stop;
    return {};
}

bool Driver::canSetMode() const {
    return m_protocol->setsMode() || m_runControl.valid();
}

DriverError Driver::setMode(PlcMode mode) {
    if (m_protocol->setsMode() || !m_runControl.valid())
        return m_protocol->setMode(mode);
    const QString what = QCoreApplication::translate("rung::comms::Driver", "switching %1 to %2")
                             .arg(plcName(), modeName(mode));
    if (mode != PlcMode::Run && mode != PlcMode::Stop)
        return {
            K::Unsupported, 0,
            QCoreApplication::translate("rung::comms::Driver", "%1: the PLC has RUN and STOP only")
                .arg(what)};
    const auto pa = where(m_runControl, DevicePart::Bit);
    return m_protocol->writeBit(*pa, mode == PlcMode::Run, what);
}

} // namespace rung::comms
