#!/usr/bin/env python3
"""Write the seed inputs of fuzz/corpus/batch/ (the `batch` target, fuzz/src/batch.rs), named by
their SHA-1 like libFuzzer's own entries: for every entry of the table, a batch of the special
bit patterns (NaN, Inf, ±0, subnormals, extremes, codes with high bits set) of an odd length,
so the vector loops' tails run. Byte 0 picks the entry; then (for the generic octahedral and
roughness entries) one parameter; then the length byte and the little-endian values. Rerun
after adding an entry: python3 fuzz/seed_batch.py."""
import hashlib, os, struct

HERE = os.path.dirname(os.path.abspath(__file__))
ENTRIES = 87  # len(BATCH)
GENERIC = {33, 34, 35}  # bits byte first
ROUGHNESS = {36, 37}  # max_power f32 first
FLAGGED = {56}  # a u32 dynamic-object flag first
VOUCHED = set(range(74, 82))  # _vouched encoders: also a batch inside their contract
WORDS = [0x7FC00000, 0xFFC00001, 0x7F800001, 0x7F800000, 0xFF800000, 0, 0x80000000, 1, 0x80000001,
         0x007FFFFF, 0x00800000, 0x3F800000, 0xBF800000, 0x7F7FFFFF, 0xFF7FFFFF, 0x3F000001,
         0x00FFFFFF, 0x01000000, 0xFFFFFFFF, 0xFF123456, 0x0000FFFF, 0x00007FFF, 0x3F3504F3]

def write(data):
    d = os.path.join(HERE, "corpus", "batch")
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, hashlib.sha1(data).hexdigest()), "wb") as fh:
        fh.write(data)

payload = b"".join(struct.pack("<I", w) for w in WORDS * 12)
# Vectors inside the vouched contract (finite, no subnormals, largest at most 2^124, and for
# hemioct any negative z): directions at scales from 2^-126 to 2^124, axes, zeros beside.
INSIDE = [0.6, -0.8, 0.0, 2.0**-126, 1.0, -2.0**-126, 2.0**124, -0.25, 2.0**124, 1e-3, 2e-3,
          -3.4e38, -0.0, 0.0, 5.0, 0.3, 0.3, -0.9, 1e30, -7e29, 2e29, 1.2e-37, 3e-38, -5e-38]
vouched = b"".join(struct.pack("<f", x) for x in INSIDE * 12)
for e in range(ENTRIES):
    params = [b""]
    if e in GENERIC:
        params = [bytes([b - 1]) for b in (8, 12, 16, 1, 13)]
    if e in ROUGHNESS:
        params = [struct.pack("<f", m) for m in (8192.0, 1000.0, 2.0, float("inf"), 1.0)] + [struct.pack("<I", 0x7FC00000)]
    if e in FLAGGED:
        params = [struct.pack("<I", flag) for flag in (0, 1, 0xFFFFFFFF)]
    for p in params:
        for n in (0, 20, 62):  # lengths 1, 21, 63
            write(bytes([e]) + p + bytes([n]) + payload)
            if e in VOUCHED:
                write(bytes([e]) + p + bytes([n]) + vouched)
