#include "model/comm/port_config.h"
#include "model/tr.h"

#include <QCoreApplication>
#include <QJsonArray>

namespace rung::model {

namespace {

QString at(const QString &path, const QString &key) {
    return path.isEmpty() ? key : path + QLatin1Char('.') + key;
}

QString list(const std::vector<int> &values) {
    QStringList out;
    for (int v : values)
        out << QString::number(v);
    return out.join(QStringLiteral(", "));
}

QString applicationIds(const PortSpec &spec, const ModelVariant *model) {
    QStringList out;
    for (const PortApplication &a : spec.applications)
        if (!model || applicationOn(a, model->name))
            out << QString::fromLatin1(a.id);
    return out.join(QStringLiteral(", "));
}

// The keys each application reads besides the common ones.
bool keyBelongs(const QString &key, const PortApplication &a) {
    const QLatin1String id(a.id);
    if (key == QLatin1String("application") || key == QLatin1String("station") ||
        key == QLatin1String("baud") || key == QLatin1String("frame"))
        return true;
    if (key == QLatin1String("slaves") || key == QLatin1String("range") ||
        key == QLatin1String("retry") || key == QLatin1String("timeout"))
        return id == QLatin1String("cpu-link");
    if (key == QLatin1String("role") || key == QLatin1String("speed"))
        return id == QLatin1String("parallel-link");
    if (key == QLatin1String("mode"))
        return id == QLatin1String("modbus");
    if (key == QLatin1String("start") || key == QLatin1String("end"))
        return a.programDriven;
    return false;
}

bool readInt(const QJsonObject &o, const char *key, const QString &path, int lowest, int highest,
             int *into, QString *error) {
    const QJsonValue v = o.value(QLatin1String(key));
    if (v.isUndefined())
        return true;
    const double d = v.toDouble(-1e300);
    if (!v.isDouble() || d != static_cast<double>(static_cast<qint64>(d)) || d < lowest ||
        d > highest) {
        *error = PortConfigTr::tr("%1: needs a whole number from %2 to %3")
                     .arg(at(path, QLatin1String(key)))
                     .arg(lowest)
                     .arg(highest);
        return false;
    }
    *into = static_cast<int>(d);
    return true;
}

bool readChoice(const QJsonObject &o, const char *key, const QString &path, const char *yes,
                const char *no, bool *into, QString *error) {
    const QJsonValue v = o.value(QLatin1String(key));
    if (v.isUndefined())
        return true;
    if (v.toString() == QLatin1String(yes)) {
        *into = true;
        return true;
    }
    if (v.toString() == QLatin1String(no)) {
        *into = false;
        return true;
    }
    *error = PortConfigTr::tr("%1: needs \"%2\" or \"%3\"")
                 .arg(at(path, QLatin1String(key)), QLatin1String(yes), QLatin1String(no));
    return false;
}

// A start or end character: a number 0..255 or null (none).
bool readCode(const QJsonObject &o, const char *key, const QString &path, int *into,
              QString *error) {
    const QJsonValue v = o.value(QLatin1String(key));
    if (v.isUndefined())
        return true;
    if (v.isNull()) {
        *into = -1;
        return true;
    }
    return readInt(o, key, path, kCharacterCode.lowest, kCharacterCode.highest, into, error);
}

} // namespace

QJsonObject mergePortJson(const std::vector<PortLayer> &layers) {
    QJsonObject merged;
    for (const PortLayer &layer : layers)
        for (auto it = layer.json.begin(); it != layer.json.end(); ++it)
            merged.insert(it.key(), it.value());
    return merged;
}

bool readPortConfig(const Target &target, const ModelVariant *model, const QString &port,
                    const std::vector<PortLayer> &layers, PortConfig *config, QString *error) {
    const QString where = layers.empty() ? QString() : layers.back().path;
    const PortSpec *spec = target.port(port);
    const QString modelName = model ? model->name : target.defaultModel().name;
    if (!spec) {
        QStringList names;
        for (const PortSpec &p : target.ports)
            if (p.on(modelName))
                names << p.name;
        *error = names.isEmpty()
                     ? PortConfigTr::tr("%1: %2 has no serial port a network can use")
                           .arg(where, target.displayName)
                     : PortConfigTr::tr("%1: %2 has no port %3 (its ports: %4)")
                           .arg(where, target.displayName, port, names.join(QStringLiteral(", ")));
        return false;
    }
    if (!spec->on(modelName)) {
        *error = PortConfigTr::tr("%1: the %2 %3 has no port %4")
                     .arg(where, target.displayName, modelName, spec->name);
        return false;
    }
    config->port = spec->name;
    // Which layer set the application, so that an error names the right key.
    QString applicationPath = where;
    QString id;
    for (const PortLayer &layer : layers) {
        const QJsonValue v = layer.json.value(QLatin1String("application"));
        if (v.isUndefined())
            continue;
        if (!v.isString()) {
            *error = PortConfigTr::tr("%1: needs the name of an application")
                         .arg(at(layer.path, QStringLiteral("application")));
            return false;
        }
        id = v.toString();
        applicationPath = layer.path;
    }
    const PortApplication *app = id.isEmpty() ? &spec->applications.front() : spec->application(id);
    if (!app) {
        *error = PortConfigTr::tr("%1: %2 is no application of %3 (%4)")
                     .arg(at(applicationPath, QStringLiteral("application")), id, spec->name,
                          applicationIds(*spec, model));
        return false;
    }
    if (!applicationOn(*app, modelName)) {
        *error = PortConfigTr::tr("%1: the %2 %3 has no %4 on %5 (it has: %6)")
                     .arg(at(applicationPath, QStringLiteral("application")), target.displayName,
                          modelName, QCoreApplication::translate("rung::model::Target", app->name),
                          spec->name, applicationIds(*spec, model));
        return false;
    }
    config->application = app;
    config->station = app->station;
    config->line = {};
    config->line.baud = app->bauds.empty() ? 19200 : app->bauds.front();
    parseFrameFormat(QString::fromLatin1(app->frame), &config->line);
    for (const PortLayer &layer : layers) {
        const QJsonObject &o = layer.json;
        for (auto it = o.begin(); it != o.end(); ++it)
            if (!keyBelongs(it.key(), *app)) {
                *error = PortConfigTr::tr("%1: %2 takes no setting \"%3\"")
                             .arg(at(layer.path, it.key()),
                                  QCoreApplication::translate("rung::model::Target", app->name),
                                  it.key());
                return false;
            }
        if (!readInt(o, "station", layer.path, app->stationMin, app->stationMax, &config->station,
                     error))
            return false;
        const QJsonValue baud = o.value(QLatin1String("baud"));
        if (!baud.isUndefined()) {
            const int b = baud.toInt(-1);
            if (std::find(app->bauds.begin(), app->bauds.end(), b) == app->bauds.end()) {
                *error = PortConfigTr::tr("%1: %2 is not a rate of %3 (%4)")
                             .arg(at(layer.path, QStringLiteral("baud")),
                                  baud.isDouble() ? QString::number(baud.toDouble())
                                                  : baud.toVariant().toString(),
                                  QCoreApplication::translate("rung::model::Target", app->name),
                                  list(app->bauds));
                return false;
            }
            config->line.baud = b;
        }
        const QJsonValue frame = o.value(QLatin1String("frame"));
        if (!frame.isUndefined()) {
            SerialSettings line = config->line;
            if (!frame.isString() || !parseFrameFormat(frame.toString(), &line)) {
                *error = PortConfigTr::tr(
                             "%1: \"%2\" is no character format (data bits 7 or 8, parity N, "
                             "E or O, stop bits 1 or 2: 8N1, 7E1)")
                             .arg(at(layer.path, QStringLiteral("frame")), frame.toString());
                return false;
            }
            if (app->fixedFrame && !line.sameLine(config->line)) {
                *error = PortConfigTr::tr("%1: %2 always uses %3")
                             .arg(at(layer.path, QStringLiteral("frame")),
                                  QCoreApplication::translate("rung::model::Target", app->name),
                                  QLatin1String(app->frame));
                return false;
            }
            config->line = line;
        }
        if (!readInt(o, "slaves", layer.path, kCpuLinkSlaves.lowest, kCpuLinkSlaves.highest,
                     &config->slaves, error) ||
            !readInt(o, "range", layer.path, kCpuLinkRange.lowest, kCpuLinkRange.highest,
                     &config->range, error) ||
            !readInt(o, "retry", layer.path, kCpuLinkRetries.lowest, kCpuLinkRetries.highest,
                     &config->retries, error) ||
            !readInt(o, "timeout", layer.path, kCpuLinkTimeout.lowest, kCpuLinkTimeout.highest,
                     &config->timeout, error) ||
            !readChoice(o, "role", layer.path, "master", "slave", &config->parallelMaster, error) ||
            !readChoice(o, "speed", layer.path, "high", "low", &config->highSpeed, error) ||
            !readChoice(o, "mode", layer.path, "ascii", "rtu", &config->modbusAscii, error) ||
            !readCode(o, "start", layer.path, &config->startCode, error) ||
            !readCode(o, "end", layer.path, &config->endCode, error))
            return false;
    }
    return true;
}

bool checkPortsJson(const Target &target, const ModelVariant *model, const QJsonObject &ports,
                    const QString &path, QString *error) {
    for (auto it = ports.begin(); it != ports.end(); ++it) {
        const QString where = at(path, it.key());
        if (!it.value().isObject()) {
            *error = PortConfigTr::tr("%1: needs an object of settings").arg(where);
            return false;
        }
        PortConfig config;
        if (!readPortConfig(target, model, it.key(), {{it.value().toObject(), where}}, &config,
                            error))
            return false;
    }
    return true;
}

QString instructionPort(const Instruction &instruction) {
    const InstructionSpec *spec = instruction.spec;
    if (!spec || (!spec->port && spec->portOperand < 0))
        return {};
    QString name = spec->port ? QString::fromLatin1(spec->port) : QString();
    if (spec->portOperand < 0)
        return name;
    if (static_cast<std::size_t>(spec->portOperand) >= instruction.operands.size())
        return {};
    const Operand &o = instruction.operands[static_cast<std::size_t>(spec->portOperand)];
    if (o.kind == Operand::Kind::Constant && !o.modified())
        return name + QString::number(o.constant.value);
    return name + o.text.trimmed().toUpper();
}

} // namespace rung::model
