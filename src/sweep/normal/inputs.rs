//! The inputs the normal sweeps run over: Fibonacci directions, an adversarial direction set,
//! a stratified sample of a 32-bit code space, and the bad encoder inputs with their answers.

use crate::normal::oct;

/// `n` spherical-Fibonacci directions (uniform on the sphere): point `i` at
/// `z = 1 − (2i + 1)/n`, azimuth `i·π(3 − √5)`, computed in f64 and rounded to f32.
pub fn fibonacci_directions(n: u32) -> Vec<[f32; 3]> {
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    (0..n)
        .map(|i| {
            let z = 1.0 - (2.0 * f64::from(i) + 1.0) / f64::from(n);
            let r = (1.0 - z * z).max(0.0).sqrt();
            let (s, c) = (golden * f64::from(i)).sin_cos();
            [(r * c) as f32, (r * s) as f32, z as f32]
        })
        .collect()
}

/// Adversarial unit directions: the six axes with every sign of zero, the octahedron's folds
/// (`|x| + |y| = 1` at `z = ±0` and `z = ±tiny`), the poles and the equator approached in ULP
/// steps, the body diagonals, and points just either side of the oct code cells' edges.
pub fn adversarial_directions() -> Vec<[f32; 3]> {
    let mut v = Vec::new();
    let zs = [0.0f32, -0.0];
    for a in 0..3 {
        for s in [1.0f32, -1.0] {
            for z1 in zs {
                for z2 in zs {
                    let mut d = [z1, z2, z1];
                    d[(a + 1) % 3] = z2;
                    d[a] = s;
                    v.push(d);
                }
            }
        }
    }
    let tiny = [0.0f32, -0.0, 1e-7, -1e-7, 1e-30, -1e-30, 1e-3, -1e-3];
    // Folds and equator: the square |x| + |y| = 1 (and circle) in the plane z ~ 0.
    for i in 0..4096 {
        let t = f64::from(i) / 4096.0 * std::f64::consts::TAU;
        let (s, c) = t.sin_cos();
        let l1 = s.abs() + c.abs();
        for &z in &tiny {
            v.push([(c / l1) as f32, (s / l1) as f32, z]);
            v.push([c as f32, s as f32, z]);
        }
    }
    // Poles approached in ULP-sized and code-sized steps.
    for k in 0..2048 {
        let e = 2f64.powi(-(k % 40)) * (1.0 + f64::from(k / 40) / 64.0);
        for (sx, sy, sz) in [
            (1.0, 1.0, 1.0),
            (-1.0, 1.0, 1.0),
            (1.0, -1.0, -1.0),
            (-1.0, -1.0, -1.0),
        ] {
            let d = [sx * e, sy * e * 0.5, sz];
            if let Some(u) = crate::normal::exact::unit(d) {
                v.push(u.map(|x| x as f32));
            }
        }
    }
    for d in [
        [1.0f32, 1.0, 1.0],
        [-1.0, 1.0, -1.0],
        [1.0, -1.0, -1.0],
        [-1.0, -1.0, 1.0],
    ] {
        v.push(d.map(|x| x / 3f32.sqrt()));
    }
    // Cell edges of every oct size: continuous coordinate k + 1/2 (the rounding encoder's tie)
    // and k + 0 (a code exactly), on both hemispheres, through a seeded walk over the square.
    let mut seed = 0x9e37_79b9_7f4a_7c15u64;
    for bits in [8u32, 12, 16] {
        let m = f64::from(oct::max_code(bits));
        for _ in 0..16384 {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            let u = (seed >> 40) as f64 / 2f64.powi(24) * m;
            let w = (seed & 0xff_ffff) as f64 / 2f64.powi(24) * m;
            for (cu, cw) in [(u.floor() + 0.5, w.floor() + 0.5), (u.floor(), w)] {
                let p = [2.0 * cu / m - 1.0, 2.0 * cw / m - 1.0];
                let z = 1.0 - p[0].abs() - p[1].abs();
                let d = if seed & 1 == 0 || z < 0.0 {
                    [p[0], p[1], z]
                } else {
                    // The same point folded to the lower hemisphere.
                    let s = |x: f64| if x >= 0.0 { 1.0 } else { -1.0 };
                    [
                        (1.0 - p[1].abs()) * s(p[0]),
                        (1.0 - p[0].abs()) * s(p[1]),
                        -z,
                    ]
                };
                if let Some(u) = crate::normal::exact::unit(d) {
                    v.push(u.map(|x| x as f32));
                }
            }
        }
    }
    v
}

/// Directions near a tie of two candidate codes of the precise encoders, where the score
/// comparison is decided by the last bits of the scores: `cells` seeded cells `(u, v)` of a
/// code with `per_axis_bits` bits per axis and largest code `m` (whose codes' exact directions
/// `decode` gives), for each a pair of the cell's four corners, a point of the great circle
/// equidistant from the pair's two directions (at a seeded offset along it of up to 1.5/m, about
/// a code spacing, from the pair's midpoint), rounded to f32, and that point moved by −1, 0, +1
/// ULP in x and in y (9 inputs per cell). A score computed with one rounding more or less than
/// the shipped one flips some of these choices (a float `|D|²` at 16 bits: 20 of 2.4 M in
/// `tests/normal_oct.rs`), so they test that the WGSL and its twin compute the same scores,
/// not just similar ones.
pub fn near_tie_directions(
    per_axis_bits: u32,
    m: u32,
    decode: fn(u32) -> [f64; 3],
    cells: u32,
    seed: u64,
) -> Vec<[f32; 3]> {
    use crate::normal::exact::unit;
    let mut rng = crate::sweep::SplitMix(seed);
    let mut next = || rng.next_u64();
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    let mut out = Vec::with_capacity(cells as usize * 9);
    for _ in 0..cells {
        let r = next();
        let (u, v) = ((r % u64::from(m)) as u32, ((r >> 32) % u64::from(m)) as u32);
        let k = (next() % 4) as u32;
        let j = (k + 1 + (next() % 3) as u32) % 4;
        let corner = |i: u32| decode((u + (i & 1)) | ((v + (i >> 1)) << per_axis_bits));
        let (a, b) = (corner(k), corner(j));
        let (Some(mid), Some(along)) = (
            unit(std::array::from_fn(|i| a[i] + b[i])),
            unit(cross(a, b)),
        ) else {
            continue;
        };
        // Within ±1.5 code spacings (2/m on the square) of the midpoint.
        let t = ((next() >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 3.0 / f64::from(m);
        let Some(p) = unit(std::array::from_fn(|i| mid[i] + t * along[i])) else {
            continue;
        };
        let f = p.map(|x| x as f32);
        // A neighbouring float (toward zero for −1 on either sign); zero stays (its −1 is NaN).
        let step = |x: f32, d: i32| {
            if x == 0.0 {
                x
            } else {
                f32::from_bits(x.to_bits().wrapping_add_signed(d))
            }
        };
        for dx in -1..=1 {
            for dy in -1..=1 {
                out.push([step(f[0], dx), step(f[1], dy), f[2]]);
            }
        }
    }
    out
}

/// The documented stratified sample of a 32-bit code space: one code from each of the 2^26
/// blocks of 64 consecutive codes (offset in the block from a hash of the block number), plus
/// every code with a coordinate (either 16-bit half) at 0, 1, 2^15 − 1, 2^15, 2^16 − 2 or
/// 2^16 − 1 — the folds, the axes and the square's edges.
pub fn stratified_codes32() -> Vec<u32> {
    let mut v: Vec<u32> = (0u32..1 << 26)
        .map(|b| (b << 6) | (b.wrapping_mul(0x9e37_79b9) >> 26))
        .collect();
    for h in [0u32, 1, 0x7fff, 0x8000, 0xfffe, 0xffff] {
        for o in 0u32..1 << 16 {
            v.push(h | (o << 16));
            v.push(o | (h << 16));
        }
    }
    v
}

/// Bad inputs for the encoders, each with the well-formed input it must encode exactly like
/// (the documented answer): NaN anywhere, zero and all-subnormal vectors → `+z`; infinities →
/// the vector of their signs; subnormal components → zero; any finite length → the same
/// direction at unit length (huge, tiny and plain non-unit vectors).
pub fn bad_inputs() -> Vec<([f32; 3], [f32; 3])> {
    let (nan, inf, sub) = (f32::NAN, f32::INFINITY, f32::from_bits(0x0040_0000));
    let qnan_neg = f32::from_bits(0xffc0_0001);
    let z = [0.0, 0.0, 1.0];
    let r = std::f32::consts::FRAC_1_SQRT_2;
    vec![
        ([0.0, 0.0, 0.0], z),
        ([-0.0, -0.0, -0.0], z),
        ([nan, 0.0, 1.0], z),
        ([0.5, qnan_neg, 0.5], z),
        ([1.0, 1.0, nan], z),
        ([nan, inf, 1.0], z),
        ([sub, -sub, sub], z),
        ([f32::from_bits(1), 0.0, 0.0], z),
        ([inf, 1.0, 0.0], [1.0, 0.0, 0.0]),
        ([-inf, 5.0, 3.0], [-1.0, 0.0, 0.0]),
        ([0.0, 0.0, -inf], [0.0, 0.0, -1.0]),
        ([inf, -inf, 7.0], [r, -r, 0.0]),
        ([sub, 1.0, -sub], [0.0, 1.0, 0.0]),
        ([sub, -0.6, 0.8], [0.0, -0.6, 0.8]),
        ([2.0, 0.0, 0.0], [1.0, 0.0, 0.0]),
        ([3.0e38, 3.0e38, 0.0], [r, r, 0.0]),
        (
            [f32::MAX, -f32::MAX, f32::MAX],
            [1.0, -1.0, 1.0].map(|x: f32| x / 3f32.sqrt()),
        ),
        ([1.0e-37, 0.0, -1.0e-37], [r, 0.0, -r]),
        ([0.0, -4.0, 0.0], [0.0, -1.0, 0.0]),
        ([-0.0, 0.0, -2.5], [-0.0, 0.0, -1.0]),
    ]
}
