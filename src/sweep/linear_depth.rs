//! Linear-depth sweeps over the stiff grid: every 24-bit code, and 2^24 float depths spread in
//! ULP space, measured against the exact f64 references of [`crate::linear_depth::exact`].

use crate::depth24::DEPTH24_MAX;
use crate::harness::{Arg, Gpu, HarnessError};
use crate::precision::metrics::{ErrorStats, ulp_distance, ulp_error};
use crate::projection::{DepthConvention, Projection};

/// Near planes of the stiff grid.
pub const NEARS: [f32; 5] = [1e-4, 1e-2, 0.1, 1.0, 10.0];
/// Far/near ratios of the stiff grid (`∞` = infinite projection).
pub const FAR_RATIOS: [f64; 5] = [10.0, 1e3, 1e6, 1e9, f64::INFINITY];

/// One cell of the stiff grid: `far = near · ratio` rounded to f32 (or `+∞`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StiffCase {
    /// Near plane.
    pub near: f32,
    /// Far plane (f32 as the shader sees it).
    pub far: f32,
    /// The nominal far/near ratio.
    pub ratio: f64,
}

impl StiffCase {
    /// The case's projection in `convention`.
    pub fn projection(&self, convention: DepthConvention) -> Projection {
        Projection::new(self.near, self.far, convention).expect("stiff grid cases are valid")
    }
}

/// All 25 cells: every near × every ratio.
pub fn stiff_grid() -> Vec<StiffCase> {
    NEARS
        .iter()
        .flat_map(|&near| {
            FAR_RATIOS.iter().map(move |&ratio| StiffCase {
                near,
                far: (f64::from(near) * ratio) as f32,
                ratio,
            })
        })
        .collect()
}

/// Error of one linear-depth function over one sweep.
#[derive(Clone, Copy, Debug, Default)]
pub struct LinearStats {
    /// Error in f32 ULPs of the exact distance. Where the exact distance is beyond f32's range,
    /// `+∞` is the correct answer (error 0) and anything else counts as an infinite error.
    pub ulps: ErrorStats,
    /// Relative error `|got − exact|/exact` (readable where the ULP error is huge; `+∞` for an
    /// infinite or wrong-signed result where the exact distance is finite).
    pub relative: ErrorStats,
    /// Neighbouring inputs whose distances go the wrong way (must be 0: depth is monotonic).
    pub non_monotonic: u64,
    /// Largest ULP distance between the adapter and the Rust twin (`u64::MAX` for NaN vs number).
    pub twin_max_ulps: u64,
    /// How many results differ from the Rust twin in any bit.
    pub twin_differ: u64,
}

/// Distances at or above this (`2^127`) are the sky: the functions return
/// [`crate::linear_depth::SKY`] for them (`ld_divide_or_sky`).
const SKY_FROM: f64 = 1.701_411_834_604_692_3e38;

/// Error of `got` against `exact` in ULPs, with [`crate::linear_depth::SKY`] the right answer
/// where the exact distance is `2^127` or more (`+∞` included): 0 for it, `+∞` for anything else.
pub fn distance_error(got: f32, exact: f64) -> f64 {
    if exact >= SKY_FROM {
        return if got == crate::linear_depth::SKY {
            0.0
        } else {
            f64::INFINITY
        };
    }
    ulp_error(got, exact)
}

/// Whether `got` is the sky sentinel for a subnormal float depth of an infinite projection:
/// the functions' denominator is then subnormal (reversed) and they return
/// [`crate::linear_depth::SKY`], as an adapter that flushes the depth to 0 would anyway
/// (`ld_divide_or_sky`); counted as exact.
pub fn subnormal_sky(depth: f32, far: f32, got: f32) -> bool {
    far.is_infinite() && depth.abs() < f32::MIN_POSITIVE && got == crate::linear_depth::SKY
}

fn measure(
    got: &[f32],
    exact: impl Fn(usize) -> f64,
    twin: Option<&dyn Fn(usize) -> f32>,
    increasing: bool,
) -> LinearStats {
    let mut s = LinearStats::default();
    for (i, &g) in got.iter().enumerate() {
        let e = exact(i);
        s.ulps.add(i as u64, distance_error(g, e));
        let rel = if e >= SKY_FROM {
            if g == crate::linear_depth::SKY {
                0.0
            } else {
                f64::INFINITY
            }
        } else {
            crate::precision::metrics::relative_error(f64::from(g), e)
        };
        s.relative.add(i as u64, rel);
        if i > 0 {
            let (a, b) = (got[i - 1], g);
            let wrong = if increasing { a > b } else { a < b };
            if wrong {
                s.non_monotonic += 1;
            }
        }
        if let Some(t) = twin {
            let t = t(i);
            if t.to_bits() != g.to_bits() {
                s.twin_differ += 1;
                s.twin_max_ulps = s.twin_max_ulps.max(ulp_distance(t, g).unwrap_or(u64::MAX));
            }
        }
    }
    s
}

/// Run `function(d: u32, extra…) -> f32` over every 24-bit code (standard convention) for
/// `case`, against the exact distance; `twin` (optional) is the Rust twin for the same code.
pub fn codes_sweep(
    gpu: &Gpu,
    source: &str,
    function: &str,
    extra: &[Arg<'_>],
    case: StiffCase,
    twin: Option<&dyn Fn(u32) -> f32>,
) -> Result<(LinearStats, Vec<f32>), HarnessError> {
    let mut args = vec![Arg::Index { start: 0 }];
    args.extend_from_slice(extra);
    let out = gpu
        .kernel(source, function)?
        .run(&args, u64::from(DEPTH24_MAX) + 1)?;
    let got = out.into_f32();
    let exact =
        |i: usize| crate::linear_depth::exact::view_z_from_depth24(i as u32, case.near, case.far);
    let twin_i = twin.map(|t| move |i: usize| t(i as u32));
    let stats = measure(
        &got,
        exact,
        twin_i.as_ref().map(|t| t as &dyn Fn(usize) -> f32),
        true,
    );
    Ok((stats, got))
}

/// `count` float depths spread evenly in ULP space over `(0, 1]` (from the smallest subnormal to
/// 1.0), with the 64 floats next to 0 and the 64 next to 1 always included.
pub fn float_depths(count: usize) -> Vec<f32> {
    let top = 1.0f32.to_bits() as u64; // ordinal of 1.0; ordinal 1 = smallest subnormal
    let mut v: Vec<u64> = (0..count as u64)
        .map(|i| 1 + i * (top - 1) / (count as u64 - 1))
        .collect();
    v.extend(1..=64);
    v.extend(top - 63..=top);
    v.sort_unstable();
    v.dedup();
    v.into_iter().map(|o| f32::from_bits(o as u32)).collect()
}

/// A WGSL function to sweep and the arguments that follow the depth.
#[derive(Clone, Copy, Debug)]
pub struct Call<'a> {
    /// WGSL source defining the function.
    pub source: &'a str,
    /// The function's name.
    pub function: &'a str,
    /// Arguments after the depth (near/far splats, or a constants vector).
    pub extra: &'a [Arg<'a>],
}

/// Run `call.function(z: f32, extra…) -> f32` over `depths` (sorted ascending) for `case` in
/// `convention`, against the exact distance; `twin` (optional) is the Rust twin.
pub fn float_sweep(
    gpu: &Gpu,
    call: Call<'_>,
    depths: &[f32],
    (case, convention): (StiffCase, DepthConvention),
    twin: Option<&dyn Fn(f32) -> f32>,
) -> Result<(LinearStats, Vec<f32>), HarnessError> {
    let mut args = vec![Arg::column(depths)];
    args.extend_from_slice(call.extra);
    let out = gpu
        .kernel(call.source, call.function)?
        .run(&args, depths.len() as u64)?;
    let got = out.into_f32();
    let exact = |i: usize| match convention {
        _ if subnormal_sky(depths[i], case.far, got[i]) => f64::INFINITY,
        DepthConvention::Standard => {
            crate::linear_depth::exact::view_z_from_depth(depths[i], case.near, case.far)
        }
        DepthConvention::Reversed => {
            crate::linear_depth::exact::view_z_from_reversed_depth(depths[i], case.near, case.far)
        }
    };
    let twin_i = twin.map(|t| move |i: usize| t(depths[i]));
    let stats = measure(
        &got,
        exact,
        twin_i.as_ref().map(|t| t as &dyn Fn(usize) -> f32),
        convention == DepthConvention::Standard,
    );
    Ok((stats, got))
}

/// Constants `(a, b)` of the textbook inverse `vz = 1/(z·a + b)` (Lee, "Pre-lighting in Resistance
/// 2") for `case` in `convention`, in f64 rounded once (the baseline's most favourable setting).
/// Standard: `a = 1/f − 1/n`, `b = 1/n`; reversed: `a = 1/n − 1/f`, `b = 1/f`.
pub fn textbook_consts(case: StiffCase, convention: DepthConvention) -> [f32; 2] {
    let (n, f) = (f64::from(case.near), f64::from(case.far));
    match convention {
        DepthConvention::Standard => [(1.0 / f - 1.0 / n) as f32, (1.0 / n) as f32],
        DepthConvention::Reversed => [(1.0 / n - 1.0 / f) as f32, (1.0 / f) as f32],
    }
}

/// Constants `(A, B)` of the `vz = B/(z − A)` form, f64 rounded once. Standard:
/// `A = f/(f − n)`, `B = −f·n/(f − n)` (`A = 1`, `B = −n` when infinite); reversed:
/// `A = −n/(f − n)`, `B = f·n/(f − n)`.
pub fn b_over_d_minus_a_consts(case: StiffCase, convention: DepthConvention) -> [f32; 2] {
    let (n, f) = (f64::from(case.near), f64::from(case.far));
    match (convention, f.is_infinite()) {
        (DepthConvention::Standard, true) => [1.0, -n as f32],
        (DepthConvention::Standard, false) => [(f / (f - n)) as f32, (-f * n / (f - n)) as f32],
        (DepthConvention::Reversed, true) => [0.0, n as f32],
        (DepthConvention::Reversed, false) => [(-n / (f - n)) as f32, (f * n / (f - n)) as f32],
    }
}

/// Which stored depth a grid row reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DepthPath {
    /// 24-bit standard-convention codes (every code).
    Code24,
    /// Float depth, standard convention.
    FloatStandard,
    /// Float depth, reversed convention.
    FloatReversed,
}

impl DepthPath {
    /// Short label for tables.
    pub fn label(self) -> &'static str {
        match self {
            Self::Code24 => "D24 code",
            Self::FloatStandard => "float standard",
            Self::FloatReversed => "float reversed",
        }
    }
}

/// One row of the README's error table: a depth path and stiff case, with the stable forms and
/// the two baselines measured on the same inputs.
#[derive(Clone, Copy, Debug)]
pub struct GridRow {
    /// Depth path.
    pub path: DepthPath,
    /// Stiff case.
    pub case: StiffCase,
    /// The shipped function taking near/far.
    pub stable: LinearStats,
    /// The shipped per-pixel-constants variant.
    pub stable_consts: LinearStats,
    /// The textbook `1/(z·a + b)` of Lee's "Pre-lighting in Resistance 2".
    pub textbook: LinearStats,
    /// The `B/(z − A)` form.
    pub b_over_z_minus_a: LinearStats,
}

/// Measure every path × case: the shipped forms against the baselines defined in
/// `baselines_source` (`tests/baselines/linear_depth.wgsl`). Float paths use
/// [`float_depths`]`(float_count)`. `each` is called after every row (for progress).
pub fn grid_table(
    gpu: &Gpu,
    baselines_source: &str,
    cases: &[StiffCase],
    float_count: usize,
    mut each: impl FnMut(&GridRow),
) -> Result<Vec<GridRow>, HarnessError> {
    let src = format!("{}\n{baselines_source}", crate::wgsl::LINEAR_DEPTH);
    let depths = float_depths(float_count);
    let mut rows = Vec::new();
    for path in [
        DepthPath::Code24,
        DepthPath::FloatStandard,
        DepthPath::FloatReversed,
    ] {
        for &case in cases {
            let nf = [Arg::splat_f32(case.near), Arg::splat_f32(case.far)];
            let conv = match path {
                DepthPath::FloatReversed => DepthConvention::Reversed,
                _ => DepthConvention::Standard,
            };
            let p = case.projection(conv);
            let tb = [Arg::splat_vec(&textbook_consts(case, conv))];
            let ba = [Arg::splat_vec(&b_over_d_minus_a_consts(case, conv))];
            let run = |function: &str, extra: &[Arg<'_>]| -> Result<LinearStats, HarnessError> {
                let call = Call {
                    source: &src,
                    function,
                    extra,
                };
                Ok(match path {
                    DepthPath::Code24 => {
                        codes_sweep(gpu, call.source, function, extra, case, None)?.0
                    }
                    _ => float_sweep(gpu, call, &depths, (case, conv), None)?.0,
                })
            };
            let row = match path {
                DepthPath::Code24 => {
                    let k = [Arg::splat_vec(
                        &p.depth24_consts()
                            .expect("a projection of the convention these constants read")
                            .to_wgsl(),
                    )];
                    GridRow {
                        path,
                        case,
                        stable: run("view_z_from_depth24", &nf)?,
                        stable_consts: run("view_z_from_depth24_consts", &k)?,
                        textbook: run("baseline_view_z_textbook24", &tb)?,
                        b_over_z_minus_a: run("baseline_view_z_b_over_d_minus_a24", &ba)?,
                    }
                }
                DepthPath::FloatStandard => {
                    let k = [Arg::splat_vec(
                        &p.depth_consts()
                            .expect("a projection of the convention these constants read")
                            .to_wgsl(),
                    )];
                    GridRow {
                        path,
                        case,
                        stable: run("view_z_from_depth", &nf)?,
                        stable_consts: run("view_z_from_depth_consts", &k)?,
                        textbook: run("baseline_view_z_textbook", &tb)?,
                        b_over_z_minus_a: run("baseline_view_z_b_over_d_minus_a", &ba)?,
                    }
                }
                DepthPath::FloatReversed => {
                    let k = [Arg::splat_vec(
                        &p.reversed_depth_consts()
                            .expect("a projection of the convention these constants read")
                            .to_wgsl(),
                    )];
                    GridRow {
                        path,
                        case,
                        stable: run("view_z_from_reversed_depth", &nf)?,
                        stable_consts: run("view_z_from_reversed_depth_consts", &k)?,
                        textbook: run("baseline_view_z_textbook", &tb)?,
                        b_over_z_minus_a: run("baseline_view_z_b_over_d_minus_a", &ba)?,
                    }
                }
            };
            each(&row);
            rows.push(row);
        }
    }
    Ok(rows)
}

/// Runs a batch (arguments, element count) and returns the `f32` results: the shipped kernel, or
/// an emulated one.
pub type RunBatch<'a> = dyn Fn(&[Arg<'_>], u64) -> Result<Vec<f32>, HarnessError> + 'a;

/// One shipped linear-depth function, as the sampled sweeps call it.
#[derive(Clone, Copy, Debug)]
pub struct Path {
    /// The WGSL function (and Rust twin) name.
    pub function: &'static str,
    /// Whether it reads 24-bit codes (else float depth).
    pub code: bool,
    /// Whether it takes the per-projection constants (else near and far).
    pub consts: bool,
    /// The depth convention it reads.
    pub convention: DepthConvention,
}

/// Every shipped path: codes, standard and reversed float depth, each with near/far and with
/// per-pixel constants.
pub const PATHS: [Path; 6] = [
    Path {
        function: "view_z_from_depth24",
        code: true,
        consts: false,
        convention: DepthConvention::Standard,
    },
    Path {
        function: "view_z_from_depth24_consts",
        code: true,
        consts: true,
        convention: DepthConvention::Standard,
    },
    Path {
        function: "view_z_from_depth",
        code: false,
        consts: false,
        convention: DepthConvention::Standard,
    },
    Path {
        function: "view_z_from_depth_consts",
        code: false,
        consts: true,
        convention: DepthConvention::Standard,
    },
    Path {
        function: "view_z_from_reversed_depth",
        code: false,
        consts: false,
        convention: DepthConvention::Reversed,
    },
    Path {
        function: "view_z_from_reversed_depth_consts",
        code: false,
        consts: true,
        convention: DepthConvention::Reversed,
    },
];

/// The sample of [`sampled_worst`]: codes 0–255, every 257th code and the top 256.
pub fn sampled_codes() -> Vec<u32> {
    let mut codes: Vec<u32> = (0..256)
        .chain((256..DEPTH24_MAX - 255).step_by(257))
        .collect();
    codes.extend(DEPTH24_MAX - 255..=DEPTH24_MAX);
    codes
}

/// One evaluated input of [`sampled_worst`]'s sample: its stiff case, the constants a
/// `_consts` path reads (else empty), the input's bits (a code, or a float depth), and the
/// result's error in ULPs.
#[derive(Clone, Debug)]
pub struct SampledInput {
    /// The stiff-grid case.
    pub case: StiffCase,
    /// The per-projection constants (for `_consts` paths; empty otherwise).
    pub consts: Vec<f32>,
    /// The code, or the float depth's bits.
    pub input_bits: u32,
    /// ULP error of the result ([`distance_error`]); 0 where a flushed subnormal depth gave the
    /// sky, its documented answer.
    pub error: f64,
    /// A description: case, input, result and exact value.
    pub at: String,
}

/// The exact view distance of `path` at an input's bits.
fn exact_of(path: &Path, bits: u32, near: f32, far: f32) -> f64 {
    let z = f32::from_bits(bits);
    if path.code {
        crate::linear_depth::exact::view_z_from_depth24(bits, near, far)
    } else if path.convention == DepthConvention::Standard {
        crate::linear_depth::exact::view_z_from_depth(z, near, far)
    } else {
        crate::linear_depth::exact::view_z_from_reversed_depth(z, near, far)
    }
}

/// The error of `got` for `path` at an input: [`distance_error`], 0 for a flushed subnormal
/// depth that gave the sky.
fn error_of(path: &Path, bits: u32, near: f32, far: f32, got: f32) -> f64 {
    if !path.code && subnormal_sky(f32::from_bits(bits), far, got) {
        return 0.0;
    }
    distance_error(got, exact_of(path, bits, near, far))
}

fn consts_of(path: &Path, case: &StiffCase) -> Vec<f32> {
    let p = case.projection(path.convention);
    let why = "a projection of the convention these constants read";
    match (path.code, path.convention) {
        (true, _) => p.depth24_consts().expect(why).to_wgsl().to_vec(),
        (false, DepthConvention::Standard) => p.depth_consts().expect(why).to_wgsl().to_vec(),
        (false, DepthConvention::Reversed) => {
            p.reversed_depth_consts().expect(why).to_wgsl().to_vec()
        }
    }
}

/// Every input of [`sampled_worst`]'s sample, evaluated by `run`: `visit` gets each input's
/// error and a closure that builds the input's whole record, called only for inputs it keeps
/// (most are not kept, so their descriptions are never formatted).
fn each_sampled(
    path: &Path,
    run: &RunBatch<'_>,
    mut visit: impl FnMut(f64, &dyn Fn() -> SampledInput),
) -> Result<(), HarnessError> {
    let codes = sampled_codes();
    let depths: Vec<u32> = float_depths(1 << 16).iter().map(|z| z.to_bits()).collect();
    let inputs = if path.code { &codes } else { &depths };
    for case in stiff_grid() {
        let (n, f) = (case.near, case.far);
        let k = consts_of(path, &case);
        let mut args = vec![Arg::column(inputs)];
        if path.consts {
            args.push(Arg::splat_vec(&k));
        } else {
            args.extend([Arg::splat_f32(n), Arg::splat_f32(f)]);
        }
        let got = run(&args, inputs.len() as u64)?;
        for (&bits, &g) in inputs.iter().zip(&got) {
            let error = error_of(path, bits, n, f, g);
            let record = || {
                let input = if path.code {
                    format!("code {bits}")
                } else {
                    format!("z {:e}", f32::from_bits(bits))
                };
                let e = exact_of(path, bits, n, f);
                SampledInput {
                    case,
                    consts: if path.consts { k.clone() } else { Vec::new() },
                    input_bits: bits,
                    error,
                    at: format!("near {n:e}, far {f:e}, {input}: {g:e} vs exact {e:e}"),
                }
            };
            visit(error, &record);
        }
    }
    Ok(())
}

/// The worst error of one path over the whole stiff grid, sampled ([`sampled_codes`], or 2^16
/// [`float_depths`]), run by `kernel` (the shipped WGSL, or an emulation of it): the ULP error
/// and a description of the input. A subnormal float depth that an emulated adapter flushed to
/// the sky (`+∞` with an infinite far plane) counts as its documented answer.
pub fn sampled_worst(path: &Path, run: &RunBatch<'_>) -> Result<(f64, String), HarnessError> {
    let mut worst = (0.0f64, String::new());
    each_sampled(path, run, |error, record| {
        if error > worst.0 {
            worst = (error, record().at);
        }
    })?;
    Ok(worst)
}

/// The `k` inputs of [`sampled_worst`]'s sample with the largest errors under `run`, worst
/// first.
pub fn worst_inputs(
    path: &Path,
    run: &RunBatch<'_>,
    k: usize,
) -> Result<Vec<SampledInput>, HarnessError> {
    let mut top: Vec<SampledInput> = Vec::with_capacity(k + 1);
    each_sampled(path, run, |error, record| {
        if top.len() < k || error > top[top.len() - 1].error {
            let at = top.partition_point(|t| t.error >= error);
            top.insert(at, record());
            top.truncate(k);
        }
    })?;
    Ok(top)
}

/// The worst-case search ([`crate::conforming::search::climb`]) at each of `inputs`: per input,
/// the direction table that makes `path`'s error largest on the emulated adapter. Returns, per
/// input, the error found and the search's record.
pub fn searched_worst(
    gpu: &Gpu,
    path: &Path,
    inputs: &[SampledInput],
    config: &crate::conforming::search::SearchConfig,
) -> Result<Vec<crate::conforming::search::Found>, HarnessError> {
    use crate::conforming::{EmulatedKernel, Emulation, Policy, search};
    let kernel = EmulatedKernel::new(
        gpu,
        crate::wgsl::LINEAR_DEPTH,
        path.function,
        &Emulation::new(Policy::Searched),
    )?;
    let bits: Vec<u32> = inputs.iter().map(|s| s.input_bits).collect();
    let near: Vec<f32> = inputs.iter().map(|s| s.case.near).collect();
    let far: Vec<f32> = inputs.iter().map(|s| s.case.far).collect();
    let consts: Vec<f32> = inputs
        .iter()
        .flat_map(|s| s.consts.iter().copied())
        .collect();
    let mut args = vec![Arg::column(&bits)];
    if path.consts {
        args.push(Arg::column(&consts));
    } else {
        args.extend([Arg::column(&near), Arg::column(&far)]);
    }
    let error = |i: usize, out: &crate::harness::Output, e: usize| {
        error_of(path, bits[i], near[i], far[i], out.as_f32()[e])
    };
    search::climb(&kernel, &args, inputs.len(), &error, config)
}

/// The machine-derived bound's sample: every `MACHINE_STRIDE`-th input of [`sampled_worst`]'s
/// sample, on every stiff-grid case (the interval evaluator runs on the CPU, about 20 µs an
/// input; the stride keeps each path near a second on two cores).
pub const MACHINE_STRIDE: usize = 16;

/// The largest error any conforming adapter can make on `path` at one input: the interval
/// enclosure of every result the spec allows ([`crate::conforming::interval`], with
/// flushing), measured at its farther end in the sweeps' ULPs ([`distance_error`]).
pub fn machine_error(
    path: &Path,
    enclosure: &crate::conforming::interval::Enclosure,
    bits: u32,
    case: &StiffCase,
    consts: &[f32],
) -> Result<f64, crate::conforming::interval::IntervalError> {
    use crate::conforming::interval::{IntervalError, Value};
    let depth = if path.code {
        Value::u32s(&[bits])
    } else {
        Value::f32s(&[f32::from_bits(bits)])
    };
    let args = if path.consts {
        vec![depth, Value::f32s(consts)]
    } else {
        vec![depth, Value::f32s(&[case.near]), Value::f32s(&[case.far])]
    };
    let v = enclosure.of(path.function, &args)?;
    let iv = v
        .f32_lanes()
        .ok_or_else(|| IntervalError::NotCovered("a result that is not f32".into()))?[0];
    let (n, f) = (case.near, case.far);
    Ok(error_of(path, bits, n, f, iv.lo).max(error_of(path, bits, n, f, iv.hi)))
}

/// [`machine_error`]'s largest value over the stiff grid, sampled ([`MACHINE_STRIDE`]), with
/// where it is; cases run on parallel threads.
/// `enclosure` is [`crate::wgsl::LINEAR_DEPTH`]'s, with flushing.
pub fn machine_worst(
    path: &Path,
    enclosure: &crate::conforming::interval::Enclosure,
) -> Result<(f64, String), crate::conforming::interval::IntervalError> {
    let codes: Vec<u32> = sampled_codes()
        .into_iter()
        .step_by(MACHINE_STRIDE)
        .collect();
    let depths: Vec<u32> = float_depths(1 << 16)
        .iter()
        .step_by(MACHINE_STRIDE)
        .map(|z| z.to_bits())
        .collect();
    let inputs = if path.code { &codes } else { &depths };
    let cases = stiff_grid();
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let per = cases.len().div_ceil(threads);
    let results = std::thread::scope(|sc| {
        let handles: Vec<_> = cases
            .chunks(per)
            .map(|part| {
                sc.spawn(move || {
                    let mut worst = (0.0f64, String::new());
                    for case in part {
                        let k = consts_of(path, case);
                        for &bits in inputs {
                            let e = machine_error(path, enclosure, bits, case, &k)?;
                            if e > worst.0 {
                                let input = if path.code {
                                    format!("code {bits}")
                                } else {
                                    format!("z {:e}", f32::from_bits(bits))
                                };
                                worst = (
                                    e,
                                    format!("near {:e}, far {:e}, {input}", case.near, case.far),
                                );
                            }
                        }
                    }
                    Ok(worst)
                })
            })
            .collect();
        handles
            .into_iter()
            .map(|h| h.join().expect("machine-bound thread"))
            .collect::<Vec<_>>()
    });
    let mut worst = (0.0f64, String::new());
    for r in results {
        let r = r?;
        if r.0 > worst.0 {
            worst = r;
        }
    }
    Ok(worst)
}
