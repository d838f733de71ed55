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

# decoders (appended entries, in fuzz/src/decoders.rs order): 4 decode_normal_xyz8, 5 _xyz8_unorm,
# 6 decode_normal_xy_fp16, 7 _xy_fp16_unorm, 8 decode_normal_oct16, 9 _oct16_unorm,
# 10 decode_normal_oct24, 11 _oct24_unorm, 12 decode_normal_oct32, 13 _oct32_unorm,
# 14 oct::decode (bits byte, code), 15 decode_normal_hemioct24, 16 _hemioct24_unorm,
# 17 decode_log_roughness (code, max_power), 18 the roughness texel extractors
NCODES = CODES + [0x7F7F, 0x8080, 0x7FF7FF, 0x7FFF7FFF, 0x3C003C00, 0x7E007E00, 0xFC00FC00]
for c in NCODES:
    for e in (4, 6, 8, 10, 12, 15, 18):
        write("decoders", e, words(c))
    for bits in (0, 7, 11, 15):
        write("decoders", 14, bytes([bits]) + words(c))
CHANNELS = [(NAN, NAN, NAN, NAN), (INF, NINF, f(0.5), SUB), (f(0.49 / 255), f(254.51 / 255), f(1.0), PZ),
            (f(2.0), f(-1.0), NZ, SNAN)]
for ch in CHANNELS:
    for e in (5, 7, 9, 11, 13, 16):
        write("decoders", e, words(*ch))
for c in (0, 200, 255, 256, 0xFFFFFFFF):
    for m in (f(8192.0), f(1000.0), NAN, NINF, INF, SUB, f(1.0), 0x7F7FFFFF):
        write("decoders", 17, words(c, m))
# encoders (appended): 3 encode_normal_xyz8, 4 _unorm, 5 xy_fp16, 6 _unorm, 7 oct16, 8 oct16_fast,
# 9 oct16_unorm, 10 oct24, 11 oct24_fast, 12 oct24_unorm, 13 oct32, 14 oct32_fast, 15 oct32_unorm,
# 16 oct::encode_precise/encode_round (bits byte, vector), 17 hemioct24, 18 hemioct24_fast,
# 19 hemioct24_unorm, 20 normal::sanitize, 21 encode_log_roughness (power, power, max_power),
# 22 pack_normal_xyz8_log_roughness (normal, code)
VECS = [(NAN, PZ, f(1.0)), (PZ, PZ, PZ), (NZ, NZ, NZ), (SUB, NSUB, SUBMAX), (INF, f(1.0), PZ),
        (INF, NINF, f(5.0)), (0x7F7FFFFF, 0x7F7FFFFF, 0xFF7FFFFF), (f(0.6), f(-0.8), NZ),
        (f(1.0), f(1.0), f(-1e-30)), (f(3.0), SUB, f(-4.0)), (f(0.0), f(-1.0), f(1e-7))]
for v in VECS:
    for e in list(range(3, 16)) + [17, 18, 19, 20]:
        write("encoders", e, words(*v))
    for bits in (0, 7, 11, 15):
        write("encoders", 16, bytes([bits]) + words(*v))
for (p, m) in [(NAN, f(8192.0)), (INF, f(1000.0)), (f(-100.0), f(8192.0)), (SUB, f(8192.0)),
               (f(1e9), f(8192.0)), (0x7F7FFFFF, INF), (f(100.0), NAN), (f(100.0), f(0.5)),
               (f(8192.0), f(8192.0)), (f(1.0), f(8192.0))]:
    write("encoders", 21, words(p, f(2.0), m))
for (n, c) in [(0xFF123456, 0x3E7), (0x80, 0xFFFFFFFF), (0, 0), (0xFFFFFFFF, 255)]:
    write("encoders", 22, words(n, c))
# decoders 25: the roughness_ggx decoders (code, channel); encoders 30: the roughness_ggx
# encoders (r, s, dynamic flag)
for c in (0, 127, 128, 255, 256, 0xFFFFFFFF):
    for ch in (NAN, INF, NINF, SUB, f(0.49 / 255), f(2.0), f(-1.0), f(0.5)):
        write("decoders", 25, words(c, ch))
for r in FLOATS + [f(1.0 / 64.0), f(0.01), f(1.0 / 510.0), f(0.089), f(0.02)]:
    for flag in (0, 1, 0xFFFFFFFF):
        write("encoders", 30, words(r, f(1.0), flag))
# lighting (fuzz/src/lighting.rs order): 0 lpp_direction, 1 lpp_pow_cosine, 2 point attenuation,
# 3 spot attenuation, 4 lpp_cosines, 5 blinn-phong light, 6 phong light, 7 point light, 8 spot
# light, 9 two-buffer specular, 10 reconstruct specular, 11 clamp colour, 12 combine / luminance,
# 13 aggregate accumulate, 14 aggregate direction / position / diffuse, 15 near-corner distance,
# 16 depth-fail tests, 17 window depth / sphere depth bounds (centre, radius, projection, t)
UNIT = (PZ, PZ, f(1.0))
for v in VECS:
    write("lighting", 0, words(*v))
    write("lighting", 11, words(*v))
for (x, y) in [(NAN, f(8.0)), (f(1.5), f(8.0)), (INF, f(8.0)), (NINF, f(8.0)), (PZ, PZ),
               (f(0.5), PZ), (SUB, f(1.0)), (f(0.5), NAN), (f(0.5), INF), (f(0.5), f(-3.0))]:
    write("lighting", 1, words(x, y))
    write("lighting", 2, words(x, y))
    write("lighting", 3, words(x, y, f(0.9)))
for v in VECS[:6]:
    for e in (4, 5, 6, 9):
        write("lighting", e, words(*UNIT, *UNIT, *v, f(1.0), f(1.0), f(1.0), f(1.0), f(8.0)))
        write("lighting", e, words(*v, *UNIT, *UNIT, f(1.0), f(1.0), f(1.0), f(1.0), f(8.0)))
    write("lighting", 7, words(*UNIT, *UNIT, *v, f(1.0), f(1.0), f(1.0), f(2.0), f(8.0)))
    write("lighting", 8, words(*UNIT, *UNIT, *v, f(1.0), f(1.0), f(1.0), f(2.0), PZ, PZ, f(-1.0), f(0.5), f(0.9), f(8.0)))
for light in [(f(1.0), f(1.0), f(1.0), f(0.5)), (PZ, PZ, PZ, f(1.0)), (NAN, f(1.0), f(1.0), f(1.0)),
              (f(65504.0), INF, f(1.0), f(1.0)), (f(1.0), f(1.0), f(1.0), f(9.0)), (SUB, SUB, SUB, SUB)]:
    for m in (f(8.0), NAN, INF, PZ):
        write("lighting", 10, words(*light, m))
        write("lighting", 12, words(f(1.0), f(1.0), f(1.0), f(1.0), f(1.0), f(1.0), *light, m, *UNIT, *UNIT))
for v in VECS[:8]:
    write("lighting", 13, words(PZ, PZ, PZ, PZ, PZ, PZ, PZ, *v, f(1.0), PZ, PZ, PZ, f(1.0), f(1.0), f(1.0), *UNIT))
    write("lighting", 14, words(*v, f(1.0), PZ, PZ, PZ, *UNIT, *UNIT, f(1.0), f(1.0), f(1.0)))
for (n, tx, ty) in [(f(0.1), f(1.0), f(0.75)), (NAN, f(1.0), f(1.0)), (f(-1.0), f(1.0), f(1.0)),
                    (PZ, f(1e30), f(1.0)), (INF, PZ, PZ)]:
    write("lighting", 15, words(n, tx, ty))
for (c, r, rho) in [((PZ, PZ, f(-10.0)), f(1.0), f(0.2)), ((PZ, PZ, f(-1.0)), f(1.0), f(0.2)),
                    ((NAN, PZ, PZ), f(1.0), f(0.2)), ((PZ, PZ, PZ), PZ, PZ), ((f(1e30), PZ, PZ), f(1e30), f(1.0))]:
    write("lighting", 16, words(*c, r, rho, PZ, PZ, f(-2.0), PZ, PZ, f(-1.0), f(5.0), f(0.5)))
for (n, fa) in PROJ:
    for (cz, r) in [(f(10.0), f(1.0)), (f(0.05), f(0.01)), (f(1e9), f(1.0)), (NAN, f(1.0)),
                    (f(5.0), f(-1.0)), (0x7F7FFFFF, 0x7F7FFFFF)]:
        for conv in (0, 1):
            write("lighting", 17, words(cz, r, n, fa) + bytes([conv]) + words(0x80000000))

# decoders (appended): 19 decode_normal_xyz10, 20 _xyz10_unorm, 21 decode_normal_snorm8,
# 22 _snorm8_snorm. encoders (appended): 23 encode_normal_xyz10, 24 _xyz10_unorm,
# 25 encode_normal_snorm8, 26 _snorm8_snorm.
for c in NCODES + [0x3FFFFFFF, 0xC0000000, 0x808080, 0x80, 0x7F7F7F]:
    for e in (19, 21):
        write("decoders", e, words(c))
for ch in CHANNELS + [(NINF, NZ, NSUB, INF), (f(-0.999), f(-1.5), f(126.51 / 127), PZ)]:
    for e in (20, 22):
        write("decoders", e, words(*ch))
for v in VECS:
    for e in (23, 24, 25, 26):
        write("encoders", e, words(*v))
# decoders (appended): 23 decode_normal_oct24_unity, 24 _unity_unorm. encoders (appended):
# 27 encode_normal_oct24_unity, 28 _unity_fast, 29 _unity_unorm.
for c in NCODES + [0x77FFFF, 0x880000]:
    write("decoders", 23, words(c))
for ch in CHANNELS:
    write("decoders", 24, words(*ch))
for v in VECS:
    for e in (27, 28, 29):
        write("encoders", e, words(*v))
# encoders (appended): 31 the vouched octahedral encoders against the robust ones (vector)
for v in VECS + [(f(0.6), f(0.0), f(-0.8)), (NZ, f(1e-38), f(-1.0)), (f(2.0 ** 124), f(1.0), NZ),
                 (f(1e-30), f(1e-30), f(-1e-30))]:
    write("encoders", 31, words(*v))
# decoders (appended): 26 the Substrate word's readers. encoders (appended): 32 the Substrate
# normal and word encoders (vector, roughness, flags).
for c in NCODES + [0x0, 0xFFFFFFFF, 0x3FF, 0x80100000, 0x80000000, 0x801003FC, 0x001FFC00]:
    write("decoders", 26, words(c))
for v in VECS:
    for r, fl in [(f(0.5), 0), (NAN, 7), (f(-0.25), 0xFFFFFFFF), (INF, 1), (f(1.5), 2)]:
        write("encoders", 32, words(*v) + words(r, fl))
# decoders (appended): 27 decode_normal_oct20, 28 _oct20_unorm. encoders (appended): 33
# encode_normal_oct20, 34 _oct20_fast, 35 _oct20_unorm.
for c in NCODES + [0x7FDFF, 0x80200, 0xFFFFF, 0xFFF00000]:
    write("decoders", 27, words(c))
for ch in CHANNELS:
    write("decoders", 28, words(*ch))
for v in VECS:
    for e in (33, 34, 35):
        write("encoders", e, words(*v))
# encoders (appended): 36 encode_normal_xyz8_best, 37 _best_unorm, and lattice directions
# (multiples of one odd vector tie) and the bisector of two neighbouring codes.
for v in VECS + [(f(1.0), f(1.0), f(1.0)), (f(255.0), f(-253.0), f(1.0)), (f(3.0), f(1.0), NZ),
                 (f(0.70710677), f(-0.70710677), f(1e-7))]:
    for e in (36, 37):
        write("encoders", e, words(*v))
# encoders (appended): 38 the vouched hemi-octahedral encoders against the robust ones (vector):
# negative z of every size (clamped; in the contract when finite), the -z half-axis (outside).
for v in VECS + [(f(0.6), f(0.0), f(-0.8)), (NZ, f(1e-38), f(-1.0)), (f(2.0 ** 124), f(1.0), NZ),
                 (f(1e-30), f(1e-30), f(-1e-30)), (f(1e-30), f(0.0), f(-3e38)),
                 (PZ, NZ, f(-1.0)), (f(1.1754944e-38), f(0.0), f(-1024.0))]:
    write("encoders", 38, words(*v))
# decoders (appended): 29 decode_normal_signed_oct, 30 _signed_oct_unorm. encoders (appended):
# 39 encode_normal_signed_oct, 40 _signed_oct_fast, 41 _signed_oct_unorm and z's sign bit
# (the equator's signed zeros, the poles, the rounding ties of (1, -1, 0)).
for c in NCODES + [0x17FDFF, 0x7FDFF, 0x180200, 0x3FF, 0x1003FF, 0xFFFFF, 0x1FFFFF, 0xFFE00000]:
    write("decoders", 29, words(c))
for ch in CHANNELS + [(f(0.5), f(0.5), f(511 / 1023), PZ), (f(0.5), f(0.5), f(512 / 1023), NAN),
                      (f(1.0), PZ, NINF, INF)]:
    write("decoders", 30, words(*ch))
for v in VECS + [(f(0.6), f(0.8), NZ), (f(0.6), f(0.8), SUB), (f(1.0), f(-1.0), f(1e-7)),
                 (f(0.0), f(0.0), f(-1.0)), (f(1.0), f(1.0), f(1.0))]:
    for e in (39, 40, 41):
        write("encoders", e, words(*v))
# encoders (appended): 42 encode_normal_oct24_hdrp, 43 its z sign (HDRP's floor: the issue's
# near-equator normal, signed zeros and subnormal z), 44 the URP and Substrate roughness bytes
# (two r, monotonic check; Substrate's truncation boundaries k/255). decoders (appended): 31 the
# URP and Substrate roughness readers (code, channel).
for v in VECS + [(f(0.97718143), f(0.21240622), f(-0.0001)), (f(0.6), f(0.8), NZ),
                 (f(0.6), f(0.8), NSUB), (f(1.0), f(0.0), f(-1 / 2048)), (PZ, NZ, f(-1.0))]:
    for e in (42, 43):
        write("encoders", e, words(*v))
for a in FLOATS + [f(k / 255) for k in (1, 157, 158, 254)] + [f(0.618034), f(0.3)]:
    write("encoders", 44, words(a, f(0.5)))
for c in CODES:
    for v in FLOATS:
        write("decoders", 31, words(c, v))
