#!/usr/bin/env python3
"""Writes the comms fuzzers' seed corpus (tests/fuzz/corpus/<fuzzer>/) from the manuals'
example frames (Vigor M/VB/VH communication manual, B-5-3; Omron CPM1/SRM1 programming manual
W353, Host Link) and the Modbus Application Protocol V1.1b3's examples, each behind the bytes
that pick the request and split the stream into reads (tests/fuzz/fuzz_comms_common.h: a
chunk is one size byte, 1 + size % 16, then that many bytes). ctest replays the corpus in a
normal build; scripts/fuzz.sh starts libFuzzer from it. Run it again after changing the
fuzzers' input layout: python3 tests/fuzz/make_corpus.py"""
import pathlib

HERE = pathlib.Path(__file__).resolve().parent / "corpus"


def hx(text):
    return bytes.fromhex(text.replace(" ", ""))


def chunks(stream, size=16):
    out = b""
    for i in range(0, len(stream), size):
        piece = stream[i:i + size]
        out += bytes([len(piece) - 1]) + piece
    return out


def word(value):
    return bytes([value >> 8 & 0xFF, value & 0xFF])


def write(fuzzer, name, data):
    d = HERE / fuzzer
    d.mkdir(parents=True, exist_ok=True)
    (d / name).write_bytes(data)


# ----- Vigor Computer Link (Vigor M/VB/VH communication manual, B-5-3: its six examples) -----
# prefix: station, command (0 51h, 1 61h, 2 70h, 3 71h), address(2), length byte (1 + b % 128)
VIGOR = [
    ("read_m8", 0, 0x0081, 2, "02 30 30 35 31 30 30 38 31 30 32 03 46 34",
     "06 30 30 35 31 30 30 41 37 39 33 03 30 44"),
    ("read_d1_d2", 0, 0x1C02, 4, "02 30 30 35 31 31 43 30 32 30 34 03 30 33",
     "06 30 30 35 31 30 30 33 34 31 32 43 44 41 42 03 46 44"),
    ("write_y30", 1, 0x0043, 2, "02 30 30 36 31 30 30 34 33 30 32 43 36 33 45 03 45 34",
     "06 30 30 36 31 30 30 03 32 41"),
    ("write_d1", 1, 0x1C02, 2, "02 30 30 36 31 31 43 30 32 30 32 32 35 41 33 03 44 44",
     "06 30 30 36 31 30 30 03 32 41"),
    ("m10_on", 2, 0x040A, 1, "02 30 30 37 30 30 34 30 41 03 39 46",
     "06 30 30 37 30 30 30 03 32 41"),
    ("m100_off", 3, 0x0464, 1, "02 30 30 37 31 30 34 36 34 03 39 39",
     "06 30 30 37 31 30 30 03 32 42"),
]
requests = b""
for name, command, address, length, request, reply in VIGOR:
    prefix = bytes([0, command]) + word(address) + bytes([length - 1])
    write("fuzz_vigor_reply", name, prefix + chunks(hx(reply)))
    write("fuzz_vigor_reply", name + "_one_byte_reads", prefix + chunks(hx(reply), 1))
    requests += hx(request)
# The slave side reads the same stream: every request of the spec, one after another.
write("fuzz_vigor_reply", "all_requests", bytes(5) + chunks(requests))

# ----- Modbus (Application Protocol V1.1b3, 6.1-6.12 examples; serial line V1.02 6.2.2) -----
def crc16(data):
    crc = 0xFFFF
    for b in data:
        crc ^= b
        for _ in range(8):
            crc = (crc >> 1) ^ 0xA001 if crc & 1 else crc >> 1
    return crc


def rtu(unit, pdu):
    frame = bytes([unit]) + pdu
    crc = crc16(frame)
    return frame + bytes([crc & 0xFF, crc >> 8])


def tcp(transaction, unit, pdu):
    return word(transaction) + word(0) + word(len(pdu) + 1) + bytes([unit]) + pdu


FUNCTIONS = [0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x0F, 0x10]
# name, function, address, count, 06 value, request PDU, response PDU
MODBUS = [
    ("f01", 0x01, 0x13, 19, None, "01 00 13 00 13", "01 03 CD 6B 05"),
    ("f02", 0x02, 0xC4, 22, None, "02 00 C4 00 16", "02 03 AC DB 35"),
    ("f03", 0x03, 0x6B, 3, None, "03 00 6B 00 03", "03 06 02 2B 00 00 00 64"),
    ("f04", 0x04, 0x08, 1, None, "04 00 08 00 01", "04 02 00 0A"),
    ("f05", 0x05, 0xAC, 1, None, "05 00 AC FF 00", "05 00 AC FF 00"),
    ("f06", 0x06, 0x01, 1, 0x0003, "06 00 01 00 03", "06 00 01 00 03"),
    ("f0f", 0x0F, 0x13, 10, None, "0F 00 13 00 0A 02 CD 01", "0F 00 13 00 0A"),
    ("f10", 0x10, 0x01, 2, None, "10 00 01 00 02 04 00 0A 01 02", "10 00 01 00 02"),
]
unit = 0x11
for name, function, address, count, value, request, response in MODBUS:
    for framing, frame in ((0, rtu(unit, hx(response))), (1, tcp(1, unit, hx(response)))):
        # The harness writes 1 + count % 123 registers for 10h: count 1 gives the example's 2.
        count_word = 0 if function == 0x10 else count - 1
        prefix = bytes([framing, FUNCTIONS.index(function)]) + word(address) + word(count_word)
        if function == 0x06:
            prefix += word(value)
        prefix += bytes([unit])
        write("fuzz_modbus_reply", f"{name}_{'tcp' if framing else 'rtu'}", prefix + chunks(frame))
    # The slave reads requests; after each chunk one byte says whether silence() follows.
    stream = rtu(unit, hx(request))
    write("fuzz_modbus_reply", f"{name}_request_rtu",
          bytes([0, 2]) + word(0) + word(0) + bytes([unit]) +
          bytes([len(stream) - 1 if len(stream) <= 16 else 15]) + stream[:16] + b"\x00" +
          (bytes([len(stream) - 17]) + stream[16:] + b"\x00" if len(stream) > 16 else b""))
# The serial line spec's CRC example, 6.2.2: read 3 registers from 6Bh of unit 11h.
write("fuzz_modbus_reply", "serial_line_example",
      bytes([0, 2]) + word(0x6B) + word(2) + bytes([0x11]) + chunks(hx("11 03 00 6B 00 03 76 87")))


# ----- Omron Host Link C-mode (Omron CPM1/SRM1 programming manual W353: command examples) -----
def fcs(text):
    value = 0
    for c in text.encode():
        value ^= c
    return f"{value:02X}"


def hl(text):
    return (text + fcs(text) + "*\r").encode()


# prefix per command (fuzz_hostlink_reply.cpp): unit, command (0 read, 1 write, 2 MS, 3 SC,
# 4 force, 5 KC, 6 MM), then the command's own bytes
HOSTLINK = [
    ("rd_dm0", bytes([0, 0, 2]) + word(0) + word(1), hl("@00RD00ABCD")),
    ("rr_ir0", bytes([0, 0, 0]) + word(0) + word(2), hl("@00RR0012340000")),
    ("rc_tim0", bytes([0, 0, 3]) + word(0) + word(2), hl("@00RC0001000250")),
    ("rg_tim0", bytes([0, 0, 4]) + word(0) + word(3), hl("@00RG00101")),
    ("wd_dm100", bytes([0, 1, 2]) + word(100) + bytes([1]), hl("@00WD00")),
    ("ms", bytes([0, 2]), hl("@00MS000300")),
    ("sc_monitor", bytes([0, 3]), hl("@00SC00")),
    ("ks_010_00", bytes([0, 4, 1]) + word(10) + bytes([0]), hl("@00KS00")),
    ("kc", bytes([0, 5]), hl("@00KC00")),
    ("mm", bytes([0, 6]), hl("@00MM0012")),
    ("wd_refused_in_run", bytes([0, 1, 2]) + word(100) + bytes([1]), hl("@00WD01")),
]
for name, prefix, reply in HOSTLINK:
    write("fuzz_hostlink_reply", name, prefix + chunks(reply))
# A reply of 100 words in four parts (30 + 31 + 31 + 8), as the PLC splits it.
text = "".join(f"{i * 257 & 0xFFFF:04X}" for i in range(100))
content = "@05RD00" + text
parts, pos, room = [], 0, 127
while len(content) - pos > room:
    end = pos + room
    end -= (end - 7) % 4
    parts.append((content[pos:end] + fcs(content[pos:end]) + "\r").encode())
    pos, room = end, 124
parts.append((content[pos:] + fcs(content[pos:]) + "*\r").encode())
write("fuzz_hostlink_reply", "rd_100_words_split", bytes([5, 0, 2]) + word(0) + word(100) +
      chunks(b"".join(parts)))
# The slave side: every command example above, one after another.
commands = [b"@00RD0000000157*\r", b"@00WD0100123456*\r", b"@00RR0000000242*\r",
            b"@00WR001000FF44*\r", b"@00RC0000000253*\r", b"@00MS5E*\r", b"@00SC0050*\r",
            b"@00SC0252*\r", b"@00SC0353*\r", b"@00MM40*\r", b"@00KSCIO 0010003C*\r"]
write("fuzz_hostlink_reply", "all_commands", bytes([0, 2]) + chunks(b"".join(commands)))


# ----- The slaves' request side (fuzz_*_slave.cpp): the peer's bytes only, behind the bytes
# that pick the slave (station; Modbus: the map, 0 Vigor CP2 / 1 PL110, and 1 + b % 247 as
# the station; Host Link: unit, mode 0 PROGRAM / 1 MONITOR / 2 RUN).
def chunks_quiet(stream, size=16):
    """Chunks as fuzz_modbus_rtu_slave reads them: each followed by the byte that says whether
    the line goes quiet (0: silence(), the end of an RTU frame; 1: more follows)."""
    out = b""
    for i in range(0, len(stream), size):
        piece = stream[i:i + size]
        last = i + size >= len(stream)
        out += bytes([len(piece) - 1]) + piece + bytes([0 if last else 1])
    return out


for name, command, address, length, request, reply in VIGOR:
    write("fuzz_vigor_slave", name, bytes([0]) + chunks(hx(request)))
    write("fuzz_vigor_slave", name + "_one_byte_reads", bytes([0]) + chunks(hx(request), 1))
write("fuzz_vigor_slave", "all_requests", bytes([0]) + chunks(requests))
# Noise before a request, and a request for station 5 on a line shared with station 0's.
write("fuzz_vigor_slave", "noise_then_read_m8",
      bytes([0]) + chunks(b"\xff\x06garbage" + hx(VIGOR[0][4])))

modbus_requests = b""
for name, function, address, count, value, request, response in MODBUS:
    frame = rtu(unit, hx(request))
    modbus_requests += frame
    # The Vigor CP2 map (0) and the PL110's (1), station 11h (1 + 16).
    for which in (0, 1):
        write("fuzz_modbus_rtu_slave", f"{name}_map{which}",
              bytes([which, 16]) + chunks_quiet(frame))
        write("fuzz_modbus_tcp_slave", f"{name}_map{which}",
              bytes([which, 16]) + chunks(tcp(1, unit, hx(request))))
write("fuzz_modbus_rtu_slave", "all_requests_pl110", bytes([1, 16]) + chunks_quiet(modbus_requests))
# What mbpoll asks a PL110 first: words 0..5 of unit 1; then function 04 and a broadcast write.
pl110 = [rtu(1, hx("03 00 00 00 06")), rtu(1, hx("04 00 00 00 06")),
         rtu(0, hx("06 07 D0 01 41")), rtu(0xFF, hx("01 06 40 00 10"))]
write("fuzz_modbus_rtu_slave", "pl110_words_0_to_5",
      bytes([1, 0]) + b"".join(chunks_quiet(f) for f in pl110))
write("fuzz_modbus_tcp_slave", "pl110_words_0_to_5",
      bytes([1, 0]) + chunks(b"".join(tcp(i + 1, 1, f[1:-2]) for i, f in enumerate(pl110))))
write("fuzz_modbus_tcp_slave", "all_requests_vigor",
      bytes([0, 16]) + chunks(b"".join(tcp(i + 1, unit, hx(m[5])) for i, m in enumerate(MODBUS))))

for i, command in enumerate(commands):
    write("fuzz_hostlink_slave", f"command_{i:02d}_monitor", bytes([0, 1]) + chunks(command))
write("fuzz_hostlink_slave", "all_commands_monitor", bytes([0, 1]) + chunks(b"".join(commands)))
write("fuzz_hostlink_slave", "all_commands_run", bytes([0, 2]) + chunks(b"".join(commands)))
write("fuzz_hostlink_slave", "all_commands_program", bytes([0, 0]) + chunks(b"".join(commands)))
# A read of 100 words answered in four parts, each asked for with a CR; a write of 40 words
# sent in two parts, each part's CR answered by the slave.
rd100 = hl("@05RD00000100")
write("fuzz_hostlink_slave", "rd_100_words_in_parts",
      bytes([5, 1]) + chunks(rd100 + b"\r\r\r"))
wd_text = "@05WD0000" + "".join(f"{i:04X}" for i in range(40))
first, rest = wd_text[:127], wd_text[127:]
write("fuzz_hostlink_slave", "wd_40_words_in_parts",
      bytes([5, 1]) + chunks((first + fcs(first) + "\r").encode() + (rest + fcs(rest) + "*\r").encode()))
