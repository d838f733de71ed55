#!/usr/bin/env python3
"""Write the hand-picked seed inputs of fuzz/corpus/ (the adversarial cases of the bad-input
table), named by their SHA-1 like libFuzzer's own corpus entries. Byte 0 picks the table entry
(fuzz/src/lib.rs), the rest is little-endian u32 / f32 bit patterns. Rerun after adding an entry:
python3 fuzz/seed_corpus.py. Inputs that once failed (found by fuzzing) are committed beside
these, under their own SHA-1 names."""
import hashlib, os, struct

HERE = os.path.dirname(os.path.abspath(__file__))
MAX24 = 0xFFFFFF
NAN, NNAN, SNAN, INF, NINF = 0x7FC00000, 0xFFC00000, 0x7F800001, 0x7F800000, 0xFF800000
PZ, NZ, SUB, NSUB, SUBMAX = 0, 0x80000000, 1, 0x80000001, 0x007FFFFF
def f(x): return struct.unpack("<I", struct.pack("<f", x))[0]
FLOATS = [NAN, NNAN, SNAN, INF, NINF, PZ, NZ, SUB, NSUB, SUBMAX, f(1.0), f(0.5), f(-1.0),
          f(2.0), 0x3F800001, 0x7F7FFFFF, 0xFF7FFFFF, 0x00800000]
CODES = [0, 1, 2, 1 << 23, MAX24 - 1, MAX24, MAX24 + 1, 0x80000000, 0xFFFFFFFF, 0xFF123456]

def words(*ws): return b"".join(struct.pack("<I", w) for w in ws)

def write(target, entry, payload):
    data = bytes([entry]) + payload
    d = os.path.join(HERE, "corpus", target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, hashlib.sha1(data).hexdigest()), "wb") as fh:
        fh.write(data)

# decoders: 0 depth24_from_rgb8, 1 depth24_from_packed, 2 hyperbolic_depth_from_depth24, 3 unpack4x8unorm
for v in FLOATS:
    write("decoders", 0, words(v, v, v))
write("decoders", 0, words(NNAN, f(1.0), SNAN))
write("decoders", 0, words(f(-1.0), f(2.0), f(1.5)))
write("decoders", 0, words(0x7F7FFFFF, 0xFF7FFFFF, f(0.5)))
for c in CODES:
    for e in (1, 2, 3):
        write("decoders", e, words(c))
# encoders: 0 pack_depth24, 1 exact::nearest_code, 2 exact::hyperbolic_depth
for c in CODES:
    write("encoders", 0, words(c))
    write("encoders", 2, words(c))
for v in FLOATS:
    write("encoders", 1, words(v))
# differential: 0 hyperbolic vs exact, 1 rgb8 within ±0.49/255 (code, then three offset bytes)
for c in CODES:
    write("differential", 0, words(c))
    for offs in (b"\x00\x00\x00", b"\x7f\x7f\x7f", b"\x80\x80\x80", b"\x7f\x80\x7f"):
        write("differential", 1, words(c) + offs)

# differential (appended entries): 2 view_z_from_depth24 vs exact (code, near, far, convention byte),
# 3 view_z_from_depth / _reversed_ vs exact (depth, near, far, convention byte)
PROJ = [(f(1e-4), f(1e5)), (f(0.1), INF), (f(10.0), f(100.0)), (f(1.0), f(1e9)), (SUBMAX, f(1.0)),
        (NAN, f(1.0)), (f(1e-4), f(1e36)), (f(1e32), INF)]
for (n, fa) in PROJ:
    for c in (0, 1, MAX24 - 1, MAX24, 0xFFFFFFFF):
        write("differential", 2, words(c, n, fa) + bytes([0]))
    for z in (PZ, SUB, f(0.5), 0x3F7FFFFF, f(1.0), INF, NINF):
        for conv in (0, 1):
            write("differential", 3, words(z, n, fa) + bytes([conv]))
# builders: 0 Projection::new (near, far, convention byte), 1 Scene (choice byte, w, h, samples)
for (n, fa) in PROJ + [(PZ, f(1.0)), (f(1.0), f(1.0)), (f(2.0), f(1.0)), (INF, INF), (f(1.0), NAN)]:
    for conv in (0, 1):
        write("builders", 0, words(n, fa) + bytes([conv]))
for b in range(0, 128, 5):
    write("builders", 1, bytes([b]) + words(0xFFFFFFFF, 0x12345678) + bytes([7]))
