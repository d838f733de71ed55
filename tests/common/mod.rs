//! Shared by the integration tests: one adapter for the whole test binary.

#[cfg(not(feature = "harness"))]
compile_error!(
    "prepass's tests execute WGSL on a wgpu adapter: run them with \
     `cargo test --release --all-features` (the README's test command)"
);

pub mod tier;

use prepass::harness::{Arg, Gpu, Output};
use std::sync::OnceLock;

/// The adapter every test runs on. With none, every test that needs it FAILS with the
/// harness's message, which names the fix (install lavapipe) — nothing is skipped.
#[allow(dead_code)]
pub fn gpu() -> &'static Gpu {
    static GPU: OnceLock<Result<Gpu, String>> = OnceLock::new();
    match GPU.get_or_init(|| {
        Gpu::new()
            .inspect(|g| eprintln!("prepass tests run on: {}", g.describe()))
            .map_err(|e| e.to_string())
    }) {
        Ok(g) => g,
        Err(e) => panic!("{e}"),
    }
}

/// `function` of `source` applied to `n` elements on [`gpu`]'s adapter. Panics with the
/// harness's error (unknown function, arguments that do not fit its signature, a lost device),
/// naming the function.
#[allow(dead_code)]
pub fn run_kernel(source: &str, function: &str, args: &[Arg<'_>], n: u64) -> Output {
    gpu()
        .kernel(source, function)
        .and_then(|k| k.run(args, n))
        .unwrap_or_else(|e| panic!("`{function}` on the adapter: {e}"))
}

/// Each `bad` input must encode, with `codec`'s WGSL encoder on the adapter, to the same code as
/// its documented equivalent in `good` (same index), and the Rust twin must give that code too.
/// Returns the adapter's codes for further checks.
#[allow(dead_code)]
pub fn assert_encodes_like(codec: &str, bad: &[[f32; 3]], good: &[[f32; 3]]) -> Vec<u32> {
    use prepass::harness::Arg;
    let c = prepass::sweep::normal::codec(codec);
    let k = gpu().kernel(c.source, c.encode).unwrap();
    let got = k
        .run(&[Arg::column(bad)], bad.len() as u64)
        .unwrap()
        .into_words();
    let want = k
        .run(&[Arg::column(good)], good.len() as u64)
        .unwrap()
        .into_words();
    for i in 0..bad.len() {
        assert_eq!(
            got[i], want[i],
            "{codec}: {:?} should encode like {:?}",
            bad[i], good[i]
        );
        assert_eq!(
            got[i],
            (c.twin_encode)(glam::Vec3::from(bad[i])),
            "{codec}: twin differs on {:?}",
            bad[i]
        );
    }
    got
}

/// The inputs of the normal render-target tests: 2^16 Fibonacci directions, then every bad
/// encoder input.
#[allow(dead_code)]
pub fn render_target_inputs() -> Vec<[f32; 3]> {
    use prepass::sweep::normal::{bad_inputs, fibonacci_directions};
    fibonacci_directions(1 << 16)
        .into_iter()
        .chain(bad_inputs().into_iter().map(|c| c.0))
        .collect()
}

/// `codec`'s WGSL render-target form (`encode_unorm` writing `lanes` unorm channels,
/// `decode_unorm` reading them) agrees bit for bit with its code path on the adapter over
/// `inputs` (see `prepass::sweep::normal::unorm_forms`).
#[allow(dead_code)]
pub fn assert_unorm_forms(
    codec: &str,
    encode_unorm: &str,
    decode_unorm: &str,
    lanes: usize,
    inputs: &[[f32; 3]],
) {
    let c = prepass::sweep::normal::codec(codec);
    let f =
        prepass::sweep::normal::unorm_forms(gpu(), c, encode_unorm, decode_unorm, lanes, inputs)
            .unwrap();
    assert_eq!(f.encode.count, 0, "{codec}: {:?}", f.encode.first);
    // Bound: 0. Every channel is within 0.45/255 of byte/255, so round(255 c) is the byte.
    assert_eq!(f.decode.count, 0, "{codec}: {:?}", f.decode.first);
}

/// A Rust render-target form decodes like its code path:
/// `decode_unorm(encode_unorm(v)) == decode(encode(v))` for every input.
#[allow(dead_code)]
pub fn assert_twin_unorm_form(
    inputs: &[[f32; 3]],
    encode_unorm: fn(glam::Vec3) -> [f32; 4],
    decode_unorm: fn([f32; 4]) -> glam::Vec3,
    encode: fn(glam::Vec3) -> u32,
    decode: fn(u32) -> glam::Vec3,
) {
    for v in inputs {
        let v = glam::Vec3::from(*v);
        assert_eq!(decode_unorm(encode_unorm(v)), decode(encode(v)), "at {v}");
    }
}

/// A round trip on the adapter keeps the twins' promise for `codec` over `inputs`: bit for bit
/// the Rust encoder's codes and decoder's vectors, each decoded vector unit within
/// `UNIT_TOLERANCE`, where the adapter evaluates like the twins ([`evaluates_like_the_twins`]:
/// lavapipe); on any other conforming adapter (naga's GLSL on
/// Mesa's GL, a GPU with a 2.5-ULP division or fused products) every code within one code step
/// of the twin's and every decode unit within `UNIT_TOLERANCE_CONFORMING`, the differences from
/// the twins printed. `what` names the codec and set.
#[allow(dead_code)]
pub fn assert_round_trip_matches_twins(
    what: &str,
    codec: &prepass::sweep::normal::Codec,
    inputs: &[[f32; 3]],
    rt: &prepass::sweep::normal::RoundTrip,
) {
    use prepass::sweep::conforming::{UNIT_TOLERANCE_CONFORMING, length_check, max_code_step};
    if !evaluates_like_the_twins() {
        let steps = max_code_step(codec, inputs, &rt.codes);
        let (len, bad) = length_check(&rt.decoded, UNIT_TOLERANCE_CONFORMING);
        eprintln!(
            "{what}: {} codes and {} decoded vectors differ from the Rust twins (this adapter \
             does not evaluate like them); codes at most {steps} step(s) away, max |len − 1| \
             {len:.3e}",
            rt.twin_encode.count, rt.twin_decode.count
        );
        prepass::assert_within!(
            steps,
            1,
            "the twins' promise: within one code on every conforming adapter",
            "{what}: code steps from the Rust twin's (first differing: {:?})",
            rt.twin_encode.first
        );
        assert_eq!(
            bad, 0,
            "{what}: {bad} decoded vectors not finite or off unit length by more than \
             UNIT_TOLERANCE_CONFORMING = {UNIT_TOLERANCE_CONFORMING:e} (largest {len:e}; \
             derivation: sweep::conforming)"
        );
        return;
    }
    assert_eq!(
        rt.twin_encode.count, 0,
        "{what}: Rust encoder differs on {} inputs, first (index, WGSL, Rust): {:?}",
        rt.twin_encode.count, rt.twin_encode.first
    );
    assert_eq!(
        rt.twin_decode.count, 0,
        "{what}: Rust decoder differs: {:?}",
        rt.twin_decode.first
    );
    assert_eq!(rt.not_unit, 0, "{what}: decoded vectors off unit length");
}

/// A decoder ignores the bits above its code: `decode` in `source` gives, bit for bit, the same
/// vector for each of `junk` as for that code with only its `mask` bits kept (the adapter
/// against itself, so this holds on every adapter).
#[allow(dead_code)]
pub fn assert_high_bits_ignored(source: &str, decode: &str, junk: &[u32], mask: u32) {
    let clean: Vec<u32> = junk.iter().map(|p| p & mask).collect();
    let n = junk.len() as u64;
    let got = run_kernel(source, decode, &[Arg::column(junk)], n);
    let want = run_kernel(source, decode, &[Arg::column(&clean)], n);
    let bits = |v: &[f32; 3]| v.map(f32::to_bits);
    let differ = (0..junk.len()).find(|&i| bits(&got.as_vec3()[i]) != bits(&want.as_vec3()[i]));
    assert!(
        differ.is_none(),
        "{decode}: bits above the code changed a decode, first {:#x}: {:?} against {:?} for \
         {:#x}",
        differ.map_or(0, |i| junk[i]),
        differ.map(|i| got.as_vec3()[i]),
        differ.map(|i| want.as_vec3()[i]),
        differ.map_or(0, |i| clean[i])
    );
}

/// Decoded vectors: finite, unit within the normalize budget, the exact direction of the code
/// up to that rounding, bit-identical to the Rust twin — where the adapter evaluates like the
/// twins ([`evaluates_like_the_twins`]); elsewhere within the conforming budgets
/// (`UNIT_TOLERANCE_CONFORMING`, `decode_angle_conforming_deg`), the twin differences printed.
#[allow(dead_code)]
pub fn assert_decoder(name: &str, d: &prepass::sweep::normal::DecoderCheck) {
    use prepass::sweep::conforming::{UNIT_TOLERANCE_CONFORMING, decode_angle_conforming_deg};
    use prepass::sweep::normal::{UNIT_TOLERANCE, decode_angle_deg};
    eprintln!(
        "{name}: {} codes, max |len-1| {:.3e}, max angle to exact {:.3e}°, twin differs {}",
        d.codes, d.max_len_error, d.max_angle_deg, d.twin.count
    );
    let like = evaluates_like_the_twins();
    let (unit, angle) = if like {
        (UNIT_TOLERANCE, decode_angle_deg())
    } else {
        (UNIT_TOLERANCE_CONFORMING, decode_angle_conforming_deg())
    };
    assert!(
        d.max_len_error <= unit && d.max_angle_deg.is_finite() && (!like || d.not_unit == 0),
        "{name}: |len − 1| up to {:e} ({} results beyond UNIT_TOLERANCE), budget {unit:e} \
         (sweep::normal::UNIT_TOLERANCE, or sweep::conforming::UNIT_TOLERANCE_CONFORMING \
         where the adapter does not evaluate like the twins), or a non-finite result",
        d.max_len_error,
        d.not_unit
    );
    prepass::assert_within!(
        d.max_angle_deg,
        angle,
        "sweep::normal::decode_angle_deg (the final quotient's rounding, √2·2^-24 rad), or \
         sweep::conforming::decode_angle_conforming_deg (its 2.5 ULP, √2·5·2^-24 rad) where \
         the adapter does not evaluate like the twins; + 1e-12° for the f64 angle",
        "{name}: max angle to the exact direction, degrees"
    );
    if like {
        assert_eq!(
            d.twin.count, 0,
            "{name}: Rust decoder differs: {:?}",
            d.twin.first
        );
    }
}

/// Replace (with `PREPASS_WRITE_DOCS=1`, as `bash .ci/docs` runs) or check the text between
/// `<!-- generated:NAME:begin -->` and `<!-- generated:NAME:end -->` in `path` (relative to the
/// repository). Checking FAILS when the committed block differs, naming the command that
/// regenerates it: published figures are never typed by hand.
#[allow(dead_code)]
pub fn publish(path: &str, name: &str, body: &str) {
    publish_block(path, name, body, None);
}

/// The README's tables give an encoding's precise encoder and its rounding one (`_fast`) in one
/// row: each row name without " fast" with the index of its `fast` sibling (the same name with
/// " fast" after the encoding, e.g. "oct24 fast" or "oct24 fast, vouched input"), in the
/// precise rows' order.
#[allow(dead_code)]
pub fn precise_with_fast(names: &[&str]) -> Vec<(usize, Option<usize>)> {
    let base = |n: &str| n.replacen(" fast", "", 1);
    names
        .iter()
        .enumerate()
        .filter(|(_, n)| !n.contains(" fast"))
        .map(|(i, n)| {
            let fast = names
                .iter()
                .position(|m| m.contains(" fast") && base(m) == **n);
            (i, fast)
        })
        .collect()
}

/// `a`, or `a · b` when the row has a `fast` sibling's figure `b` ([`precise_with_fast`]).
#[allow(dead_code)]
pub fn with_fast(a: String, b: Option<String>) -> String {
    match b {
        Some(b) => format!("{a} · {b}"),
        None => a,
    }
}

/// [`publish`] for a block measured on the adapter: the block records the adapter and driver it
/// was measured on (an HTML comment, invisible in the rendered page), and its text is compared
/// only on that adapter and driver. On any other (another Mesa, a user's GPU) the differences are
/// printed beside the published figures and the check passes: the caller asserts every figure
/// against its bound, which is the promise that must hold everywhere.
#[allow(dead_code)]
pub fn publish_measured(path: &str, name: &str, body: &str) {
    publish_block(path, name, body, Some(measured_on()));
}

/// [`publish_measured`] for a block measured on several implementations, named by `on`.
#[allow(dead_code)]
pub fn publish_on(path: &str, name: &str, body: &str, on: &str) {
    publish_block(
        path,
        name,
        body,
        Some(format!("<!-- measured on: {on} -->\n")),
    );
}

/// Whether this adapter and driver are the ones the README's measured figures were published
/// from (its `<!-- measured on: … -->` line names them).
#[allow(dead_code)]
pub fn is_publishing_adapter() -> bool {
    let readme = std::fs::read_to_string(format!("{}/README.md", env!("CARGO_MANIFEST_DIR")))
        .expect("README.md");
    readme.contains(&measured_on())
}

/// The first line of a measured block: the adapter's name and driver.
#[allow(dead_code)]
pub fn measured_on() -> String {
    let i = gpu().adapter_info();
    format!(
        "<!-- measured on: {} ({:?}, {}) -->\n",
        i.name, i.backend, i.driver_info
    )
}

/// The comment lines that open and close the generated block `name`.
fn block_markers(name: &str) -> (String, String) {
    (
        format!("<!-- generated:{name}:begin -->"),
        format!("<!-- generated:{name}:end -->"),
    )
}

/// The committed text of block `name` in `path` (from its opening marker to its closing one),
/// or `None` where the file has no such block.
fn committed_block(path: &str, name: &str) -> Option<String> {
    let text = std::fs::read_to_string(format!("{}/{path}", env!("CARGO_MANIFEST_DIR"))).ok()?;
    let (b, e) = block_markers(name);
    let (i, j) = text.find(&b).zip(text.find(&e))?;
    Some(text[i..j].to_string())
}

fn publish_block(path: &str, name: &str, body: &str, measured: Option<String>) {
    static FILES: std::sync::Mutex<()> = std::sync::Mutex::new(());
    let _g = FILES.lock().unwrap_or_else(|e| e.into_inner());
    let full = format!("{}/{path}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&full).unwrap_or_default();
    let (b, e) = block_markers(name);
    let block = format!("{b}\n{}{body}{e}", measured.as_deref().unwrap_or(""));
    let found = text.find(&b).zip(text.find(&e));
    if std::env::var_os("PREPASS_WRITE_DOCS").is_some() {
        let new = match found {
            Some((i, j)) => format!("{}{block}{}", &text[..i], &text[j + e.len()..]),
            None => format!("{text}\n{block}\n"),
        };
        std::fs::write(&full, new).unwrap();
        return;
    }
    let current = found.map(|(i, j)| &text[i..j + e.len()]);
    if let (Some(here), Some(committed)) = (&measured, current)
        && !committed.contains(here.as_str())
    {
        let published = committed.lines().nth(1).unwrap_or("(no adapter line)");
        eprintln!(
            "{path}, block `{name}`: published from another adapter ({published}); \
             compared with its bounds only. Published, then this adapter's:\n{committed}\n{block}"
        );
        return;
    }
    assert_eq!(
        current,
        Some(block.as_str()),
        "{path}, block `{name}`, differs from what the tests compute on the adapter it was \
         published from: run `bash .ci/docs` to regenerate it"
    );
}

/// The line naming the adapter that every published table starts with.
#[allow(dead_code)]
pub fn adapter_line() -> String {
    let i = gpu().adapter_info();
    format!("Measured on {} ({}).\n", i.name, i.driver_info)
}

#[allow(dead_code)]
/// The fuzz corpora (`fuzz/corpus/*/*`: the inputs libFuzzer kept, full of NaN, ±∞, subnormal
/// and huge bit patterns) as argument bits for a function with parameters of `words` words each:
/// the bytes after the first (which picks a fuzz entry) read as little-endian words, lane after
/// lane, zeros past the end. One argument set per corpus file, in file-name order.
pub fn corpus_args(words: &[usize]) -> Vec<Vec<u32>> {
    static FILES: std::sync::OnceLock<Vec<Vec<u8>>> = std::sync::OnceLock::new();
    let files = FILES.get_or_init(|| {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/corpus");
        let mut paths = Vec::new();
        for dir in std::fs::read_dir(&root).expect("fuzz/corpus") {
            for f in std::fs::read_dir(dir.unwrap().path()).unwrap() {
                paths.push(f.unwrap().path());
            }
        }
        paths.sort();
        paths.iter().map(|p| std::fs::read(p).unwrap()).collect()
    });
    let mut columns = vec![Vec::new(); words.len()];
    for bytes in files {
        let mut word = bytes.get(1..).unwrap_or(&[]).chunks(4).map(|c| {
            let mut b = [0u8; 4];
            b[..c.len()].copy_from_slice(c);
            u32::from_le_bytes(b)
        });
        for (col, &w) in columns.iter_mut().zip(words) {
            col.extend((0..w).map(|_| word.next().unwrap_or(0)));
        }
    }
    columns
}

/// One progress line for long work (a sweep over the stiff grid, thousands of modules), so a
/// person watching `bash .ci/test` sees what runs and how far it is. Written straight to the
/// process's stderr — the test harness captures only the print macros — when a label is first
/// seen, then at most every 10 s, and when `done` reaches `total`.
#[allow(dead_code)]
pub fn progress(label: &str, done: usize, total: usize) {
    use std::collections::BTreeMap;
    use std::sync::Mutex;
    use std::time::{Duration, Instant};
    // Per label: when it was first seen, and when a line was last written.
    static SEEN: Mutex<BTreeMap<String, (Instant, Instant)>> = Mutex::new(BTreeMap::new());
    let now = Instant::now();
    let mut seen = SEEN.lock().unwrap_or_else(|e| e.into_inner());
    let entry = seen
        .entry(label.to_string())
        .or_insert((now, now - Duration::from_secs(60)));
    if done < total && now - entry.1 < Duration::from_secs(10) {
        return;
    }
    entry.1 = now;
    let started = entry.0;
    let line = format!(
        "  … {label}: {done}/{total} ({:.0} %, {:.0} s)\n",
        100.0 * done as f64 / total.max(1) as f64,
        (now - started).as_secs_f64()
    );
    uncaptured(&line);
}

/// Write `text` to stderr past libtest's capture (which takes only `print!` and `eprint!`),
/// so that a passing test's line still reaches the caller: progress, and the figures
/// `.ci/timings` reads (`codec cost:`).
pub fn uncaptured(text: &str) {
    use std::io::Write as _;
    let _ = std::io::stderr().write_all(text.as_bytes());
}

/// A published "slots read" cell: the fewest and most direction-table slots a searched
/// evaluation read, and whether every input was searched exhaustively.
#[allow(dead_code)]
pub fn slots_cell((least, most, exhaustive): (u32, u32, bool)) -> String {
    let how = if exhaustive { "exhaustive" } else { "climbed" };
    format!("{least}–{most}, {how}")
}

/// Whether the full-strength run was asked for (`PREPASS_FULL=1 bash .ci/test`, CONTRIBUTING.md):
/// the tests that sample where a sample proves the same bound (each says why) then run every
/// case instead.
#[allow(dead_code)]
pub fn full_strength() -> bool {
    tier::tier() == tier::Tier::Full
}

/// The `Scene` of `examples/deferred_minimal/main.rs`, as the example builds it (oct24 normals,
/// reversed-Z infinite `Depth32Float`, view-space positions). The example keeps its own copy so
/// it reads whole; the tests that read its modules take this one.
#[allow(dead_code)]
pub fn deferred_minimal_scene() -> prepass::scene::Scene {
    use prepass::projection::DepthConvention;
    use prepass::scene::*;
    Scene {
        depth: DepthChoice {
            storage: DepthStorage::Float32,
            convention: DepthConvention::Reversed,
            infinite_far: true,
        },
        normal: NormalChoice {
            encoding: Some(NormalEncoding::Oct24),
            fast_encoder: false,
        },
        position: PositionChoice::View,
        ..Scene::default()
    }
}

/// `n` random vectors in the cube [−1, 1]^3 and `n` vectors of random f32 bit patterns (every
/// exponent, NaN and infinities included), from one seeded `sweep::SplitMix` stream: the
/// random sets the old-encoder comparisons run over.
#[allow(dead_code)]
pub fn random_cube_and_bits(seed: u64, n: usize) -> (Vec<[f32; 3]>, Vec<[f32; 3]>) {
    let mut rng = prepass::sweep::SplitMix(seed);
    let unit = |x: u64| (x >> 40) as f32 / (1u64 << 23) as f32 - 1.0;
    let (mut cube, mut raw) = (Vec::with_capacity(n), Vec::with_capacity(n));
    for _ in 0..n {
        let w = [rng.next_u64(), rng.next_u64()];
        cube.push([unit(w[0]), unit(w[0] << 24), unit(w[1])]);
        raw.push([w[0] as u32, (w[0] >> 32) as u32, w[1] as u32].map(f32::from_bits));
    }
    (cube, raw)
}

/// The precise encoders' score before issue 21, verbatim (`normal::sin2_to` of that time):
/// `|s × D|² / |D|²` with `|D|²` summed exactly in u32 and converted once, the cross product
/// and the dot `(x·x + y·y) + z·z` rounded per operation, no fusion. The old-encoder
/// references of `tests/normal_oct.rs` and `tests/normal_hemioct.rs` score with it.
#[allow(dead_code)]
pub fn old_sin2_to(s: glam::Vec3, d: glam::IVec3) -> f32 {
    let ad = d.abs().as_uvec3();
    let len2 = (ad.x * ad.x + ad.y * ad.y + ad.z * ad.z) as f32;
    let d = d.as_vec3();
    let x = glam::Vec3::new(
        s.y * d.z - s.z * d.y,
        s.z * d.x - s.x * d.z,
        s.x * d.y - s.y * d.x,
    );
    ((x.x * x.x + x.y * x.y) + x.z * x.z) / len2
}

/// Whether this adapter evaluates the operations the normal codecs' Rust twins mirror as they
/// do, so the twins' bit-identity promise applies: a probe kernel computes, on 2^16 seeded
/// inputs, the precise encoders' score `dot(cross(s, d), cross(s, d)) / q` (scaled inputs,
/// integer directions up to 65,535, integer `|D|²` up to 2^32), the decoders' `normalize` of an
/// integer vector, and a quotient of two floats, and each must equal the twins' rule bit for
/// bit (each product, difference and sum rounded to nearest, no fusion, `(x·x + y·y) + z·z`,
/// `v / sqrt(v·v)`, correctly rounded quotients), as on lavapipe. The twins promise
/// bit-identical codes and vectors on such an adapter only; on another conforming one (a fused
/// cross product, a 2.5-ULP division, `inverseSqrt` in `normalize`) they promise a code within
/// one step, near-ties decided within the conforming slack, and decodes within the conforming
/// budgets.
#[allow(dead_code)]
pub fn evaluates_like_the_twins() -> bool {
    static R: OnceLock<bool> = OnceLock::new();
    *R.get_or_init(|| {
        const PROBE: &str = "fn probe(s: vec3<f32>, d: vec3<f32>, q: f32) -> vec4<f32> {\n    \
                             let x = cross(s, d);\n    \
                             let n = normalize(d);\n    \
                             return vec4<f32>(dot(x, x) / q, n.x, n.y, s.x / q);\n}\n";
        let mut rng = prepass::sweep::SplitMix(0x5c0e);
        let n = 1 << 16;
        let (mut ss, mut ds, mut qs) = (Vec::new(), Vec::new(), Vec::new());
        for _ in 0..n {
            ss.push([(); 3].map(|_| rng.range(-4.0, 4.0)));
            ds.push([(); 3].map(|_| (rng.next_u64() % 131_071) as f32 - 65_535.0));
            qs.push((rng.next_u64() >> 32).max(1) as f32);
        }
        let args = [Arg::column(&ss), Arg::column(&ds), Arg::column(&qs)];
        let out = run_kernel(PROBE, "probe", &args, n as u64);
        let same = (0..n).all(|i| {
            let (s, d) = (glam::Vec3::from(ss[i]), glam::Vec3::from(ds[i]));
            let x = glam::Vec3::new(
                s.y * d.z - s.z * d.y,
                s.z * d.x - s.x * d.z,
                s.x * d.y - s.y * d.x,
            );
            let score = ((x.x * x.x + x.y * x.y) + x.z * x.z) / qs[i];
            let unit = d / ((d.x * d.x + d.y * d.y) + d.z * d.z).sqrt();
            let twin = [score, unit.x, unit.y, s.x / qs[i]];
            let got = out.as_vec4()[i];
            (0..4).all(|k| twin[k].to_bits() == got[k].to_bits())
        });
        if !same {
            eprintln!(
                "this adapter evaluates cross/dot/normalize/division other than the Rust twins \
                 (fused or not correctly rounded): normal codes and decodes are held to the \
                 twins' conforming promises (one code step, the conforming budgets and \
                 optimality slack), not to bit identity"
            );
        }
        same
    })
}

/// Of a promise's two bounds, the one that applies to this adapter, with its name: the
/// correctly rounded one where the adapter evaluates like the twins
/// ([`evaluates_like_the_twins`]: round to nearest, correctly rounded quotients), the bound on
/// every conforming adapter elsewhere.
#[allow(dead_code)]
pub fn bound_here(correctly_rounded: f64, conforming: f64) -> (f64, &'static str) {
    if evaluates_like_the_twins() {
        (correctly_rounded, "correctly rounded")
    } else {
        (
            conforming,
            "every conforming adapter (this one does not evaluate like the twins)",
        )
    }
}

/// The precise encoder `c` over near-tie `inputs`: the WGSL's codes equal the Rust twin's bit
/// for bit where the adapter evaluates like the twins ([`evaluates_like_the_twins`], lavapipe);
/// elsewhere each code is within the conforming slack
/// `sweep::conforming::optimality_tolerance_conforming_deg` of the closest candidate.
#[allow(dead_code)]
pub fn assert_near_ties(c: &prepass::sweep::normal::Codec, inputs: &[[f32; 3]]) {
    use prepass::sweep::conforming::optimality_tolerance_conforming_deg;
    use prepass::sweep::normal::{precise_optimality, round_trip};
    let rt = round_trip(gpu(), c, inputs).unwrap();
    eprintln!("{}: {} near-tie inputs", c.name, inputs.len());
    if evaluates_like_the_twins() {
        assert_round_trip_matches_twins(&format!("{} near ties", c.name), c, inputs, &rt);
    } else {
        let o = precise_optimality(c, inputs, &rt);
        prepass::assert_within!(
            o.worst_excess_deg,
            optimality_tolerance_conforming_deg(),
            "sweep::conforming::optimality_tolerance_conforming_deg: the conforming slack",
            "{} near ties: input {}, degrees worse than its best neighbour",
            c.name,
            o.argworst
        );
    }
}

/// The octahedral codecs (`prepass::sweep::normal::CODECS`' names), each with a vouched-input
/// form ([`vouched_codec`]).
#[allow(dead_code)]
pub const OCTAHEDRAL: [&str; 6] = [
    "oct16",
    "oct16 fast",
    "oct24",
    "oct24 fast",
    "oct32",
    "oct32 fast",
];

/// The hemi-octahedral codecs, each with a vouched-input form ([`vouched_codec`]; the contract
/// `prepass::normal::hemioct::is_vouched`).
#[allow(dead_code)]
pub const HEMIOCTAHEDRAL: [&str; 2] = ["hemioct24", "hemioct24 fast"];

/// The vouched encoders as codecs: the robust codec `name` with its encoder (WGSL and twin)
/// swapped for the vouched form, the decoder, references and targets kept (the vouched code is
/// the robust one inside the contract, so the same targets hold).
#[allow(dead_code)]
pub fn vouched_codec(name: &str) -> prepass::sweep::normal::Codec {
    let mut c = *prepass::sweep::normal::codec(name);
    let (vname, enc, twin): (&'static str, &'static str, fn(glam::Vec3) -> u32) = match name {
        "oct16" => (
            "oct16 vouched",
            "encode_normal_oct16_vouched",
            prepass::normal::oct::encode_normal_oct16_vouched,
        ),
        "oct16 fast" => (
            "oct16 vouched fast",
            "encode_normal_oct16_fast_vouched",
            prepass::normal::oct::encode_normal_oct16_fast_vouched,
        ),
        "oct24" => (
            "oct24 vouched",
            "encode_normal_oct24_vouched",
            prepass::normal::oct::encode_normal_oct24_vouched,
        ),
        "oct24 fast" => (
            "oct24 vouched fast",
            "encode_normal_oct24_fast_vouched",
            prepass::normal::oct::encode_normal_oct24_fast_vouched,
        ),
        "oct32" => (
            "oct32 vouched",
            "encode_normal_oct32_vouched",
            prepass::normal::oct::encode_normal_oct32_vouched,
        ),
        "oct32 fast" => (
            "oct32 vouched fast",
            "encode_normal_oct32_fast_vouched",
            prepass::normal::oct::encode_normal_oct32_fast_vouched,
        ),
        "hemioct24" => (
            "hemioct24 vouched",
            "encode_normal_hemioct24_vouched",
            prepass::normal::hemioct::encode_normal_hemioct24_vouched,
        ),
        "hemioct24 fast" => (
            "hemioct24 vouched fast",
            "encode_normal_hemioct24_fast_vouched",
            prepass::normal::hemioct::encode_normal_hemioct24_fast_vouched,
        ),
        _ => panic!("{name} has no vouched form"),
    };
    c.name = vname;
    c.encode = enc;
    c.twin_encode = twin;
    c
}

/// Inside their contract the vouched encoders of the robust codecs `names` return the robust
/// codes bit for bit, over `inputs` (all inside the contract): the Rust twins always, and the
/// WGSL on the adapter where it evaluates like the twins (the correctly rounded case the
/// identity is promised for); elsewhere the adapter's mismatches are only counted and printed.
#[allow(dead_code)]
pub fn assert_vouched_codes_are_the_robust_ones(names: &[&str], inputs: &[[f32; 3]]) {
    use prepass::harness::Arg;
    let like = evaluates_like_the_twins();
    for &name in names {
        let robust = prepass::sweep::normal::codec(name);
        let v = vouched_codec(name);
        let run = |f: &str| {
            gpu()
                .kernel(robust.source, f)
                .unwrap()
                .run(&[Arg::column(inputs)], inputs.len() as u64)
                .unwrap()
                .into_words()
        };
        let (want, got) = (run(robust.encode), run(v.encode));
        let mut wrong = 0;
        for (i, &n) in inputs.iter().enumerate() {
            let (rt, vt) = ((robust.twin_encode)(n.into()), (v.twin_encode)(n.into()));
            assert_eq!(vt, rt, "{}: twin differs from {name}'s on {n:?}", v.name);
            if got[i] != want[i] {
                wrong += 1;
                assert!(
                    !like,
                    "{}: WGSL code {:#x} differs from {}'s {:#x} on {n:?}",
                    v.name, got[i], robust.encode, want[i]
                );
            }
        }
        eprintln!(
            "{}: {wrong} of {} codes differ from {}'s on the adapter (evaluates like the twins: {like})",
            v.name,
            inputs.len(),
            robust.encode
        );
    }
}

/// The round trip of a per-channel (linear) normal codec over the tier's Fibonacci directions
/// ([`tier::fibonacci_set`]: 2^20, 2^24 in the full tier) and the adversarial set: the twins' promise ([`assert_round_trip_matches_twins`]), no NaN, no bit
/// outside `code_mask`, and the max angle within the derived `bound_deg` (named `bound`) plus
/// `normal::F32_SLACK_DEG`. Returns the Fibonacci round trip for further checks.
#[allow(dead_code)]
pub fn assert_linear_round_trip(
    name: &str,
    code_mask: u32,
    bound_deg: f64,
    bound: &str,
) -> prepass::sweep::normal::RoundTrip {
    use prepass::sweep::normal::{adversarial_directions, round_trip};
    let c = prepass::sweep::normal::codec(name);
    let mut fib = None;
    for (set, inputs) in [
        tier::fibonacci_set(),
        ("adversarial".to_string(), adversarial_directions()),
    ] {
        let set = set.as_str();
        let rt = round_trip(gpu(), c, &inputs).unwrap();
        eprintln!(
            "{name} {set}: mean {:.6}° max {:.6}° (bound {bound_deg:.4}°)",
            rt.error.mean(),
            rt.error.max
        );
        assert_round_trip_matches_twins(set, c, &inputs, &rt);
        assert_eq!(rt.error.nan_count, 0, "{name} {set}: NaN round trips");
        assert!(
            rt.codes.iter().all(|p| p & !code_mask == 0),
            "{name} {set}: bits outside {code_mask:#x} set"
        );
        prepass::assert_within!(
            rt.error.max,
            bound_deg + prepass::normal::F32_SLACK_DEG,
            format!("{bound} + normal::F32_SLACK_DEG"),
            "{name} {set}: max degrees at input {}",
            rt.error.argmax
        );
        fib.get_or_insert(rt);
    }
    fib.expect("two sets")
}

/// A Rust render-target encoder: the channels a normal writes.
#[allow(dead_code)]
pub type RenderEncode = fn(glam::Vec3) -> [f32; 4];
/// A Rust render-target decoder: the normal sampled channels give.
#[allow(dead_code)]
pub type RenderDecode = fn([f32; 4]) -> glam::Vec3;

/// A codec's WGSL render-target form for `target` (`rgb10a2unorm`, `rgba8snorm`) agrees bit for
/// bit with its code path on the adapter over [`render_target_inputs`]
/// (`prepass::sweep::normal::render_target_forms`), and the Rust form with the Rust code path.
#[allow(dead_code)]
pub fn assert_render_target_form(
    name: &str,
    (encode_rt, decode_rt): (&str, &str),
    target: prepass::sweep::normal::RenderTarget,
    twins: (RenderEncode, RenderDecode),
) {
    let inputs = render_target_inputs();
    let c = prepass::sweep::normal::codec(name);
    let f = prepass::sweep::normal::render_target_forms(
        gpu(),
        c,
        encode_rt,
        decode_rt,
        target,
        &inputs,
    )
    .unwrap();
    assert_eq!(f.encode.count, 0, "{encode_rt}: {:?}", f.encode.first);
    // Bound: 0. Every channel is within 0.45 of a step of the exact channel, so rounding it
    // back gives the code.
    assert_eq!(f.decode.count, 0, "{decode_rt}: {:?}", f.decode.first);
    assert_twin_unorm_form(&inputs, twins.0, twins.1, c.twin_encode, c.twin_decode);
}

/// Interop with an engine that writes the f32 channel values `channels(n)` of each unit input
/// to a target whose conversion is `round(scale·clamp(c))` (`signed`: snorm): the adapter's
/// codes of `name` over 2^20 Fibonacci directions equal the engine's lane by lane, except where
/// the engine's value lies within `sweep::normal::interop::RENORMALISE_CHANNEL` of a tie.
#[allow(dead_code)]
pub fn assert_writes_like_the_engine(
    name: &str,
    channels: fn([f32; 3]) -> [f32; 3],
    lanes: &[(u32, u32)],
    scale: f64,
    signed: bool,
) {
    use prepass::sweep::normal::interop::{RENORMALISE_CHANNEL, engine_write};
    let c = prepass::sweep::normal::codec(name);
    let inputs = prepass::sweep::normal::fibonacci_directions(1 << 20);
    let rt = prepass::sweep::normal::round_trip(gpu(), c, &inputs).unwrap();
    let (mut ties, mut differ) = (0u64, Vec::new());
    for (n, &p) in inputs.iter().zip(&rt.codes) {
        let engine = engine_write(channels(*n), scale, signed);
        for (e, &(shift, width)) in engine.iter().zip(lanes) {
            let field = (p >> shift) & ((1 << width) - 1);
            let ours = if signed {
                i64::from(((field << (32 - width)) as i32) >> (32 - width))
            } else {
                i64::from(field)
            };
            match e {
                None => ties += 1,
                Some(e) if *e != ours => differ.push((*n, p)),
                _ => {}
            }
        }
    }
    eprintln!("{name} interop: {ties} lanes within the tie window of {RENORMALISE_CHANNEL:e}");
    assert!(
        differ.is_empty(),
        "{name}: {} inputs where prepass writes another code than the engine's write, away from \
         a tie (window: sweep::normal::interop::RENORMALISE_CHANNEL); first {:?}",
        differ.len(),
        differ.first()
    );
}

/// The directions an engine-interop test writes (issue 60): 2^20 spherical-Fibonacci directions
/// first (so `[..1 << 20]` is that set), then the adversarial set (axes, folds, poles; its folds
/// lie on `|x| + |y| + |z| = 1`, not unit: an engine that writes unnormalised input sees them
/// shorter), circles with a zero x or y of either sign, and the band `|z| < 2^-10` (z = ±0,
/// ±2^-11, ±1e-6, ±1e-12) at 4,096 azimuths each.
#[allow(dead_code)]
pub fn interop_directions() -> Vec<[f32; 3]> {
    let mut dirs = prepass::sweep::normal::fibonacci_directions(1 << 20);
    dirs.extend(prepass::sweep::normal::adversarial_directions());
    let zs = [
        0.0f32,
        -0.0,
        1.0 / 2048.0,
        -1.0 / 2048.0,
        1e-6,
        -1e-6,
        1e-12,
        -1e-12,
    ];
    for k in 0..4096 {
        let (s, c) = (f64::from(k) * std::f64::consts::TAU / 4096.0).sin_cos();
        let (s, c) = (s as f32, c as f32);
        for zero in [0.0f32, -0.0] {
            dirs.push([zero, c, s]);
            dirs.push([c, zero, s]);
        }
        for z in zs {
            let r = (1.0 - f64::from(z).powi(2)).sqrt() as f32;
            dirs.push([c * r, s * r, z]);
        }
    }
    dirs
}

/// An engine's texels read by prepass's `decoder` (in `source`) on the adapter against the
/// engine's reader in f64 (`None`: no direction there, skipped): asserts every angle within
/// `sweep::normal::decode_angle_deg` (the decoder's rounding of the exact direction) and returns
/// the worst, in degrees. `what` names the decoder and the engine in a failure.
#[allow(dead_code)]
pub fn assert_reads_like_the_engine(
    source: &str,
    decoder: &str,
    texels: &[u32],
    engine: impl Fn(u32) -> Option<[f64; 3]>,
    what: &str,
) -> f64 {
    use prepass::precision::metrics::{angle_degrees, widen3};
    let got = run_kernel(source, decoder, &[Arg::column(texels)], texels.len() as u64);
    let worst = texels
        .iter()
        .zip(got.as_vec3())
        .filter_map(|(&p, &v)| engine(p).map(|u| angle_degrees(widen3(v), u)))
        .fold(0f64, f64::max);
    prepass::assert_within!(
        worst,
        prepass::sweep::normal::decode_angle_deg(),
        "sweep::normal::decode_angle_deg: the decoder's rounding of the exact direction",
        "{decoder} against {what}, {} texels, degrees",
        texels.len()
    );
    worst
}
