#!/usr/bin/python3
"""A Modbus slave built on Debian's python3-pymodbus, for the tests of our master.

    pymodbus_peer.py rtu PATH UNIT    RTU on a serial port or pseudo-terminal
    pymodbus_peer.py tcp PORT UNIT    Modbus TCP on 127.0.0.1:PORT

The values are peer_values.h's formulas. Prints "ready", then serves until killed.
"""
import asyncio
import sys

from pymodbus.datastore import (ModbusSequentialDataBlock, ModbusServerContext,
                                ModbusSlaveContext)
from pymodbus.server import StartAsyncSerialServer, StartAsyncTcpServer
from pymodbus.transaction import ModbusRtuFramer, ModbusSocketFramer

SIZE = 40000


def main():
    mode, where, unit = sys.argv[1], sys.argv[2], int(sys.argv[3])
    regs = [(a * 7 + 3) & 0xFFFF for a in range(SIZE)]
    slave = ModbusSlaveContext(
        co=ModbusSequentialDataBlock(0, [a % 3 == 0 for a in range(SIZE)]),
        di=ModbusSequentialDataBlock(0, [a % 5 == 0 for a in range(SIZE)]),
        hr=ModbusSequentialDataBlock(0, list(regs)),
        ir=ModbusSequentialDataBlock(0, list(regs)),
        zero_mode=True)
    context = ModbusServerContext(slaves={unit: slave}, single=False)

    async def run():
        if mode == "rtu":
            server = await StartAsyncSerialServer(
                context=context, framer=ModbusRtuFramer, port=where, baudrate=19200,
                bytesize=8, parity="N", stopbits=1, defer_start=True)
        else:
            server = await StartAsyncTcpServer(
                context=context, framer=ModbusSocketFramer, address=("127.0.0.1", int(where)),
                defer_start=True)
        if mode == "rtu":
            await server.start()
            print("ready", flush=True)
            await asyncio.Event().wait()
        else:
            serving = asyncio.create_task(server.serve_forever())
            await server.serving  # listening now
            print("ready", flush=True)
            await serving

    asyncio.run(run())


if __name__ == "__main__":
    main()
