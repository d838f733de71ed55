//! The WGSL harness itself: signatures, feeds, chunking, bit transparency, errors.

mod common;

use common::gpu;
use prepass::harness::{Arg, HarnessError, MAX_CHUNK, Scalar, ValueType};

const SRC: &str = "
fn mix3(a: vec3<f32>, s: f32, k: u32) -> vec3<f32> { return a * s + vec3<f32>(f32(k)); }
fn affine(i: u32, j: i32) -> i32 { return i32(i) * 3 - j; }
fn id_f32(x: f32) -> f32 { return x; }
fn id_vec4(x: vec4<u32>) -> vec4<u32> { return x; }
fn swap(v: vec2<f32>) -> vec2<f32> { return v.yx; }
fn flag(x: f32) -> bool { return x > 0.0; }
fn takes_bool(b: bool) -> u32 { return select(0u, 1u, b); }
";

#[test]
fn reads_signatures_with_naga() {
    let k = gpu().kernel(SRC, "mix3").unwrap();
    let s = k.signature();
    assert_eq!(s.params.len(), 3);
    assert_eq!(s.params[0].name, "a");
    let vec3f = ValueType {
        scalar: Scalar::F32,
        lanes: 3,
    };
    assert_eq!(s.params[0].ty, vec3f);
    assert_eq!(s.result, vec3f);
    assert_eq!(s.params[2].ty.scalar, Scalar::U32);
}

#[test]
fn columns_splats_and_indices_feed_each_element() {
    let n = 1000u64;
    let a: Vec<[f32; 3]> = (0..n).map(|i| [i as f32, -(i as f32), 0.5]).collect();
    let out = gpu()
        .kernel(SRC, "mix3")
        .unwrap()
        .run(
            &[
                Arg::column(&a),
                Arg::splat_f32(2.0),
                Arg::Index { start: 10 },
            ],
            n,
        )
        .unwrap();
    for (i, v) in out.as_vec3().iter().enumerate() {
        let k = (i + 10) as f32;
        // Small integers and halves: every operation here is exact in f32.
        assert_eq!(
            *v,
            [2.0 * i as f32 + k, -2.0 * i as f32 + k, 1.0 + k],
            "element {i}"
        );
    }
}

#[test]
fn signed_integers_and_vectors_round_trip() {
    let n = 300u64;
    let j: Vec<i32> = (0..n as i32).map(|x| x * 7 - 1000).collect();
    let out = gpu()
        .kernel(SRC, "affine")
        .unwrap()
        .run(&[Arg::Index { start: 0 }, Arg::column(&j)], n)
        .unwrap();
    for (i, &r) in out.as_i32().iter().enumerate() {
        assert_eq!(r, i as i32 * 3 - j[i]);
    }
    let v: Vec<[u32; 4]> = (0..n as u32)
        .map(|i| [i, !i, i << 7, u32::MAX - i])
        .collect();
    let out = gpu()
        .kernel(SRC, "id_vec4")
        .unwrap()
        .run(&[Arg::column(&v)], n)
        .unwrap();
    assert_eq!(out.words(), bytemuck::cast_slice::<[u32; 4], u32>(&v));
    let w: Vec<[f32; 2]> = vec![[1.0, 2.0], [3.0, -4.0]];
    let out = gpu()
        .kernel(SRC, "swap")
        .unwrap()
        .run(&[Arg::column(&w)], 2)
        .unwrap();
    assert_eq!(out.as_vec2(), &[[2.0, 1.0], [-4.0, 3.0]]);
}

#[test]
fn special_floats_cross_the_buffers_bit_exactly() {
    let specials = [
        0.0f32,
        -0.0,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::from_bits(0x7fc0_0001), // quiet NaN with a payload
        f32::MAX,
        f32::MIN_POSITIVE,
        1.0,
    ];
    let out = gpu()
        .kernel(SRC, "id_f32")
        .unwrap()
        .run(&[Arg::column(&specials)], specials.len() as u64)
        .unwrap();
    let got: Vec<u32> = out.words().to_vec();
    let want: Vec<u32> = specials.iter().map(|x| x.to_bits()).collect();
    assert_eq!(got, want);
}

#[test]
fn batches_larger_than_a_chunk_are_dispatched_in_pieces() {
    // Two full chunks and a ragged tail not a multiple of the workgroup size.
    let n = 2 * MAX_CHUNK + 77;
    let j: Vec<i32> = (0..n).map(|i| (i % 1013) as i32).collect();
    let mut chunks = 0;
    let mut seen = 0u64;
    gpu()
        .kernel(SRC, "affine")
        .unwrap()
        .run_chunks(
            &[Arg::Index { start: 5 }, Arg::column(&j)],
            n,
            |first, out| {
                chunks += 1;
                for (k, &r) in out.as_i32().iter().enumerate() {
                    let i = first + k as u64;
                    let want = (i as u32 + 5).wrapping_mul(3) as i32 - j[i as usize];
                    assert_eq!(r, want, "element {i}");
                }
                seen += out.len() as u64;
                Ok(())
            },
        )
        .unwrap();
    assert_eq!(seen, n);
    assert_eq!(chunks, 3);
}

#[test]
fn errors_name_what_is_wrong() {
    let g = gpu();
    let e = g.kernel(SRC, "nope").err().unwrap().to_string();
    assert!(
        e.contains("no function `nope`") && e.contains("mix3"),
        "{e}"
    );
    let e = g.kernel(SRC, "flag").err().unwrap().to_string();
    assert!(e.contains("result"), "{e}");
    let e = g.kernel(SRC, "takes_bool").err().unwrap().to_string();
    assert!(e.contains("`b`"), "{e}");
    let e = g.kernel("fn f( -> f32 {}", "f").err().unwrap().to_string();
    assert!(e.contains("parse"), "{e}");
    let k = g.kernel(SRC, "mix3").unwrap();
    let short = [[0.0f32; 3]; 3];
    let e = k
        .run(
            &[Arg::column(&short), Arg::splat_f32(1.0), Arg::splat_u32(0)],
            4,
        )
        .unwrap_err();
    assert!(matches!(e, HarnessError::Arguments(_)), "{e}");
    let e = k
        .run(&[Arg::Index { start: 0 }], 4)
        .unwrap_err()
        .to_string();
    assert!(e.contains("takes 3 arguments"), "{e}");
    let e = k
        .run(
            &[
                Arg::Index { start: 0 },
                Arg::splat_f32(1.0),
                Arg::splat_u32(0),
            ],
            4,
        )
        .unwrap_err()
        .to_string();
    assert!(e.contains("scalars"), "{e}");
}

#[test]
fn reports_the_adapter() {
    let d = gpu().describe();
    assert!(!d.trim().is_empty());
    eprintln!("adapter: {d}");
}
