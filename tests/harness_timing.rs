//! `Kernel::time`: the GPU-timing API errplot uses. Timings are never asserted against numbers
//! (they depend on the machine); these tests check that the API measures something, reports its
//! clock truthfully, and rejects dispatches it cannot time.

mod common;

use prepass::harness::{Arg, MIN_TIMED_INVOCATIONS, TimingMethod};

const SRC: &str = "fn timing_probe(x: vec3<f32>, k: u32) -> vec2<f32> {\n\
                   return vec2<f32>(sqrt(dot(x, x)), f32(k) * 0.5);\n}\n";

fn column() -> Vec<[f32; 3]> {
    (0..1024).map(|i| [i as f32, 1.0, -2.0]).collect()
}

#[test]
fn timing_reports_its_clock_and_positive_durations() {
    let gpu = common::gpu();
    let k = gpu.kernel(SRC, "timing_probe").unwrap();
    let col = column();
    let args = [Arg::column(&col), Arg::Index { start: 7 }];
    let t = k.time(&args, MIN_TIMED_INVOCATIONS, 1).unwrap();
    let has_timestamps = gpu
        .device()
        .features()
        .contains(wgpu::Features::TIMESTAMP_QUERY);
    let expected = if has_timestamps {
        TimingMethod::TimestampQuery
    } else {
        TimingMethod::WallClock
    };
    assert_eq!(t.method, expected);
    assert_eq!(t.invocations, MIN_TIMED_INVOCATIONS);
    assert!(t.function_ns > 0.0 && t.function_ns.is_finite(), "{t:?}");
    assert!(t.baseline_ns > 0.0 && t.baseline_ns.is_finite(), "{t:?}");
    assert!(t.ns_per_eval().is_finite(), "{t:?}");

    // The wall clock can always be asked for.
    let w = k
        .time_with(&args, MIN_TIMED_INVOCATIONS, 1, TimingMethod::WallClock)
        .unwrap();
    assert_eq!(w.method, TimingMethod::WallClock);
    assert!(w.function_ns > 0.0 && w.baseline_ns > 0.0, "{w:?}");
}

#[test]
fn timing_rejects_what_it_cannot_time() {
    let gpu = common::gpu();
    let k = gpu.kernel(SRC, "timing_probe").unwrap();
    let col = column();
    let args = [Arg::column(&col), Arg::Index { start: 0 }];
    let small = k.time(&args, MIN_TIMED_INVOCATIONS - 1, 1).unwrap_err();
    assert!(small.to_string().contains("2^24"), "{small}");
    let odd: Vec<[f32; 3]> = column()[..1000].to_vec();
    let e = k
        .time(
            &[Arg::column(&odd), Arg::Index { start: 0 }],
            MIN_TIMED_INVOCATIONS,
            1,
        )
        .unwrap_err();
    assert!(e.to_string().contains("power-of-two"), "{e}");
    let e = k.time(&args[..1], MIN_TIMED_INVOCATIONS, 1).unwrap_err();
    assert!(e.to_string().contains("takes 2 arguments"), "{e}");
}
