#include "comms/slave/responder.h"

namespace rung::comms::slave {

ImageChange Responder::apply(const MappedImage::Change &change) {
    const QDeadlineTimer deadline(m_writeTimeoutMs);
    if (!change.commands.empty()) {
        ImageChange done = m_image->apply(change.commands, deadline);
        if (!done.done())
            return done;
    }
    if (change.mode && *change.mode != m_image->mode())
        return m_image->setMode(*change.mode, deadline);
    return {};
}

} // namespace rung::comms::slave
