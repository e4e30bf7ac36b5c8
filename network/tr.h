#pragma once

// The translation contexts of network/'s messages, each declared once: a file's texts go
// through its context, NetworkTr::tr("..."). lupdate takes the context from the class a tr()
// call names, so each is a class, not an alias of one.

#include <QCoreApplication>

namespace rung::network {

struct DevicesTr {
    Q_DECLARE_TR_FUNCTIONS(rung::network::Devices)
};
struct EngineImageTr {
    Q_DECLARE_TR_FUNCTIONS(rung::network::EngineImage)
};
struct NetworkCheckTr {
    Q_DECLARE_TR_FUNCTIONS(rung::network::NetworkCheck)
};
struct NetworkFileTr {
    Q_DECLARE_TR_FUNCTIONS(rung::network::NetworkFile)
};
struct NetworkTr {
    Q_DECLARE_TR_FUNCTIONS(rung::network::Network)
};
struct NetworkSessionTr {
    Q_DECLARE_TR_FUNCTIONS(rung::network::NetworkSession)
};
struct SharedLinkTr {
    Q_DECLARE_TR_FUNCTIONS(rung::network::SharedLink)
};
struct TraceTr {
    Q_DECLARE_TR_FUNCTIONS(rung::network::Trace)
};
struct TrafficTr {
    Q_DECLARE_TR_FUNCTIONS(rung::network::Traffic)
};
struct TrafficDecodeTr {
    Q_DECLARE_TR_FUNCTIONS(rung::network::TrafficDecode)
};

} // namespace rung::network
