// A Modbus slave built on Debian's libmodbus, for the tests of our master (test_real_peers):
//   rung_modbus_peer rtu PATH UNIT    RTU on a serial port or pseudo-terminal
//   rung_modbus_peer tcp PORT UNIT    Modbus TCP on 127.0.0.1:PORT
// Every address holds a value the test can compute (peer_values.h); writes change it. It
// prints "ready" once it listens and serves until it is killed.

#include "peer_values.h"

#include <modbus.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <unistd.h>

int main(int argc, char **argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: %s rtu PATH UNIT | tcp PORT UNIT\n", argv[0]);
        return 2;
    }
    const bool rtu = std::strcmp(argv[1], "rtu") == 0;
    const int unit = std::atoi(argv[3]);
    modbus_t *ctx = rtu ? modbus_new_rtu(argv[2], 19200, 'N', 8, 1)
                        : modbus_new_tcp("127.0.0.1", std::atoi(argv[2]));
    if (!ctx) {
        std::fprintf(stderr, "modbus_new: %s\n", modbus_strerror(errno));
        return 1;
    }
    modbus_set_slave(ctx, unit);
    using namespace rung::comms::test::peer;
    modbus_mapping_t *map = modbus_mapping_new(Size, Size, Size, Size);
    for (int a = 0; a < Size; ++a) {
        map->tab_bits[a] = coil(a) ? 1 : 0;
        map->tab_input_bits[a] = input(a) ? 1 : 0;
        map->tab_registers[a] = reg(a);
        map->tab_input_registers[a] = reg(a);
    }
    int server = -1;
    if (rtu) {
        if (modbus_connect(ctx) != 0) {
            std::fprintf(stderr, "modbus_connect %s: %s\n", argv[2], modbus_strerror(errno));
            return 1;
        }
    } else {
        server = modbus_tcp_listen(ctx, 1);
        if (server < 0) {
            std::fprintf(stderr, "modbus_tcp_listen: %s\n", modbus_strerror(errno));
            return 1;
        }
    }
    std::printf("ready\n");
    std::fflush(stdout);
    // A test that died (an abort, a sanitizer's halt) cannot stop its peer: an orphan leaves,
    // and so does a peer whose pseudo-terminal is gone (EIO at once, forever: a spinning
    // core for the rest of the test run).
    const pid_t parent = ::getppid();
    for (;;) {
        if (!rtu && modbus_tcp_accept(ctx, &server) < 0)
            return 1;
        for (;;) {
            uint8_t request[MODBUS_TCP_MAX_ADU_LENGTH];
            const int n = modbus_receive(ctx, request);
            if (n == 0)
                continue; // not for this unit
            if (::getppid() != parent || (rtu && n < 0 && errno == EIO))
                return 0;
            if (n < 0)
                break; // the connection closed (TCP), or a broken frame (RTU): go on
            modbus_reply(ctx, request, n, map);
        }
        if (rtu)
            modbus_flush(ctx);
        else
            ::close(modbus_get_socket(ctx));
    }
}
