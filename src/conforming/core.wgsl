// prepass conforming-adapter emulation: the helper library that src/conforming/rewrite.rs calls
// in place of every f32 operation whose result WGSL does not pin. Conventions: README,
// "Conventions"; policy, host allowances and derivations: src/conforming/mod.rs.
//
// Every helper takes a `site` (a number unique to the rewritten expression) so that the seeded
// policy draws an independent choice per operation and per invocation (the operands' bits enter
// the hash). The PREPASS_CF_* constants are written in front of this text by the rewrite.
//
// The helpers rely on the host adapter rounding + - * to nearest, without contraction,
// reassociation or flushing (lavapipe does): the error-free transformations below (TwoSum,
// Dekker's product, Fast2Sum) need exactly that. The emulator self-tests check it.
//
// The helpers choose with `select` and the non-short-circuit `&` and `|` rather than `if`,
// `&&` and `||` wherever both sides are cheap and have no effect: every call is inlined, and
// lavapipe's pipeline build grows faster than the number of branches it inlines. Under the
// searched policy a choice computes both the seeded draw and the table's, and keeps one.
// Measured with PREPASS_LOG_COMPILES (lavapipe 22.3.6, GALLIVM_PERF=nopt): oct16's emulated
// round trip built in 11.7 s with branches, 5.6 s without; every_normal_encoding_under_emulation's
// 61 builds took 82-89 s, then 48 s.

var<private> prepass_cf_undefined: u32;

// Freedom bits (Freedoms in Rust).
const PREPASS_CF_DIVISION: u32 = 1u;
const PREPASS_CF_INVERSE_SQRT: u32 = 2u;
const PREPASS_CF_EXP_LOG: u32 = 4u;
const PREPASS_CF_UNPACK: u32 = 8u;
const PREPASS_CF_PACK: u32 = 16u;
const PREPASS_CF_ROUNDING: u32 = 32u;
const PREPASS_CF_FLUSH: u32 = 64u;
const PREPASS_CF_FUSION: u32 = 128u;
const PREPASS_CF_REASSOCIATION: u32 = 256u;
const PREPASS_CF_INHERITED: u32 = 512u;
const PREPASS_CF_CONVERSION: u32 = 1024u;
const PREPASS_CF_TRIG: u32 = 2048u;

// Mark the current evaluation as outside the spec's domain (indeterminate result): bit 1.
fn prepass_cf_undefined_if(c: bool) {
    prepass_cf_undefined = prepass_cf_undefined | select(0u, 1u, c);
}

// The same for an operation on a run-time ±Inf or NaN that no arithmetic helper sees (min, max,
// clamp, abs, floor, comparisons, the identity's builtins, an infinite or NaN unpack2x16float
// half, a float-to-integer conversion): bit 2, so a suite can tell these apart (EmulatedKernel::run_flags).
fn prepass_cf_operand_if(c: bool) {
    prepass_cf_undefined = prepass_cf_undefined | select(0u, 2u, c);
}

fn prepass_cf_hash(v: u32) -> u32 {
    var x = v;
    x = x ^ (x >> 16u);
    x = x * 0x7feb352du;
    x = x ^ (x >> 15u);
    x = x * 0x846ca68bu;
    x = x ^ (x >> 16u);
    return x;
}

// Under the searched policy the table wrappers' third argument, (mode, seed, 0, 0): mode 0
// reads the direction table, mode 1 is the seeded policy with that seed. One compiled module
// then serves upper, lower, every seed and the search.
var<private> prepass_cf_mode: vec4<u32>;

fn prepass_cf_seeded() -> bool {
    return (PREPASS_CF_POLICY == 3u) | ((PREPASS_CF_POLICY == 4u) & (prepass_cf_mode.x == 1u));
}

fn prepass_cf_rand(site: u32, x: f32, y: f32) -> u32 {
    let h = prepass_cf_hash(bitcast<u32>(x) ^ prepass_cf_hash(bitcast<u32>(y) + 0x9e3779b9u));
    let seed = select(PREPASS_CF_SEED, prepass_cf_mode.y, PREPASS_CF_POLICY == 4u);
    return prepass_cf_hash(seed ^ prepass_cf_hash(site ^ h));
}

// The direction table of the searched policy (PREPASS_CF_POLICY 4): one bit per slot, 1 = the
// upper end (or larger form), 0 = the lower; a site reads slot hash(site ^ context) % 256. The table
// wrappers the rewrite adds set it from their last two arguments, so one compiled module
// serves every table. prepass_cf_touched: the slots this evaluation read, for the search to
// enumerate only those. Each is eight words, slot >> 5 the word, held as two vec4 (words 0-3,
// 4-7) and reached with selects, never a run-time index: lavapipe turns each indexed access
// into branches. (Two levels, array<vec4<u32>, 2> with a run-time index into each, compiled
// the slot-mask pipeline of an emulated lighting function in 69 s instead of 17.5 s; a flat
// array<u32, 8> builds oct16's emulated round trip in 5.4 s, these selects in 4.9 s.)
var<private> prepass_cf_dirs_lo: vec4<u32>;
var<private> prepass_cf_dirs_hi: vec4<u32>;
var<private> prepass_cf_touched_lo: vec4<u32>;
var<private> prepass_cf_touched_hi: vec4<u32>;

// The call context: which call of a function this evaluation is in (the rewrite brackets every
// call of the module's own functions with enter and leave), so that each call of a helper
// reads its own table slots.
var<private> prepass_cf_ctx: u32;

fn prepass_cf_enter(k: u32) -> u32 {
    let saved = prepass_cf_ctx;
    prepass_cf_ctx = prepass_cf_hash(saved ^ k);
    return saved;
}

fn prepass_cf_leave(saved: u32) {
    prepass_cf_ctx = saved;
}

fn prepass_cf_table_dir(site: u32) -> i32 {
    let slot = prepass_cf_hash(site ^ prepass_cf_ctx) & 255u;
    // Called under the seeded mode too (the choice then keeps the draw): no slot is read there.
    let read = vec4<u32>(select(1u << (slot & 31u), 0u, prepass_cf_seeded()));
    let lo = vec4<u32>(slot >> 5u) == vec4<u32>(0u, 1u, 2u, 3u);
    let hi = vec4<u32>(slot >> 5u) == vec4<u32>(4u, 5u, 6u, 7u);
    prepass_cf_touched_lo = prepass_cf_touched_lo | select(vec4<u32>(0u), read, lo);
    prepass_cf_touched_hi = prepass_cf_touched_hi | select(vec4<u32>(0u), read, hi);
    let w = select(vec4<u32>(0u), prepass_cf_dirs_lo, lo) | select(vec4<u32>(0u), prepass_cf_dirs_hi, hi);
    let bit = (((w.x | w.y) | (w.z | w.w)) >> (slot & 31u)) & 1u;
    return select(-1, 1, bit == 1u);
}

// The identity test stands apart so that under the identity every call of this function is
// the constant false (src/conforming/fold.rs then drops the branches it guards).
fn prepass_cf_on(freedom: u32) -> bool {
    if (PREPASS_CF_POLICY == 0u) {
        return false;
    }
    return (PREPASS_CF_FREEDOMS & freedom) != 0u;
}

// Direction of a push inside an interval: +1 (upper end), -1 (lower end), seeded -1/0/+1, or
// the searched table's (policy 4 in mode 1: seeded).
fn prepass_cf_dir(freedom: u32, site: u32, x: f32, y: f32) -> i32 {
    if (!prepass_cf_on(freedom)) {
        return 0;
    }
    if (PREPASS_CF_POLICY == 1u) {
        return 1;
    }
    if (PREPASS_CF_POLICY == 2u) {
        return -1;
    }
    let seeded = i32(prepass_cf_rand(site, x, y) % 3u) - 1;
    if (PREPASS_CF_POLICY == 3u) {
        return seeded;
    }
    return select(prepass_cf_table_dir(site), seeded, prepass_cf_seeded());
}

// One of two allowed results: the larger (upper), the smaller (lower) or a seeded choice.
fn prepass_cf_pick(freedom: u32, site: u32, a: f32, b: f32) -> f32 {
    if (!prepass_cf_on(freedom)) {
        return a;
    }
    if (PREPASS_CF_POLICY == 1u) {
        return max(a, b);
    }
    if (PREPASS_CF_POLICY == 2u) {
        return min(a, b);
    }
    let seeded = select(a, b, (prepass_cf_rand(site ^ 0x5bd1e995u, a, b) & 1u) == 1u);
    if (PREPASS_CF_POLICY == 3u) {
        return seeded;
    }
    let table = select(min(a, b), max(a, b), prepass_cf_table_dir(site ^ 0x5bd1e995u) > 0);
    return select(table, seeded, prepass_cf_seeded());
}

fn prepass_cf_finite(x: f32) -> bool {
    return (bitcast<u32>(x) & 0x7f800000u) != 0x7f800000u;
}

// x, with the evaluation marked outside the domain where it is ±Inf or NaN: for the builtins the
// identity policy calls unchanged, whose operands pass through no prepass_cf_ftz.
fn prepass_cf_checked(x: f32) -> f32 {
    prepass_cf_operand_if(!prepass_cf_finite(x));
    return x;
}

fn prepass_cf_checked2(v: vec2<f32>) -> vec2<f32> {
    return vec2<f32>(prepass_cf_checked(v.x), prepass_cf_checked(v.y));
}

fn prepass_cf_checked3(v: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(prepass_cf_checked(v.x), prepass_cf_checked(v.y), prepass_cf_checked(v.z));
}

fn prepass_cf_checked4(v: vec4<f32>) -> vec4<f32> {
    return vec4<f32>(prepass_cf_checked2(v.xy), prepass_cf_checked2(v.zw));
}

fn prepass_cf_is_subnormal(x: f32) -> bool {
    let a = bitcast<u32>(x) & 0x7fffffffu;
    return (a != 0u) & (a < 0x00800000u);
}

// Largest finite float with x's sign in place of an infinity (no push may overflow).
fn prepass_cf_clamp_finite(x: f32) -> f32 {
    let largest = bitcast<f32>((bitcast<u32>(x) & 0x80000000u) | 0x7f7fffffu);
    return select(x, largest, (bitcast<u32>(x) & 0x7fffffffu) == 0x7f800000u);
}

// The adjacent float above (up) or below x; +0 and -0 count as one value.
fn prepass_cf_next(x: f32, up: bool) -> f32 {
    let b = bitcast<u32>(x);
    let away = select(b - 1u, b + 1u, ((b >> 31u) == 0u) == up);
    let smallest = select(0x80000001u, 1u, up);
    return bitcast<f32>(select(away, smallest, (b & 0x7fffffffu) == 0u));
}

// Exponent p of the spacing 2^p of the floats just below |x|. Any real that rounds to x (to
// either neighbour) has an ULP of at least 2^p, so a push counted in it stays inside the spec's
// k-ULP interval.
fn prepass_cf_spacing_exp_below(x: f32) -> i32 {
    let a = bitcast<u32>(x) & 0x7fffffffu;
    return max(i32((max(a, 1u) - 1u) >> 23u), 1) - 150;
}

// Exponent of the spacing between x and its neighbour n.
fn prepass_cf_pair_exp(x: f32, n: f32) -> i32 {
    let a = min(bitcast<u32>(x) & 0x7fffffffu, bitcast<u32>(n) & 0x7fffffffu);
    let sx = (bitcast<u32>(x) >> 31u) != (bitcast<u32>(n) >> 31u);
    if (sx) {
        return -149; // across zero: the smallest spacing
    }
    return max(i32(a >> 23u), 1) - 150;
}

// x moved by halves/2 ULPs (signed), float by float, never farther: the last float whose
// distance from x is within the budget. Integer bookkeeping only (quarters of the spacing below
// x), so no compiler identity such as (x + d) - x = d can change it. At most 1024 floats.
fn prepass_cf_push(x: f32, halves: i32) -> f32 {
    if ((halves == 0) | !prepass_cf_finite(x)) {
        return x;
    }
    let up = halves > 0;
    let budget = 2 * abs(halves);
    let base = prepass_cf_spacing_exp_below(x);
    var t = x;
    var spent = 0;
    for (var i = 0; i < 1024; i++) {
        let n = prepass_cf_next(t, up);
        if (!prepass_cf_finite(n)) {
            break;
        }
        let q = prepass_cf_pair_exp(t, n) - base + 2;
        if (q < 0) {
            // Below a quarter of the base spacing (deep into the subnormals): count a quarter.
            spent += 1;
        } else {
            spent += 1 << u32(min(q, 30));
        }
        if (spent > budget) {
            break;
        }
        t = n;
    }
    return t;
}

// A subnormal flushed to zero (keeping its sign) or kept: both are allowed for the operations
// of the accuracy table. Every helper passes its operands (and most their results) through
// here, so this is also where an operation on a run-time ±Inf or NaN leaves the domain, on
// every path: min, max, clamp, abs, floor and comparisons compute nothing that raises it.
fn prepass_cf_ftz(site: u32, x: f32) -> f32 {
    prepass_cf_operand_if(!prepass_cf_finite(x));
    if (!prepass_cf_is_subnormal(x)) {
        return x;
    }
    return prepass_cf_pick(PREPASS_CF_FLUSH, site, x, bitcast<f32>(bitcast<u32>(x) & 0x80000000u));
}

// x, through a value the host's compiler cannot see: prepass_cf_mode.z is 0, read at run time
// from the table wrappers' last argument in the searched module. The error-free
// transformations below pass their operands through it because SPIR-V does not mark them
// exact, and with a constant operand lavapipe's compiler rewrites them: Dekker's a*b - p for
// a = 1e-4, b = 16777215 (a literal) came out -1.3e-8 instead of +2.2e-5, and the push went
// the wrong way, one ULP beyond the spec (found by conforming::interval). Modules built by
// `emulate` alone never write prepass_cf_mode, so there a compiler may still fold.
fn prepass_cf_opaque(x: f32) -> f32 {
    return bitcast<f32>(bitcast<u32>(x) | prepass_cf_mode.z);
}

// Exact a*b - p for p = a*b rounded to nearest (Dekker), or 0 where the split could overflow or
// underflow: there the host's rounding, one allowed neighbour, stands.
fn prepass_cf_mul_err(a0: f32, b0: f32, p: f32) -> f32 {
    let a = prepass_cf_opaque(a0);
    let b = prepass_cf_opaque(b0);
    let ca = 4097.0 * a;
    let ah = ca - (ca - a);
    let al = a - ah;
    let cb = 4097.0 * b;
    let bh = cb - (cb - b);
    let bl = b - bh;
    let err = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
    return select(0.0, err, prepass_cf_mul_err_ok(a, b, p));
}

// The sign of a + b - s for s = a + b rounded to nearest (Knuth's TwoSum), as the exact error
// scaled by 2^64 where both operands are below 2^-60: scaling first (exact, and rounding
// commutes with it while the sum stays normal) keeps the error term out of the subnormals, so
// a host that flushes them still gets its sign. Subnormal sums are exact and need no error term.
fn prepass_cf_add_err_scaled(a0: f32, b0: f32, s0: f32) -> f32 {
    let k = select(1.0, bitcast<f32>(0x5f800000u), max(abs(a0), abs(b0)) < bitcast<f32>(0x21800000u));
    let a = prepass_cf_opaque(a0) * k;
    let b = prepass_cf_opaque(b0) * k;
    let s = s0 * k;
    let bb = s - a;
    let exact = !prepass_cf_finite(s0) | (abs(s0) < bitcast<f32>(0x00800000u));
    return select((a - (s - bb)) + (b - bb), 0.0, exact);
}

// Exact a + b - s (the scaled error scaled back: an f32 sum's error is always a float).
fn prepass_cf_add_err(a0: f32, b0: f32, s0: f32) -> f32 {
    let scaled = max(abs(a0), abs(b0)) < bitcast<f32>(0x21800000u);
    return prepass_cf_add_err_scaled(a0, b0, s0) * select(1.0, bitcast<f32>(0x1f800000u), scaled);
}

// s or its other neighbour across the exact value s + err: either rounding is allowed.
fn prepass_cf_round(site: u32, s: f32, err: f32, x: f32, y: f32) -> f32 {
    let dir = prepass_cf_dir(PREPASS_CF_ROUNDING, site, x, y);
    let other = ((dir > 0) & (err > 0.0)) | ((dir < 0) & (err < 0.0));
    return select(s, prepass_cf_clamp_finite(prepass_cf_next(s, err > 0.0)), other);
}

// a + b: flush choices on inputs and output, either neighbour of the exact sum.
fn prepass_cf_add(site: u32, a0: f32, b0: f32) -> f32 {
    let a = prepass_cf_ftz(site + 1u, a0);
    let b = prepass_cf_ftz(site + 2u, b0);
    let s = a + b;
    prepass_cf_undefined_if(!prepass_cf_finite(s));
    var r = s;
    if (prepass_cf_on(PREPASS_CF_ROUNDING)) {
        r = prepass_cf_round(site, s, prepass_cf_add_err_scaled(a, b, s), a, b);
    }
    return prepass_cf_ftz(site + 3u, r);
}

fn prepass_cf_sub(site: u32, a: f32, b: f32) -> f32 {
    return prepass_cf_add(site, a, -b);
}

// a * b: flush choices, either neighbour of the exact product.
fn prepass_cf_mul(site: u32, a0: f32, b0: f32) -> f32 {
    let a = prepass_cf_ftz(site + 1u, a0);
    let b = prepass_cf_ftz(site + 2u, b0);
    let p = a * b;
    prepass_cf_undefined_if(!prepass_cf_finite(p));
    var r = p;
    if (prepass_cf_on(PREPASS_CF_ROUNDING)) {
        r = prepass_cf_round(site, p, prepass_cf_mul_err(a, b, p), a, b);
    }
    return prepass_cf_ftz(site + 3u, r);
}

// ---- Results at the ends of their intervals, from exact references ----
// The helpers for /, inverseSqrt, exp, exp2, log, log2 and unpack*norm compute the exact
// result as an unevaluated sum hi + lo of two f32 (double-f32, from the error-free
// transformations above, accurate to far below one ULP of hi) and return the last float
// inside `exact ± allowance` in the chosen direction: the end of the spec interval itself, not
// the host's result pushed by the allowance less an assumed host error. Where a reference
// cannot be formed (a product beyond Dekker's range, an exp2 result below 2^-100, an exact 0),
// the push of the host's result stands (PREPASS_CF_*_HALVES, HostAccuracy in Rust).

// a + b as hi + lo, exactly (TwoSum). Never Fast2Sum's b - ((a + b) - a): Mesa's NIR applies
// its inexact algebraic rules to SPIR-V float operations without NoContraction and folds that
// to 0 (measured: every placed inverseSqrt and unpack off its end); the TwoSum in add_err reads
// its operands through a run-time scaling the rules cannot see through.
fn prepass_cf_two_sum(a: f32, b: f32) -> vec2<f32> {
    let s = prepass_cf_opaque(a) + prepass_cf_opaque(b);
    return vec2<f32>(s, prepass_cf_add_err(a, b, s));
}

// Whether prepass_cf_mul_err(a, b, p) is the exact error (not its out-of-range 0).
fn prepass_cf_mul_err_ok(a: f32, b: f32, p: f32) -> bool {
    let big = bitcast<f32>(0x5d800000u); // 2^60
    let small = bitcast<f32>(0x0d800000u); // 2^-100
    return (abs(a) < big) & (abs(b) < big) & (abs(p) > small) & prepass_cf_finite(p);
}

// x * y of two double-f32 values, to about 2^-44 relative (the lo*lo term and one rounding of
// the cross terms are lost).
fn prepass_cf_df_mul(x: vec2<f32>, y: vec2<f32>) -> vec2<f32> {
    let p = prepass_cf_opaque(x.x) * prepass_cf_opaque(y.x);
    let e = prepass_cf_mul_err(x.x, y.x, p) + (x.x * y.y + x.y * y.x);
    return prepass_cf_two_sum(p, e);
}

// x + y of two double-f32 values, to about 2^-44 relative where they do not cancel.
fn prepass_cf_df_add(x: vec2<f32>, y: vec2<f32>) -> vec2<f32> {
    let s = prepass_cf_two_sum(x.x, y.x);
    return prepass_cf_two_sum(s.x, s.y + (x.y + y.y));
}

// 2^p for p in [-126, 127].
fn prepass_cf_pow2(p: i32) -> f32 {
    return bitcast<f32>(u32(clamp(p, -126, 127) + 127) << 23u);
}

// Exponent p of one ULP (2^p) of the real value hi + lo, |hi| normal: the spacing of the floats
// around it; at a power of two, or just below one, the spacing below (WGSL's ULP of x is the
// smallest gap between floats a <= x <= b).
fn prepass_cf_ulp_exp(hi: f32, lo: f32) -> i32 {
    let a = bitcast<u32>(hi) & 0x7fffffffu;
    let ex = i32(a >> 23u);
    let below = ((a & 0x7fffffu) == 0u) & ((lo == 0.0) | ((lo < 0.0) == (hi > 0.0)));
    return max(select(ex, ex - 1, below), 1) - 150;
}

// k ULPs of hi + lo, less 2^-12 of itself. The margin (at least 2^-11 ULP, as k >= 2) covers
// each reference's own error (below 2^-17 ULP: the exp/log references are good to about 2^-40
// relative, the others to about 2^-44), so a placed result never leaves the interval; an end
// float closer than the margin to the interval's edge is given up for its neighbour. No margin
// where `exact` (a reference that is exact when its lo part is 0: the quotient and unpack,
// whose residuals are then 0) and lo is 0: an end lying on a float (an exact result
// and a whole number of ULPs) is reached, and the excess below is then computed exactly.
fn prepass_cf_ulp_budget(e: vec2<f32>, k: f32, exact: bool) -> f32 {
    let margin = select(1.0 - 1.0 / 4096.0, 1.0, exact & (e.y == 0.0));
    return k * margin * prepass_cf_pow2(prepass_cf_ulp_exp(e.x, e.y));
}

// How far t lies beyond distance `budget` from hi + lo on side dir (> 0: outside). Plain f32:
// its rounding is below 2^-23 of the budget, inside the 2^-12 margin every budget carries, so
// a t it calls inside is inside the spec's interval.
fn prepass_cf_excess(t: f32, e: vec2<f32>, budget: f32, dir: f32) -> f32 {
    return (dir * (prepass_cf_opaque(t) - e.x) - budget) - dir * e.y;
}

// The last float on side dir (+1 above, -1 below) whose distance from the exact e.x + e.y is
// within budget (absolute): the end of the interval exact ± budget. The guess
// t0 = e.x ± budget, rounded, is within one spacing of t0 of the edge (|e.y| is at most half a
// spacing of e.x), so the end is t0's outer neighbour, t0, or one or two floats inside it (two
// where t0 is a power of two and the floats inside it are twice as dense).
fn prepass_cf_place(e: vec2<f32>, budget: f32, dir: i32) -> f32 {
    let s = f32(dir);
    let t0 = prepass_cf_clamp_finite(e.x + s * budget);
    let out = prepass_cf_next(t0, dir > 0);
    let t1 = prepass_cf_next(t0, dir < 0);
    let t2 = prepass_cf_next(t1, dir < 0);
    let inner = select(t2, t1, prepass_cf_excess(t1, e, budget, s) <= 0.0);
    let within = select(inner, t0, prepass_cf_excess(t0, e, budget, s) <= 0.0);
    let reached = prepass_cf_finite(out) & (prepass_cf_excess(out, e, budget, s) <= 0.0);
    return select(within, out, reached);
}

// A result at the end of its k-ULP interval on side dir; the nearest float to the exact value
// where dir is 0 (the seeded policy's middle).
fn prepass_cf_place_ulp(e: vec2<f32>, k: f32, dir: i32, exact: bool) -> f32 {
    if (dir == 0) {
        return e.x + prepass_cf_opaque(e.y);
    }
    return prepass_cf_place(e, prepass_cf_ulp_budget(e, k, exact), dir);
}

// a / b within 2.5 ULP of the exact quotient q + r/b, r = a - q*b exactly (a - p is exact:
// p = q*b rounded is within a few ULPs of a). Outside Dekker's range the host's quotient
// (within DIV_HOST) is pushed by the rest of the budget. Divisors outside
// +-[2^-126, 2^126] make the result indeterminate.
fn prepass_cf_div(site: u32, a0: f32, b0: f32) -> f32 {
    let a = prepass_cf_ftz(site + 1u, a0);
    let b = prepass_cf_ftz(site + 2u, b0);
    prepass_cf_undefined_if(!((abs(b) >= bitcast<f32>(0x00800000u)) & (abs(b) <= bitcast<f32>(0x7e800000u))));
    let q = a / b;
    prepass_cf_undefined_if(!prepass_cf_finite(q));
    let dir = prepass_cf_dir(PREPASS_CF_DIVISION, site, a, b);
    if (dir == 0) {
        return prepass_cf_ftz(site + 3u, q);
    }
    let p = prepass_cf_opaque(q) * b;
    if ((abs(q) >= bitcast<f32>(0x0d800000u)) & prepass_cf_mul_err_ok(q, b, p)) {
        let r = (prepass_cf_opaque(a) - p) - prepass_cf_mul_err(q, b, p);
        let e = prepass_cf_two_sum(q, r / b);
        return prepass_cf_ftz(site + 3u, prepass_cf_place_ulp(e, 2.5, dir, true));
    }
    return prepass_cf_ftz(site + 3u, prepass_cf_push(q, dir * PREPASS_CF_DIV_HALVES));
}

// inverseSqrt(x) within 2 ULP; x <= 0, subnormal or infinite is outside the domain.
// The exact 1/sqrt(x) as hi + lo whatever the host's inverseSqrt does (lavapipe's is 1/sqrt,
// up to 1.44 ULP off): from y = sqrt(x) and r = 1/y, 1/sqrt(x) = r(1 + rr - ry/(2x)) to second
// order (about 2^-44), with the exact residuals rr = 1 - r*y and ry = x - y^2 (Dekker), which
// needs only a sqrt and a / within a few ULPs. x is scaled by 2^-+64 first so that no product
// overflows.
fn prepass_cf_inverse_sqrt_exact(x0: f32) -> vec2<f32> {
    var x = x0;
    var scale = 1.0;
    if (x0 > bitcast<f32>(0x5f800000u)) {
        x = x0 * bitcast<f32>(0x1f800000u);
        scale = bitcast<f32>(0x2f800000u);
    } else if (x0 < bitcast<f32>(0x1f800000u)) {
        x = x0 * bitcast<f32>(0x5f800000u);
        scale = bitcast<f32>(0x4f800000u);
    }
    let y = sqrt(x);
    let p = y * y;
    let ry = (x - p) - prepass_cf_mul_err(y, y, p);
    let r = 1.0 / y;
    let q = r * y;
    let rr = (1.0 - q) - prepass_cf_mul_err(r, y, q);
    return prepass_cf_two_sum(r, r * (rr - 0.5 * ry * r * r)) * scale;
}

fn prepass_cf_inverse_sqrt(site: u32, x0: f32) -> f32 {
    let x = prepass_cf_ftz(site + 1u, x0);
    prepass_cf_undefined_if(!((x >= bitcast<f32>(0x00800000u)) & (x <= bitcast<f32>(0x7f7fffffu))));
    let dir = prepass_cf_dir(PREPASS_CF_INVERSE_SQRT, site, x, x);
    if (dir == 0) {
        return prepass_cf_ftz(site + 3u, inverseSqrt(x));
    }
    return prepass_cf_ftz(site + 3u, prepass_cf_place_ulp(prepass_cf_inverse_sqrt_exact(x), 2.0, dir, false));
}

// sqrt(x) as the spec defines its accuracy: 1.0 / inverseSqrt(x). sqrt(+-0) stays 0: the
// inherited interval is unbounded there, and every implementation known returns 0.
fn prepass_cf_sqrt(site: u32, x: f32) -> f32 {
    if (!prepass_cf_on(PREPASS_CF_INHERITED)) {
        return sqrt(x);
    }
    if (x == 0.0) {
        return x;
    }
    return prepass_cf_div(site + 8u, 1.0, prepass_cf_inverse_sqrt(site, x));
}

// sin and cos: within 2^-11 absolute on [-pi, pi]; outside it the spec states no accuracy, so
// the result is indeterminate and the flag is raised. No exact reference: the host's result is
// pushed by the allowance less the host's error and the push's rounding (PREPASS_CF_TRIG_PUSH).
fn prepass_cf_trig_end(site: u32, x: f32, host: f32) -> f32 {
    prepass_cf_undefined_if(!(abs(x) <= PREPASS_CF_TRIG_DOMAIN));
    let dir = prepass_cf_dir(PREPASS_CF_TRIG, site, x, x);
    return prepass_cf_ftz(site + 3u, host + f32(dir) * PREPASS_CF_TRIG_PUSH);
}

fn prepass_cf_sin(site: u32, x0: f32) -> f32 {
    let x = prepass_cf_ftz(site + 1u, x0);
    return prepass_cf_trig_end(site, x, sin(x));
}

fn prepass_cf_cos(site: u32, x0: f32) -> f32 {
    let x = prepass_cf_ftz(site + 1u, x0);
    return prepass_cf_trig_end(site, x, cos(x));
}

// Budget of exp and exp2, 3 + 2|x| ULP, less the host's own error, in half ULPs (the push of
// the host's result, where no reference is formed).
fn prepass_cf_exp_halves(dir: i32, x: f32) -> i32 {
    let budget = 2.0 * (3.0 + 2.0 * min(abs(x), 1000.0)) - f32(PREPASS_CF_EXP_HOST_HALVES);
    return dir * i32(floor(max(budget, 0.0)));
}

// 2^(f + n) as hi + lo for |f| <= 0.5 (double-f32) and an integer n with a normal result:
// e^t, t = f*ln2 (|t| <= 0.35), is 1 + t(1 + t(1/2 + t(1/6 + t(1/24 + t*R(t))))) with the last
// four steps in double-f32 and R (terms 5 to 10) in f32; the first omitted term and R's
// rounding are below 2^-40 of the result.
fn prepass_cf_exp2_exact(f: vec2<f32>, n: f32) -> vec2<f32> {
    let t = prepass_cf_df_mul(f, vec2<f32>(bitcast<f32>(0x3f317218u), bitcast<f32>(0xb102e308u)));
    let z = t.x;
    let r = 1.0 / 120.0 + z * (1.0 / 720.0 + z * (1.0 / 5040.0 + z * (1.0 / 40320.0 + z * (1.0 / 362880.0 + z / 3628800.0))));
    var s = prepass_cf_df_add(vec2<f32>(bitcast<f32>(0x3d2aaaabu), bitcast<f32>(0xb0aaaaabu)), vec2<f32>(z * r, 0.0));
    s = prepass_cf_df_add(vec2<f32>(bitcast<f32>(0x3e2aaaabu), bitcast<f32>(0xb1aaaaabu)), prepass_cf_df_mul(t, s));
    s = prepass_cf_df_add(vec2<f32>(0.5, 0.0), prepass_cf_df_mul(t, s));
    s = prepass_cf_df_add(vec2<f32>(1.0, 0.0), prepass_cf_df_mul(t, s));
    s = prepass_cf_df_add(vec2<f32>(1.0, 0.0), prepass_cf_df_mul(t, s));
    // Two power-of-two steps: n may be 128 with a result below 2^128.
    let k = i32(n);
    return s * prepass_cf_pow2(k / 2) * prepass_cf_pow2(k - k / 2);
}

// An exponential within 3 + 2|x| ULP of its exact value e (hi + lo), or the host's result r
// pushed where there is no reference; dir is not 0 (the callers return r there).
fn prepass_cf_exp_end(dir: i32, x: f32, r: f32, e: vec2<f32>, exact: bool) -> f32 {
    if (!exact) {
        return prepass_cf_push(r, prepass_cf_exp_halves(dir, x));
    }
    return prepass_cf_place_ulp(e, 3.0 + 2.0 * abs(x), dir, false);
}

fn prepass_cf_exp2(site: u32, x0: f32) -> f32 {
    let x = prepass_cf_ftz(site + 1u, x0);
    let r = exp2(x);
    prepass_cf_undefined_if(!(x < 128.0) | !prepass_cf_finite(r));
    let dir = prepass_cf_dir(PREPASS_CF_EXP_LOG, site, x, x);
    if (dir == 0) {
        return prepass_cf_ftz(site + 3u, r);
    }
    // A reference where the result is at least 2^-100 (its lo part stays normal).
    let exact = (x >= -100.0) & (x < 128.0);
    let n = round(x);
    let e = prepass_cf_exp2_exact(vec2<f32>(prepass_cf_opaque(x) - n, 0.0), n);
    return prepass_cf_ftz(site + 3u, prepass_cf_exp_end(dir, x, r, e, exact));
}

fn prepass_cf_exp(site: u32, x0: f32) -> f32 {
    let x = prepass_cf_ftz(site + 1u, x0);
    let r = exp(x);
    prepass_cf_undefined_if(!(x < 88.0) | !prepass_cf_finite(r));
    let dir = prepass_cf_dir(PREPASS_CF_EXP_LOG, site, x, x);
    if (dir == 0) {
        return prepass_cf_ftz(site + 3u, r);
    }
    let exact = (x >= -69.0) & (x < 88.0);
    // x*log2(e) as hi + lo, split into n + f with |f| <= 0.5 (the subtraction of n is exact).
    let t = prepass_cf_df_mul(vec2<f32>(x, 0.0), vec2<f32>(bitcast<f32>(0x3fb8aa3bu), bitcast<f32>(0x32a57060u)));
    let n = round(t.x);
    let e = prepass_cf_exp2_exact(prepass_cf_two_sum(prepass_cf_opaque(t.x) - n, t.y), n);
    return prepass_cf_ftz(site + 3u, prepass_cf_exp_end(dir, x, r, e, exact));
}

// ln(x) (base2 false) or log2(x) of a normal positive finite x as hi + lo: x = m*2^k with m in
// [sqrt(1/2), sqrt(2)), ln m = 2 atanh(s), s = (m - 1)/(m + 1) (|s| <= 0.1716) in double-f32
// from the exact residual of the division, the series 2(s + s^3/3) in double-f32 and its
// terms s^5 to s^15 in f32 (at most 2^-12 of ln m, so their rounding is below 2^-33 of it); the
// first omitted term is below 2^-44.
fn prepass_cf_log_exact(x: f32, base2: bool) -> vec2<f32> {
    let b = bitcast<u32>(x);
    var k = f32(i32(b >> 23u) - 127);
    var m = bitcast<f32>((b & 0x7fffffu) | 0x3f800000u);
    if (m > bitcast<f32>(0x3fb504f3u)) {
        m = m * 0.5;
        k = k + 1.0;
    }
    let u = prepass_cf_opaque(m) - 1.0; // exact (Sterbenz)
    let v = prepass_cf_two_sum(m, 1.0);
    let sh = u / v.x;
    let p = prepass_cf_opaque(sh) * v.x;
    let res = ((u - p) - prepass_cf_mul_err(sh, v.x, p)) - sh * v.y;
    let s = prepass_cf_two_sum(sh, res / v.x);
    let z = s.x * s.x;
    let tail = s.x * z * z * (2.0 / 5.0 + z * (2.0 / 7.0 + z * (2.0 / 9.0 + z * (2.0 / 11.0 + z * (2.0 / 13.0 + z * (2.0 / 15.0))))));
    let s3 = prepass_cf_df_mul(prepass_cf_df_mul(s, s), s);
    let two_thirds = vec2<f32>(bitcast<f32>(0x3f2aaaabu), bitcast<f32>(0xb2aaaaabu));
    let ln_m = prepass_cf_df_add(prepass_cf_df_add(2.0 * s, prepass_cf_df_mul(s3, two_thirds)), vec2<f32>(tail, 0.0));
    if (base2) {
        let inv_ln2 = vec2<f32>(bitcast<f32>(0x3fb8aa3bu), bitcast<f32>(0x32a57060u));
        return prepass_cf_df_add(vec2<f32>(k, 0.0), prepass_cf_df_mul(ln_m, inv_ln2));
    }
    let ln2 = vec2<f32>(bitcast<f32>(0x3f317218u), bitcast<f32>(0xb102e308u));
    return prepass_cf_df_add(prepass_cf_df_mul(vec2<f32>(k, 0.0), ln2), ln_m);
}

// log and log2: absolute 2^-21 on [0.5, 2], 3 ULP elsewhere, of the exact value; x <= 0,
// subnormal or infinite is outside the domain (no reference is needed there: the result is
// indeterminate).
fn prepass_cf_log_end(site: u32, x: f32, r: f32, base2: bool) -> f32 {
    let dir = prepass_cf_dir(PREPASS_CF_EXP_LOG, site, x, x);
    // Two ifs, not `||`: naga lowers `||` through a local, which fold.rs does not follow.
    if (dir == 0) {
        return r;
    }
    if (!(x >= bitcast<f32>(0x00800000u) && x <= bitcast<f32>(0x7f7fffffu))) {
        return r;
    }
    let e = prepass_cf_log_exact(x, base2);
    if (x >= 0.5 && x <= 2.0) {
        return prepass_cf_place(e, bitcast<f32>(0x35000000u) * (1.0 - 1.0 / 4096.0), dir);
    }
    return prepass_cf_place_ulp(e, 3.0, dir, false);
}

fn prepass_cf_log2(site: u32, x0: f32) -> f32 {
    let x = prepass_cf_ftz(site + 1u, x0);
    prepass_cf_undefined_if(!((x >= bitcast<f32>(0x00800000u)) & (x <= bitcast<f32>(0x7f7fffffu))));
    return prepass_cf_ftz(site + 3u, prepass_cf_log_end(site, x, log2(x), true));
}

fn prepass_cf_log(site: u32, x0: f32) -> f32 {
    let x = prepass_cf_ftz(site + 1u, x0);
    prepass_cf_undefined_if(!((x >= bitcast<f32>(0x00800000u)) & (x <= bitcast<f32>(0x7f7fffffu))));
    return prepass_cf_ftz(site + 3u, prepass_cf_log_end(site, x, log(x), false));
}

// pow(x, y) as inherited: exp2(y * log2(x)).
fn prepass_cf_pow(site: u32, x: f32, y: f32) -> f32 {
    if (!prepass_cf_on(PREPASS_CF_INHERITED)) {
        return prepass_cf_checked(pow(prepass_cf_checked(x), prepass_cf_checked(y)));
    }
    return prepass_cf_exp2(site + 8u, prepass_cf_mul(site + 16u, y, prepass_cf_log2(site + 24u, x)));
}

// a*b + c rounded once, from error-free transformations (within one rounding of the exact
// value: what a fused multiply-add may return).
fn prepass_cf_fused(a: f32, b: f32, c: f32) -> f32 {
    let p = a * b;
    let ep = prepass_cf_mul_err(a, b, p);
    let s = p + c;
    let es = prepass_cf_add_err(p, c, s);
    return s + (es + ep);
}

// a*b + c, fused or not.
fn prepass_cf_mad(site: u32, a: f32, b: f32, c: f32) -> f32 {
    let unfused = prepass_cf_add(site, prepass_cf_mul(site + 8u, a, b), c);
    if (!prepass_cf_on(PREPASS_CF_FUSION)) {
        return unfused;
    }
    let fa = prepass_cf_ftz(site + 16u, a);
    let fb = prepass_cf_ftz(site + 17u, b);
    let fc = prepass_cf_ftz(site + 18u, c);
    return prepass_cf_pick(PREPASS_CF_FUSION, site + 19u, unfused, prepass_cf_fused(fa, fb, fc));
}

// a*b - c, fused or not.
fn prepass_cf_msub(site: u32, a: f32, b: f32, c: f32) -> f32 {
    let unfused = prepass_cf_sub(site, prepass_cf_mul(site + 8u, a, b), c);
    if (!prepass_cf_on(PREPASS_CF_FUSION)) {
        return unfused;
    }
    let fa = prepass_cf_ftz(site + 16u, a);
    let fb = prepass_cf_ftz(site + 17u, b);
    let fc = prepass_cf_ftz(site + 18u, c);
    return prepass_cf_pick(PREPASS_CF_FUSION, site + 19u, unfused, prepass_cf_fused(fa, fb, -fc));
}

// c - a*b, fused or not.
fn prepass_cf_nmad(site: u32, a: f32, b: f32, c: f32) -> f32 {
    let unfused = prepass_cf_sub(site, c, prepass_cf_mul(site + 8u, a, b));
    if (!prepass_cf_on(PREPASS_CF_FUSION)) {
        return unfused;
    }
    let fa = prepass_cf_ftz(site + 16u, a);
    let fb = prepass_cf_ftz(site + 17u, b);
    let fc = prepass_cf_ftz(site + 18u, c);
    return prepass_cf_pick(PREPASS_CF_FUSION, site + 19u, unfused, prepass_cf_fused(-fa, fb, fc));
}

// fma(a, b, c): inherited from a*b + c, so it may be fused or not.
fn prepass_cf_fma(site: u32, a: f32, b: f32, c: f32) -> f32 {
    if (!prepass_cf_on(PREPASS_CF_INHERITED)) {
        let r = fma(prepass_cf_checked(a), prepass_cf_checked(b), prepass_cf_checked(c));
        return prepass_cf_checked(r);
    }
    return prepass_cf_mad(site, a, b, c);
}

// (a + b) + c, or a + (b + c).
fn prepass_cf_add3(site: u32, a: f32, b: f32, c: f32) -> f32 {
    let left = prepass_cf_add(site, prepass_cf_add(site + 8u, a, b), c);
    if (!prepass_cf_on(PREPASS_CF_REASSOCIATION)) {
        return left;
    }
    let right = prepass_cf_add(site + 16u, a, prepass_cf_add(site + 24u, b, c));
    // The third grouping of three terms: (a + c) + b.
    let third = prepass_cf_add(site + 40u, prepass_cf_add(site + 48u, a, c), b);
    let two = prepass_cf_pick(PREPASS_CF_REASSOCIATION, site + 32u, left, right);
    return prepass_cf_pick(PREPASS_CF_REASSOCIATION, site + 56u, two, third);
}

// (a - b) + c, (a + c) - b, or a - (b - c).
fn prepass_cf_sub_add(site: u32, a: f32, b: f32, c: f32) -> f32 {
    let left = prepass_cf_add(site, prepass_cf_sub(site + 8u, a, b), c);
    if (!prepass_cf_on(PREPASS_CF_REASSOCIATION)) {
        return left;
    }
    let right = prepass_cf_sub(site + 16u, prepass_cf_add(site + 24u, a, c), b);
    let third = prepass_cf_sub(site + 40u, a, prepass_cf_sub(site + 48u, b, c));
    let two = prepass_cf_pick(PREPASS_CF_REASSOCIATION, site + 32u, left, right);
    return prepass_cf_pick(PREPASS_CF_REASSOCIATION, site + 56u, two, third);
}

// (a + b) - c, a + (b - c), or (a - c) + b.
fn prepass_cf_add_sub(site: u32, a: f32, b: f32, c: f32) -> f32 {
    let left = prepass_cf_sub(site, prepass_cf_add(site + 8u, a, b), c);
    if (!prepass_cf_on(PREPASS_CF_REASSOCIATION)) {
        return left;
    }
    let right = prepass_cf_add(site + 16u, a, prepass_cf_sub(site + 24u, b, c));
    let third = prepass_cf_add(site + 40u, prepass_cf_sub(site + 48u, a, c), b);
    let two = prepass_cf_pick(PREPASS_CF_REASSOCIATION, site + 32u, left, right);
    return prepass_cf_pick(PREPASS_CF_REASSOCIATION, site + 56u, two, third);
}

// (a - b) + x*y: fused or not, or reassociated to (a + x*y) - b.
fn prepass_cf_sub_add_mad(site: u32, a: f32, b: f32, x: f32, y: f32) -> f32 {
    let left = prepass_cf_mad(site, x, y, prepass_cf_sub(site + 40u, a, b));
    if (!prepass_cf_on(PREPASS_CF_REASSOCIATION)) {
        return left;
    }
    let right = prepass_cf_sub(site + 48u, prepass_cf_mad(site + 56u, x, y, a), b);
    return prepass_cf_pick(PREPASS_CF_REASSOCIATION, site + 80u, left, right);
}

// (a + b) + x*y: fused or not, or reassociated to a + (b + x*y).
fn prepass_cf_add3_mad(site: u32, a: f32, b: f32, x: f32, y: f32) -> f32 {
    let left = prepass_cf_mad(site, x, y, prepass_cf_add(site + 40u, a, b));
    if (!prepass_cf_on(PREPASS_CF_REASSOCIATION)) {
        return left;
    }
    let right = prepass_cf_add(site + 48u, a, prepass_cf_mad(site + 56u, x, y, b));
    return prepass_cf_pick(PREPASS_CF_REASSOCIATION, site + 80u, left, right);
}

// (a * b) / c, (a / c) * b, or a * (b / c).
fn prepass_cf_mul_div(site: u32, a: f32, b: f32, c: f32) -> f32 {
    let left = prepass_cf_div(site, prepass_cf_mul(site + 8u, a, b), c);
    if (!prepass_cf_on(PREPASS_CF_REASSOCIATION)) {
        return left;
    }
    let right = prepass_cf_mul(site + 16u, prepass_cf_div(site + 24u, a, c), b);
    let third = prepass_cf_mul(site + 40u, a, prepass_cf_div(site + 48u, b, c));
    let two = prepass_cf_pick(PREPASS_CF_REASSOCIATION, site + 32u, left, right);
    return prepass_cf_pick(PREPASS_CF_REASSOCIATION, site + 56u, two, third);
}

// fract(x) as inherited: x - floor(x).
fn prepass_cf_fract(site: u32, x: f32) -> f32 {
    if (!prepass_cf_on(PREPASS_CF_INHERITED)) {
        return fract(prepass_cf_checked(x));
    }
    return prepass_cf_sub(site, x, floor(x));
}

// mix(a, b, t) as inherited: a*(1 - t) + b*t.
fn prepass_cf_mix(site: u32, a: f32, b: f32, t: f32) -> f32 {
    if (!prepass_cf_on(PREPASS_CF_INHERITED)) {
        let r = mix(prepass_cf_checked(a), prepass_cf_checked(b), prepass_cf_checked(t));
        return prepass_cf_checked(r);
    }
    let left = prepass_cf_mul(site + 40u, a, prepass_cf_sub(site + 48u, 1.0, t));
    return prepass_cf_mad(site, b, t, left);
}

// v / (s2 - 1) exactly, as hi + lo, whatever the host's division does: the quotient q and its
// exact residual v - q*(s2 - 1) (Dekker; v - p is exact, p being within a few ULPs of v).
fn prepass_cf_unorm_exact(v: f32, s2: f32) -> vec2<f32> {
    let d = s2 - 1.0;
    let q = v / d;
    if (v == 0.0) {
        return vec2<f32>(q, 0.0);
    }
    let p = prepass_cf_opaque(q) * d;
    let r = (prepass_cf_opaque(v) - p) - prepass_cf_mul_err(q, d, p);
    return prepass_cf_two_sum(q, r / d);
}

// max(v / (s2 - 1), -1) exactly, as hi + lo.
fn prepass_cf_snorm_exact(v: f32, s2: f32) -> vec2<f32> {
    if (v <= 1.0 - s2) {
        return vec2<f32>(-1.0, 0.0);
    }
    return prepass_cf_unorm_exact(v, s2);
}

// An unpacked lane at the end of unpack's 3 ULP around its exact value; 0 stays 0 on the
// nearest side and is pushed into the subnormals by the rest of the budget elsewhere.
fn prepass_cf_unpack_lane(site: u32, e: vec2<f32>) -> f32 {
    let dir = prepass_cf_dir(PREPASS_CF_UNPACK, site, e.x, e.x);
    if (e.x == 0.0) {
        return prepass_cf_push(e.x, dir * PREPASS_CF_UNPACK_HALVES);
    }
    return prepass_cf_place_ulp(e, 3.0, dir, true);
}

fn prepass_cf_unpack4x8unorm(site: u32, p: u32) -> vec4<f32> {
    if (!prepass_cf_on(PREPASS_CF_UNPACK)) {
        return unpack4x8unorm(p);
    }
    var r: vec4<f32>;
    for (var i = 0u; i < 4u; i++) {
        r[i] = prepass_cf_unpack_lane(site + 8u * i, prepass_cf_unorm_exact(f32((p >> (8u * i)) & 0xffu), 256.0));
    }
    return r;
}

fn prepass_cf_unpack4x8snorm(site: u32, p: u32) -> vec4<f32> {
    if (!prepass_cf_on(PREPASS_CF_UNPACK)) {
        return unpack4x8snorm(p);
    }
    var r: vec4<f32>;
    for (var i = 0u; i < 4u; i++) {
        let v = bitcast<i32>(p << (24u - 8u * i)) >> 24u;
        r[i] = prepass_cf_unpack_lane(site + 8u * i, prepass_cf_snorm_exact(f32(v), 128.0));
    }
    return r;
}

fn prepass_cf_unpack2x16unorm(site: u32, p: u32) -> vec2<f32> {
    if (!prepass_cf_on(PREPASS_CF_UNPACK)) {
        return unpack2x16unorm(p);
    }
    var r: vec2<f32>;
    for (var i = 0u; i < 2u; i++) {
        r[i] = prepass_cf_unpack_lane(site + 8u * i, prepass_cf_unorm_exact(f32((p >> (16u * i)) & 0xffffu), 65536.0));
    }
    return r;
}

fn prepass_cf_unpack2x16snorm(site: u32, p: u32) -> vec2<f32> {
    if (!prepass_cf_on(PREPASS_CF_UNPACK)) {
        return unpack2x16snorm(p);
    }
    var r: vec2<f32>;
    for (var i = 0u; i < 2u; i++) {
        let v = bitcast<i32>(p << (16u - 16u * i)) >> 16u;
        r[i] = prepass_cf_unpack_lane(site + 8u * i, prepass_cf_snorm_exact(f32(v), 32768.0));
    }
    return r;
}

// floor(0.5 + t), exact for the |t| <= 65535 of pack's scaled lanes.
fn prepass_cf_round_half_up(t: f32) -> f32 {
    let f = floor(t);
    return f + select(0.0, 1.0, t - f >= 0.5);
}

// The integer a pack stores for lane c (already clamped) with scale 2^k - 1 = s2 - 1:
// floor(0.5 + (s2 - 1)*c) of either rounding of the product, which differ only at .5 ties.
// The rounding's direction comes from Fast2Sum, which a host compiler's algebraic rewrites can
// defeat (then only the host's byte is returned): used for snorm8 and the 16-bit packs, whose
// ties the self-tests do not reach; unorm8 has the integer path above.
fn prepass_cf_pack_lane(site: u32, c: f32, s2: f32) -> f32 {
    let hi = c * s2;
    let t = hi - c;
    let e = (-c) - (t - hi);
    var t2 = t;
    if (e != 0.0) {
        t2 = prepass_cf_next(t, e > 0.0);
    }
    return prepass_cf_pick(PREPASS_CF_PACK, site, prepass_cf_round_half_up(t), prepass_cf_round_half_up(t2));
}

// The byte of an unorm8 lane c in [0, 1], from integers only: the exact product 255*c is
// P*2^-shift with P = 255*mantissa (< 2^32), and the f32 intermediate the spec rounds first is P
// cut to 24 significant bits, rounded down or up; either byte floor(0.5 + that) is allowed.
fn prepass_cf_pack_unorm8_lane(site: u32, c: f32) -> u32 {
    let bits = bitcast<u32>(c);
    if (c <= 0.0 || (bits & 0x7f800000u) == 0u) {
        return 0u; // zero, negative or subnormal (255*c < 2^-118): byte 0 either way
    }
    let e = i32(bits >> 23u);
    let m = (bits & 0x007fffffu) | 0x00800000u;
    let shift = 150 - e;
    if (shift >= 33) {
        return 0u; // 255*c < 2^32 * 2^-33 = 0.5: byte 0 either way
    }
    let p = 255u * m;
    let drop = u32(max(0, 8 - i32(countLeadingZeros(p))));
    let down = (p >> drop) << drop;
    let up = select(down + (1u << drop), down, down == p);
    // floor(0.5 + P*2^-shift) = (floor(P*2^(1-shift)) + 1) / 2, with no carry out of 32 bits.
    let b_down = ((down >> u32(shift - 1)) + 1u) >> 1u;
    let b_up = ((up >> u32(shift - 1)) + 1u) >> 1u;
    return u32(prepass_cf_pick(PREPASS_CF_PACK, site, f32(b_down), f32(b_up)));
}

fn prepass_cf_pack4x8unorm(site: u32, v: vec4<f32>) -> u32 {
    if (!prepass_cf_on(PREPASS_CF_PACK)) {
        return pack4x8unorm(v);
    }
    var r = 0u;
    for (var i = 0u; i < 4u; i++) {
        let b = prepass_cf_pack_unorm8_lane(site + 8u * i, clamp(v[i], 0.0, 1.0));
        r = r | (min(b, 255u) << (8u * i));
    }
    return r;
}

fn prepass_cf_pack4x8snorm(site: u32, v: vec4<f32>) -> u32 {
    if (!prepass_cf_on(PREPASS_CF_PACK)) {
        return pack4x8snorm(v);
    }
    var r = 0u;
    for (var i = 0u; i < 4u; i++) {
        let b = prepass_cf_pack_lane(site + 8u * i, clamp(v[i], -1.0, 1.0), 128.0);
        r = r | ((bitcast<u32>(i32(b)) & 0xffu) << (8u * i));
    }
    return r;
}

fn prepass_cf_pack2x16unorm(site: u32, v: vec2<f32>) -> u32 {
    if (!prepass_cf_on(PREPASS_CF_PACK)) {
        return pack2x16unorm(v);
    }
    var r = 0u;
    for (var i = 0u; i < 2u; i++) {
        let b = prepass_cf_pack_lane(site + 8u * i, clamp(v[i], 0.0, 1.0), 65536.0);
        r = r | (u32(b) << (16u * i));
    }
    return r;
}

fn prepass_cf_pack2x16snorm(site: u32, v: vec2<f32>) -> u32 {
    if (!prepass_cf_on(PREPASS_CF_PACK)) {
        return pack2x16snorm(v);
    }
    var r = 0u;
    for (var i = 0u; i < 2u; i++) {
        let b = prepass_cf_pack_lane(site + 8u * i, clamp(v[i], -1.0, 1.0), 32768.0);
        r = r | ((bitcast<u32>(i32(b)) & 0xffffu) << (16u * i));
    }
    return r;
}

// One of the two ends lo <= hi of a choice between neighbours: the upper policy takes hi, the
// lower lo, a seeded one either or the host's own result.
fn prepass_cf_choose(freedom: u32, site: u32, host: f32, lo: f32, hi: f32) -> f32 {
    let dir = prepass_cf_dir(freedom, site, lo, hi);
    if (dir > 0) {
        return hi;
    }
    if (dir < 0) {
        return lo;
    }
    return host;
}

// The f16 value of an f16-subnormal x flushed to zero (keeping its sign) or kept: pack and
// unpack intermediates may be flushed.
fn prepass_cf_ftz16(site: u32, x: f32) -> f32 {
    if (x == 0.0 || abs(x) >= bitcast<f32>(0x38800000u)) { // 2^-14, the smallest normal f16
        return x;
    }
    return prepass_cf_pick(PREPASS_CF_FLUSH, site, x, bitcast<f32>(bitcast<u32>(x) & 0x80000000u));
}

// The f32 value of a finite f16 code, from its bits alone: a compiler may fold
// unpack2x16float(pack2x16float(x)) into x (Mesa 25 does), which would hide the rounding.
fn prepass_cf_f16_value(h: u32) -> f32 {
    let sign = select(1.0, -1.0, (h & 0x8000u) != 0u);
    let e = (h >> 10u) & 0x1fu;
    let m = h & 0x3ffu;
    if (e == 0u) {
        return sign * f32(m) * bitcast<f32>(0x33800000u); // m * 2^-24, exact
    }
    return sign * bitcast<f32>(((e + 112u) << 23u) | (m << 13u));
}

// One lane of pack2x16float, in range: either neighbouring f16 of x (the host's code is one of
// them; the other is one f16 step away, toward x), then flushed or not if f16-subnormal. The
// chosen value is an f16, so the final conversion is exact on any adapter.
fn prepass_cf_f16_lane(site: u32, x0: f32) -> u32 {
    let x = prepass_cf_ftz(site + 1u, x0);
    let h = pack2x16float(vec2<f32>(x, 0.0)) & 0xffffu;
    let vh = prepass_cf_f16_value(h);
    var lo = vh;
    var hi = vh;
    if (vh != x) {
        let toward = select(h - 1u, h + 1u, abs(x) > abs(vh));
        let vo = prepass_cf_f16_value(toward & 0xffffu);
        lo = min(vh, vo);
        hi = max(vh, vo);
    }
    let c = prepass_cf_ftz16(site + 3u, prepass_cf_choose(PREPASS_CF_PACK, site, vh, lo, hi));
    return pack2x16float(vec2<f32>(c, 0.0)) & 0xffffu;
}

// pack2x16float: either neighbouring f16 per lane, f16 subnormals flushed or not; indeterminate
// when a lane leaves +-65504.
fn prepass_cf_pack2x16float(site: u32, v: vec2<f32>) -> u32 {
    prepass_cf_undefined_if(!((abs(v.x) <= 65504.0) & (abs(v.y) <= 65504.0)));
    if (!prepass_cf_on(PREPASS_CF_PACK | PREPASS_CF_FLUSH)) {
        return pack2x16float(v);
    }
    return prepass_cf_f16_lane(site, v.x) | (prepass_cf_f16_lane(site + 8u, v.y) << 16u);
}

// unpack2x16float: exact, but an f16-subnormal lane may be flushed. An infinite or NaN half
// gives a run-time ±Inf or NaN: outside the domain.
fn prepass_cf_unpack2x16float(site: u32, p: u32) -> vec2<f32> {
    let v = unpack2x16float(p);
    prepass_cf_operand_if(!(prepass_cf_finite(v.x) & prepass_cf_finite(v.y)));
    if (!prepass_cf_on(PREPASS_CF_FLUSH)) {
        return v;
    }
    return vec2<f32>(prepass_cf_ftz16(site, v.x), prepass_cf_ftz16(site + 8u, v.y));
}

// The f32 neighbours (down, up) of an unsigned integer: equal where x is exact (below 2^24 or
// with few enough significant bits). Both are exact conversions of integers with at most 24
// significant bits (the up one may be 2^32).
fn prepass_cf_u32_neighbours(x: u32) -> vec2<f32> {
    let lz = countLeadingZeros(x);
    if (lz >= 8u) {
        let f = f32(x);
        return vec2<f32>(f, f);
    }
    let shift = 8u - lz;
    let down = (x >> shift) << shift;
    let lo = f32(down);
    if (down == x) {
        return vec2<f32>(lo, lo);
    }
    return vec2<f32>(lo, lo + f32(1u << shift));
}

// f32(u32): exact where representable, otherwise either neighbour (WGSL "Floating Point
// Conversion").
fn prepass_cf_f32_from_u32(site: u32, x: u32) -> f32 {
    if (!prepass_cf_on(PREPASS_CF_CONVERSION)) {
        return f32(x);
    }
    let n = prepass_cf_u32_neighbours(x);
    return prepass_cf_choose(PREPASS_CF_CONVERSION, site, f32(x), n.x, n.y);
}

// u32(x) and i32(x) of an f32: exact (truncated toward zero, saturated), but outside the domain
// for a ±Inf or NaN x (the spec's finite-math assumption): bit 2. No freedom, so no slot read.
fn prepass_cf_u32_from_f32(site: u32, x: f32) -> u32 {
    prepass_cf_operand_if(!prepass_cf_finite(x));
    return u32(x);
}

fn prepass_cf_i32_from_f32(site: u32, x: f32) -> i32 {
    prepass_cf_operand_if(!prepass_cf_finite(x));
    return i32(x);
}

// f32(i32), the same on the magnitude (|i32::MIN| = 2^31 is exact).
fn prepass_cf_f32_from_i32(site: u32, x: i32) -> f32 {
    if (!prepass_cf_on(PREPASS_CF_CONVERSION)) {
        return f32(x);
    }
    let neg = x < 0;
    let n = prepass_cf_u32_neighbours(select(bitcast<u32>(x), 0u - bitcast<u32>(x), neg));
    if (neg) {
        return prepass_cf_choose(PREPASS_CF_CONVERSION, site, f32(x), -n.y, -n.x);
    }
    return prepass_cf_choose(PREPASS_CF_CONVERSION, site, f32(x), n.x, n.y);
}

// The exactly rounded operations of the accuracy table whose inputs and outputs may be flushed
// (a flushed negative subnormal floors to -0 instead of -1, say).
fn prepass_cf_floor(site: u32, x: f32) -> f32 {
    return prepass_cf_ftz(site + 3u, floor(prepass_cf_ftz(site + 1u, x)));
}

fn prepass_cf_ceil(site: u32, x: f32) -> f32 {
    return prepass_cf_ftz(site + 3u, ceil(prepass_cf_ftz(site + 1u, x)));
}

fn prepass_cf_trunc(site: u32, x: f32) -> f32 {
    return prepass_cf_ftz(site + 3u, trunc(prepass_cf_ftz(site + 1u, x)));
}

fn prepass_cf_round_even(site: u32, x: f32) -> f32 {
    return prepass_cf_ftz(site + 3u, round(prepass_cf_ftz(site + 1u, x)));
}

fn prepass_cf_abs(site: u32, x: f32) -> f32 {
    return prepass_cf_ftz(site + 3u, abs(prepass_cf_ftz(site + 1u, x)));
}

fn prepass_cf_sign(site: u32, x: f32) -> f32 {
    return sign(prepass_cf_ftz(site + 1u, x));
}

fn prepass_cf_saturate(site: u32, x: f32) -> f32 {
    return prepass_cf_ftz(site + 3u, saturate(prepass_cf_ftz(site + 1u, x)));
}

fn prepass_cf_min(site: u32, a: f32, b: f32) -> f32 {
    return prepass_cf_ftz(site + 3u, min(prepass_cf_ftz(site + 1u, a), prepass_cf_ftz(site + 2u, b)));
}

fn prepass_cf_max(site: u32, a: f32, b: f32) -> f32 {
    return prepass_cf_ftz(site + 3u, max(prepass_cf_ftz(site + 1u, a), prepass_cf_ftz(site + 2u, b)));
}

fn prepass_cf_step(site: u32, edge: f32, x: f32) -> f32 {
    return step(prepass_cf_ftz(site + 1u, edge), prepass_cf_ftz(site + 2u, x));
}

fn prepass_cf_clamp(site: u32, x: f32, lo: f32, hi: f32) -> f32 {
    let a = prepass_cf_ftz(site + 1u, x);
    let l = prepass_cf_ftz(site + 2u, lo);
    let h = prepass_cf_ftz(site + 4u, hi);
    return prepass_cf_ftz(site + 3u, clamp(a, l, h));
}

// Comparisons are exact, but their operands may be flushed.
fn prepass_cf_lt(site: u32, a: f32, b: f32) -> bool {
    return prepass_cf_ftz(site + 1u, a) < prepass_cf_ftz(site + 2u, b);
}

fn prepass_cf_le(site: u32, a: f32, b: f32) -> bool {
    return prepass_cf_ftz(site + 1u, a) <= prepass_cf_ftz(site + 2u, b);
}

fn prepass_cf_gt(site: u32, a: f32, b: f32) -> bool {
    return prepass_cf_ftz(site + 1u, a) > prepass_cf_ftz(site + 2u, b);
}

fn prepass_cf_ge(site: u32, a: f32, b: f32) -> bool {
    return prepass_cf_ftz(site + 1u, a) >= prepass_cf_ftz(site + 2u, b);
}

fn prepass_cf_eq(site: u32, a: f32, b: f32) -> bool {
    return prepass_cf_ftz(site + 1u, a) == prepass_cf_ftz(site + 2u, b);
}

fn prepass_cf_ne(site: u32, a: f32, b: f32) -> bool {
    return prepass_cf_ftz(site + 1u, a) != prepass_cf_ftz(site + 2u, b);
}
