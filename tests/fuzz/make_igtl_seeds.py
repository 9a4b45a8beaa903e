#!/usr/bin/env python3
"""Writes the OpenIGTLink seed corpus of the `igtl` fuzz target (tests/fuzz/corpus/igtl/).

Each seed starts with one byte that the target uses to pick a read size, then version-1
messages (58-byte big-endian header, CRC-64 ECMA-182 of the body) as a tracker would send:
TRANSFORM, POSITION, TDATA and SENSOR, plus a stream with garbage between messages.
Run it from the repository root; it overwrites the seeds it makes.
"""
import pathlib
import struct

POLY = 0x42F0E1EBA9EA3693


def crc64(data: bytes) -> int:
    crc = 0
    for byte in data:
        crc ^= byte << 56
        for _ in range(8):
            crc = ((crc << 1) ^ POLY) if crc & (1 << 63) else (crc << 1)
            crc &= (1 << 64) - 1
    return crc


def message(kind: str, device: str, body: bytes, stamp: int = 0) -> bytes:
    header = struct.pack(">H12s20sQQQ", 1, kind.encode(), device.encode(), stamp, len(body), crc64(body))
    return header + body


def transform(tx: float, ty: float, tz: float) -> bytes:
    # rotation columns (identity) then translation
    return struct.pack(">12f", 1, 0, 0, 0, 1, 0, 0, 0, 1, tx, ty, tz)


def main() -> None:
    out = pathlib.Path("tests/fuzz/corpus/igtl")
    out.mkdir(parents=True, exist_ok=True)
    left = message("TRANSFORM", "LeftForceps", transform(1.5, -2.0, 30.0), stamp=(5 << 32))
    right = message("TRANSFORM", "RightForceps", transform(-1.0, 0.5, 31.0))
    position = message("POSITION", "Stylus", struct.pack(">7f", 10, 20, 30, 0, 0, 0.7071068, 0.7071068))
    element = struct.pack(">20sBB", b"Needle", 1, 0) + transform(0.1, 0.2, 0.3)
    tdata = message("TDATA", "Tracker", element + struct.pack(">20sBB", b"Probe", 1, 0) + transform(4, 5, 6))
    sensor = message("SENSOR", "LeftClosure", struct.pack(">BBQd", 1, 0, 0, 0.42))
    seeds = {
        "transform.bin": b"\x07" + left + right,
        "position.bin": b"\x0d" + position,
        "tdata.bin": b"\x01" + tdata,
        "sensor.bin": b"\x20" + sensor + left,
        "garbage_between.bin": b"\x03" + left + b"\xde\xad\xbe\xef" * 5 + right,
        "truncated.bin": b"\x05" + left + right[:40],
    }
    for name, data in seeds.items():
        (out / name).write_bytes(data)


if __name__ == "__main__":
    main()
