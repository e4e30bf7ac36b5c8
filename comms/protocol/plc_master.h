#pragma once

// The codecs of this room as the master a PLC's program drives (model/comm/master_protocol.h):
// Vigor Computer Link for LINK (Vigor M/VB/VH communication manual, B-3-3), MODBUS RTU or ASCII for
// MBUS (B-3-6) and the PL110's COM / EXP (PL110 manual 4.2.21). The same encoders and decoders as
// the IDE's driver and the virtual PLC's responders, so the frames on a simulated wire are the
// product's frames.

#include "comms/protocol/modbus_master.h"
#include "comms/protocol/vigor_link_master.h"
#include "model/comm/master_protocol.h"

#include <memory>
#include <optional>

namespace rung::comms {

class VigorLinkMaster final : public model::MasterProtocol {
public:
    int maxUnits(model::ProtocolSpace space, bool write) const override;
    QByteArray request(const model::MasterRequest &request) override;
    bool expectsReply() const override { return true; }
    model::MasterStatus feed(QByteArrayView bytes) override;
    const std::vector<std::uint16_t> &values() const override { return m_values; }
    QString problem() const override { return m_problem; }
    int errorCode() const override { return m_code; }

private:
    std::optional<vigor::ReplyDecoder> m_decoder;
    std::vector<std::uint16_t> m_values;
    QString m_problem;
    int m_code = 0;
};

class ModbusMaster final : public model::MasterProtocol {
public:
    explicit ModbusMaster(modbus::Framing framing)
        : m_framing(framing) {}
    int maxUnits(model::ProtocolSpace space, bool write) const override;
    QByteArray request(const model::MasterRequest &request) override;
    bool expectsReply() const override { return m_expects; }
    model::MasterStatus feed(QByteArrayView bytes) override;
    const std::vector<std::uint16_t> &values() const override { return m_values; }
    QString problem() const override { return m_problem; }
    int errorCode() const override { return m_code; }

private:
    modbus::Framing m_framing;
    std::optional<modbus::ReplyDecoder> m_decoder;
    bool m_expects = true;
    std::vector<std::uint16_t> m_values;
    QString m_problem;
    int m_code = 0;
};

} // namespace rung::comms
