//! Batch throughput of the Rust twins, in bytes of encoded data per second, and the same
//! batches through meshoptimizer's octahedral vertex filter for comparison.
//!
//! ```text
//! cargo bench --bench twins
//! ```
//! "Encoded data" is the stored form: an encoder's output, a decoder's input (4 bytes per
//! depth texel; 4 or 8 bytes per octahedral normal). Every group runs its functions over the
//! same input batch so the rows compare directly.

use criterion::{BatchSize, Criterion, Throughput, criterion_group, criterion_main};
use glam::Vec3;
use prepass::depth24;
use prepass::normal::oct;
use std::hint::black_box;

/// Values per batch: large enough to leave the per-batch overhead negligible, small enough
/// (≤ 1 MiB per array) to stay in the L2 cache, so the figures measure arithmetic, not DRAM.
const N: usize = 1 << 16;

/// Codes spread over the whole 24-bit range (a multiplicative hash of the index).
fn codes() -> Vec<u32> {
    (0..N as u32)
        .map(|k| k.wrapping_mul(0x9e37_79b1) & depth24::DEPTH24_MAX)
        .collect()
}

fn depth24(c: &mut Criterion) {
    let codes = codes();
    let packed: Vec<u32> = codes.iter().map(|&d| depth24::pack_depth24(d)).collect();
    let rgb: Vec<Vec3> = packed
        .iter()
        .map(|&p| {
            let [r, g, b, _] = depth24::unpack4x8unorm(p);
            Vec3::new(r, g, b)
        })
        .collect();
    let mut out_u32 = vec![0u32; N];
    let mut out_f32 = vec![0f32; N];
    let mut g = c.benchmark_group("depth24");
    g.throughput(Throughput::Bytes((N * 4) as u64));
    g.bench_function("pack_depth24 (encode)", |b| {
        b.iter(|| {
            for (o, &d) in out_u32.iter_mut().zip(black_box(&codes)) {
                *o = depth24::pack_depth24(d);
            }
            black_box(&out_u32);
        })
    });
    g.bench_function("depth24_from_packed (decode)", |b| {
        b.iter(|| {
            for (o, &p) in out_u32.iter_mut().zip(black_box(&packed)) {
                *o = depth24::depth24_from_packed(p);
            }
            black_box(&out_u32);
        })
    });
    g.bench_function("depth24_from_rgb8 (decode)", |b| {
        b.iter(|| {
            for (o, &v) in out_u32.iter_mut().zip(black_box(&rgb)) {
                *o = depth24::depth24_from_rgb8(v);
            }
            black_box(&out_u32);
        })
    });
    g.bench_function("hyperbolic_depth_from_depth24", |b| {
        b.iter(|| {
            for (o, &d) in out_f32.iter_mut().zip(black_box(&codes)) {
                *o = depth24::hyperbolic_depth_from_depth24(d);
            }
            black_box(&out_f32);
        })
    });
    g.finish();
}

/// Unit normals spread over the sphere (a spherical Fibonacci lattice), as meshopt's filter
/// takes them: four floats per normal, w = 0.
fn normals() -> Vec<[f32; 4]> {
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    (0..N)
        .map(|i| {
            let z = 1.0 - (2.0 * i as f64 + 1.0) / N as f64;
            let r = (1.0 - z * z).sqrt();
            let phi = golden * i as f64;
            [
                (r * phi.cos()) as f32,
                (r * phi.sin()) as f32,
                z as f32,
                0.0,
            ]
        })
        .collect()
}

/// meshoptimizer's octahedral filter: `bits` per component, stored as 8-bit (stride 4) or
/// 16-bit (stride 8) snorm.
fn meshopt_oct(c: &mut Criterion, bits: i32, stride: usize) {
    let normals = normals();
    let flat: Vec<f32> = normals.iter().flatten().copied().collect();
    let mut encoded = vec![0u8; N * stride];
    // SAFETY: `encoded` holds N·stride bytes and `flat` N·4 floats, as the function requires;
    // stride is 4 or 8 and bits ≤ 16.
    unsafe {
        meshopt::ffi::meshopt_encodeFilterOct(
            encoded.as_mut_ptr().cast(),
            N,
            stride,
            bits,
            flat.as_ptr(),
        );
    }
    let mut g = c.benchmark_group(format!("normal_oct_{bits}bit"));
    // Normals per second: meshopt stores `stride` bytes per normal, prepass 2·bits/8 bytes.
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("meshopt encodeFilterOct", |b| {
        b.iter(|| {
            // SAFETY: as above.
            unsafe {
                meshopt::ffi::meshopt_encodeFilterOct(
                    encoded.as_mut_ptr().cast(),
                    N,
                    stride,
                    bits,
                    black_box(flat.as_ptr()),
                );
            }
            black_box(&encoded);
        })
    });
    g.bench_function("meshopt decodeFilterOct", |b| {
        // The filter decodes in place: each run gets a fresh copy (not timed).
        b.iter_batched_ref(
            || encoded.clone(),
            |buf| {
                // SAFETY: `buf` holds N·stride bytes of this filter's encoding.
                unsafe {
                    meshopt::ffi::meshopt_decodeFilterOct(buf.as_mut_ptr().cast(), N, stride)
                };
                black_box(&buf);
            },
            BatchSize::LargeInput,
        )
    });
    // prepass's octahedral twins on the same batch: 2×8 bits (oct16) beside meshopt's 8-bit
    // filter, 2×16 bits (oct32) beside its 16-bit one. The precise encoder tries 4 codes; the
    // fast one rounds once, as meshopt's does.
    let vecs: Vec<glam::Vec3> = normals
        .iter()
        .map(|n| glam::Vec3::new(n[0], n[1], n[2]))
        .collect();
    type Enc = fn(glam::Vec3) -> u32;
    let (precise, fast, decode): (Enc, Enc, fn(u32) -> glam::Vec3) = if bits == 8 {
        (
            oct::encode_normal_oct16,
            oct::encode_normal_oct16_fast,
            oct::decode_normal_oct16,
        )
    } else {
        (
            oct::encode_normal_oct32,
            oct::encode_normal_oct32_fast,
            oct::decode_normal_oct32,
        )
    };
    let mut codes = vec![0u32; N];
    for (name, enc) in [
        ("prepass encode (precise)", precise),
        ("prepass encode (fast)", fast),
    ] {
        g.bench_function(name, |b| {
            b.iter(|| {
                for (c, v) in codes.iter_mut().zip(black_box(&vecs)) {
                    *c = enc(*v);
                }
                black_box(&codes);
            })
        });
    }
    let mut decoded = vec![glam::Vec3::ZERO; N];
    g.bench_function("prepass decode", |b| {
        b.iter(|| {
            for (d, &c) in decoded.iter_mut().zip(black_box(&codes)) {
                *d = decode(c);
            }
            black_box(&decoded);
        })
    });
    g.finish();
}

fn normal_oct(c: &mut Criterion) {
    meshopt_oct(c, 8, 4);
    meshopt_oct(c, 16, 8);
}

criterion_group! {
    name = benches;
    // Short runs: the figures are stable to a few per cent on a quiet machine.
    config = Criterion::default()
        .warm_up_time(std::time::Duration::from_millis(500))
        .measurement_time(std::time::Duration::from_secs(2));
    targets = depth24, normal_oct
}
criterion_main!(benches);
