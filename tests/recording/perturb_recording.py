#!/usr/bin/env python3
"""Flips one bit of a recording's first recorded impulse and makes its checksum right.

    perturb_recording.py IN OUT

Walks the recording format as docs/user-guide.md ("Recordings") lays it out, independently of
the library's reader: the 32-byte header, the flags, the snapshot, then records of a u8 call
code, a u32 size and the arguments. The first apply_impulse record (its code given by its place
in the call list, read from src/tamias2d/recording/recorded_calls.hpp) has bit 24 of its
impulse's x component flipped (the arguments: the body's index and generation, then impulse.x);
the checksum, FNV-1a 64 of the header's first 24 bytes and the payload, is written again.
Exit status: 0 when a record was changed, 1 when the recording holds no impulse.
"""
import re
import struct
import sys
from pathlib import Path


def fnv1a(data, h=0xCBF29CE484222325):
    for b in data:
        h = ((h ^ b) * 0x100000001B3) & 0xFFFFFFFFFFFFFFFF
    return h


def main(argv):
    if len(argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    calls = (Path(__file__).resolve().parents[2] / "src/tamias2d/recording/recorded_calls.hpp").read_text()
    codes = re.findall(r"^\s*X\((\w+),", calls, re.M)
    impulse = codes.index("apply_impulse")
    b = bytearray(Path(argv[0]).read_bytes())
    at = 32 + 4
    (snapshot,) = struct.unpack_from("<Q", b, at)
    at += 8 + snapshot
    while at < len(b):
        code, size = b[at], struct.unpack_from("<I", b, at + 1)[0]
        if code == impulse:
            b[at + 5 + 8 + 3] ^= 1
            struct.pack_into("<Q", b, 24, fnv1a(b[32:], fnv1a(b[:24])))
            Path(argv[1]).write_bytes(b)
            return 0
        at += 5 + size
    print("perturb_recording: no apply_impulse record", file=sys.stderr)
    return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
