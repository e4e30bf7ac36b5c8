#include "transport.h"

#include <libserialport.h>

namespace rung::comms {

QStringList availableSerialPorts()
{
    QStringList names;
    sp_port **ports = nullptr;
    if (sp_list_ports(&ports) != SP_OK)
        return names;
    for (int i = 0; ports[i]; ++i)
        names << QString::fromUtf8(sp_get_port_name(ports[i]));
    sp_free_port_list(ports);
    return names;
}

} // namespace rung::comms
