//! The WebGPU conformance suite's f32 acceptance intervals, transcribed in f64.
//!
//! An adapter is conforming, in practice, when it passes the CTS (gpuweb/cts); its f32 rules
//! live in `src/webgpu/util/floating_point.ts` (the `FPTraits` class and its `F32Traits`) and
//! `src/webgpu/util/math.ts`. Each function here returns the interval the CTS accepts for one
//! operation at one input, following the function named in its doc line; the code is written
//! here from the rules, not copied. The emulation of the worst conforming adapter
//! ([`super::Policy::Upper`] and [`super::Policy::Lower`]) must reach at least as far as these
//! ends (`tests/conforming_cts.rs` checks it); where the WGSL spec's own reading allows more
//! (its ULP of a real just above a power of two is the spacing above, the CTS's that of the
//! f32 neighbour below), the emulation keeps the wider.
//!
//! How the CTS builds an interval, in three steps that every rule below repeats:
//! 1. **Inputs**: every input is replaced by its f32 neighbours (`correctlyRoundedF32`, one
//!    value when representable), and 0 is added where one of them is subnormal
//!    (`addFlushedIfNeeded`: flush-to-zero is allowed on every input); an input that is itself
//!    an interval contributes its two endpoints (`runScalarToIntervalOp` and its pair, triple
//!    and vector forms: the CTS assumes each operation monotonic between them).
//! 2. **Operation**: evaluated in f64 on each combination, giving a point or an interval.
//! 3. **Result**: `ulpInterval(n, k)` rounds the exact `n` to its f32 neighbours `m` (plus 0
//!    if one is subnormal) and accepts `[m − k·ULP(m), m + k·ULP(m)]` around each, each end
//!    widened to 0 where it is subnormal (`ULPIntervalOp`); `absoluteErrorInterval(n, e)` accepts
//!    `[m − e, m + e]` around the same neighbours; `correctlyRoundedInterval(n)` the neighbours
//!    themselves. `ULP(m)` is `oneULPF32` in flush mode: 2^-126 for 0 and every subnormal, the
//!    spacing below at a power of two, the binade's spacing elsewhere.
//!
//! The interval is unbounded (any value, [`None`] here) where an input leaves the operation's
//! domain or any value is not finite.

/// 2^-126, the least normal f32 (`kValue.f32.positive.min`).
const MIN_NORMAL: f64 = 1.175_494_350_822_287_5e-38;
/// The largest finite f32.
const F32_MAX: f64 = f32::MAX as f64;

/// An acceptance interval `[lo, hi]` of reals: the f32 values inside it are accepted. Where a
/// rule returns `Option<Interval>`, [`None`] is the CTS's unbounded interval (any value).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    /// Lower end (a real, not necessarily an f32).
    pub lo: f64,
    /// Upper end.
    pub hi: f64,
}

impl Interval {
    /// The point `x`.
    pub fn point(x: f64) -> Interval {
        Interval { lo: x, hi: x }
    }

    fn span(self, o: Interval) -> Interval {
        Interval {
            lo: self.lo.min(o.lo),
            hi: self.hi.max(o.hi),
        }
    }

    /// Whether the f32 `x` is accepted (either zero is, where the interval holds 0).
    pub fn contains(&self, x: f32) -> bool {
        self.lo <= f64::from(x) && f64::from(x) <= self.hi
    }

    /// The least f32 inside the interval (its lowest accepted result).
    pub fn lowest_f32(&self) -> f32 {
        let r = self.lo as f32;
        if f64::from(r) < self.lo {
            r.next_up()
        } else {
            r
        }
    }

    /// The greatest f32 inside the interval (its highest accepted result).
    pub fn highest_f32(&self) -> f32 {
        let r = self.hi as f32;
        if f64::from(r) > self.hi {
            r.next_down()
        } else {
            r
        }
    }

    fn endpoints(self) -> Vec<f64> {
        if self.lo == self.hi {
            vec![self.lo]
        } else {
            vec![self.lo, self.hi]
        }
    }
}

/// The span of `ivs`, unbounded if any is (or is not finite): `spanIntervals` and the
/// `isFinite` checks of `runScalarToIntervalOp`.
fn span_all(ivs: impl IntoIterator<Item = Option<Interval>>) -> Option<Interval> {
    let mut out: Option<Interval> = None;
    for iv in ivs {
        let iv = iv?;
        if !(iv.lo.is_finite() && iv.hi.is_finite()) {
            return None;
        }
        out = Some(match out {
            None => iv,
            Some(o) => o.span(iv),
        });
    }
    out
}

/// `isSubnormalNumberF32` (math.ts): a nonzero value of magnitude below 2^-126.
fn is_subnormal(x: f64) -> bool {
    x != 0.0 && x.abs() < MIN_NORMAL
}

/// `flushSubnormalNumberF32` (math.ts).
fn flush(x: f64) -> f64 {
    if is_subnormal(x) { 0.0 } else { x }
}

/// `correctlyRoundedF32` (math.ts): the f32 values next to `n` (one where it is an f32; an
/// infinity beyond the largest finite f32).
fn neighbours(n: f64) -> Vec<f64> {
    if n >= 2f64.powi(128) {
        return vec![f64::INFINITY];
    }
    if n <= -(2f64.powi(128)) {
        return vec![f64::NEG_INFINITY];
    }
    if n > F32_MAX {
        return vec![F32_MAX, f64::INFINITY];
    }
    if n < -F32_MAX {
        return vec![f64::NEG_INFINITY, -F32_MAX];
    }
    let r = n as f32;
    let r64 = f64::from(r);
    if r64 == n {
        vec![n]
    } else if r64 < n {
        vec![r64, f64::from(r.next_up())]
    } else {
        vec![f64::from(r.next_down()), r64]
    }
}

/// `roundAndFlushScalarToInterval`'s inputs: the neighbours of `n`, and 0 where one of them is
/// subnormal (`addFlushedIfNeeded`).
pub fn rounded_inputs(n: f64) -> Vec<f64> {
    let mut v = neighbours(n);
    if v.iter().any(|&x| is_subnormal(x)) {
        v.push(0.0);
    }
    v
}

/// `nextAfterF32(val, dir, 'flush')` (math.ts) for an f32 `val`: ±2^-126 from zero, results
/// flushed.
fn next_after_flushed(val: f64, up: bool) -> f64 {
    let v = flush(val);
    if v == 0.0 {
        return if up { MIN_NORMAL } else { -MIN_NORMAL };
    }
    let f = v as f32;
    flush(f64::from(if up { f.next_up() } else { f.next_down() }))
}

/// `oneULPF32(target, 'flush')` (math.ts): 2^-126 at 0 and for subnormals; for an f32, the
/// smaller gap to its flushed neighbours (the spacing below at a power of two); for a value
/// between two f32s, their gap; 2^104 at and beyond the largest finite f32.
pub fn one_ulp(target: f64) -> f64 {
    let t = flush(target);
    if t.abs() >= F32_MAX {
        return 2f64.powi(104);
    }
    if f64::from(t as f32) == t {
        let before = next_after_flushed(t, false);
        let after = next_after_flushed(t, true);
        (t - before).min(after - t)
    } else {
        let n = neighbours(t);
        n[1] - n[0]
    }
}

/// `ulpInterval(n, k)` (floating_point.ts, `ulpIntervalImpl` and `ULPIntervalOp`): `k` ULP
/// around each f32 neighbour of `n` (and around 0 where one is subnormal), each end widened to
/// 0 where it is subnormal.
pub fn ulp_interval(n: f64, k: f64) -> Option<Interval> {
    span_all(rounded_inputs(n).into_iter().map(|m| {
        if !m.is_finite() {
            return None;
        }
        let u = one_ulp(m);
        let (b, e) = (m - k * u, m + k * u);
        Some(Interval {
            lo: b.min(flush(b)),
            hi: e.max(flush(e)),
        })
    }))
}

/// `absoluteErrorInterval(n, e)` (floating_point.ts, `AbsoluteErrorIntervalOp`): `±e` around
/// each f32 neighbour of `n` (and 0 where one is subnormal).
pub fn absolute_interval(n: f64, e: f64) -> Option<Interval> {
    span_all(rounded_inputs(n).into_iter().map(|m| {
        m.is_finite().then_some(Interval {
            lo: m - e,
            hi: m + e,
        })
    }))
}

/// `correctlyRoundedInterval(n)` (floating_point.ts, `CorrectlyRoundedIntervalOp`): the f32
/// neighbours of `n`, and 0 where one is subnormal.
pub fn correctly_rounded(n: f64) -> Option<Interval> {
    span_all(
        rounded_inputs(n)
            .into_iter()
            .map(|m| m.is_finite().then_some(Interval::point(m))),
    )
}

/// A unary operation over an interval input: its endpoints, each rounded and flushed, then
/// `op` (`runScalarToIntervalOp` with `roundAndFlushScalarToInterval`).
fn unary(x: Option<Interval>, op: impl Fn(f64) -> Option<Interval>) -> Option<Interval> {
    let x = x?;
    span_all(
        x.endpoints()
            .into_iter()
            .flat_map(rounded_inputs)
            .map(|m| if m.is_finite() { op(m) } else { None })
            .collect::<Vec<_>>(),
    )
}

/// A binary operation over interval inputs (`runScalarPairToIntervalOp` with
/// `roundAndFlushScalarPairToInterval`).
fn binary(
    x: Option<Interval>,
    y: Option<Interval>,
    op: impl Fn(f64, f64) -> Option<Interval>,
) -> Option<Interval> {
    let (x, y) = (x?, y?);
    let xs: Vec<f64> = x.endpoints().into_iter().flat_map(rounded_inputs).collect();
    let ys: Vec<f64> = y.endpoints().into_iter().flat_map(rounded_inputs).collect();
    let mut out = Vec::new();
    for &a in &xs {
        for &b in &ys {
            out.push(if a.is_finite() && b.is_finite() {
                op(a, b)
            } else {
                None
            });
        }
    }
    span_all(out)
}

/// `x + y` (`AdditionIntervalOp`): correctly rounded, inputs flushed or not.
pub fn add(x: Option<Interval>, y: Option<Interval>) -> Option<Interval> {
    binary(x, y, |a, b| correctly_rounded(a + b))
}

/// `x − y` (`SubtractionIntervalOp`).
pub fn sub(x: Option<Interval>, y: Option<Interval>) -> Option<Interval> {
    binary(x, y, |a, b| correctly_rounded(a - b))
}

/// `x · y` (`MultiplicationIntervalOp`; the f64 product of two f32 is exact).
pub fn mul(x: Option<Interval>, y: Option<Interval>) -> Option<Interval> {
    binary(x, y, |a, b| correctly_rounded(a * b))
}

/// `x / y` (`DivisionIntervalOpBuilder`): 2.5 ULP of the quotient; unbounded where a rounded
/// or flushed divisor leaves ±[2^-126, 2^126] (a divisor interval holding 0 included).
pub fn div(x: Option<Interval>, y: Option<Interval>) -> Option<Interval> {
    let yv = y?;
    if yv.lo <= 0.0 && yv.hi >= 0.0 {
        return None; // the extrema step replaces y by 0: unbounded
    }
    let ok = |b: f64| (MIN_NORMAL..=2f64.powi(126)).contains(&b.abs());
    binary(x, y, |a, b| {
        if ok(b) {
            ulp_interval(a / b, 2.5)
        } else {
            None
        }
    })
}

/// `inverseSqrt(x)` (`InverseSqrtIntervalOp`): 2 ULP of `1/√x`; unbounded unless every
/// rounded and flushed input lies in `[2^-149, f32::MAX]` (`greaterThanZeroInterval`), so a
/// subnormal input (which may be flushed to 0) is unbounded too.
pub fn inverse_sqrt(x: Option<Interval>) -> Option<Interval> {
    let x = x?;
    let ins: Vec<f64> = x.endpoints().into_iter().flat_map(rounded_inputs).collect();
    if ins.iter().any(|&m| !(m >= 2f64.powi(-149) && m <= F32_MAX)) {
        return None;
    }
    span_all(ins.into_iter().map(|m| ulp_interval(1.0 / m.sqrt(), 2.0)))
}

/// `sqrt(x)` (`SqrtIntervalOp`): inherited, `1.0 / inverseSqrt(x)`; unbounded at 0 and for
/// subnormals (where `inverseSqrt` is).
pub fn sqrt(x: Option<Interval>) -> Option<Interval> {
    unary(x, |m| {
        div(
            Some(Interval::point(1.0)),
            inverse_sqrt(Some(Interval::point(m))),
        )
    })
}

/// The cartesian product of per-lane choices.
fn product(lanes: &[Vec<f64>]) -> Vec<Vec<f64>> {
    lanes.iter().fold(vec![Vec::new()], |acc, lane| {
        acc.iter()
            .flat_map(|p| {
                lane.iter().map(move |&v| {
                    let mut q = p.clone();
                    q.push(v);
                    q
                })
            })
            .collect()
    })
}

/// A vector's lanes rounded and flushed, every combination (`roundAndFlushVectorToInterval`).
fn vector_inputs(v: &[f64]) -> Vec<Vec<f64>> {
    product(&v.iter().map(|&x| rounded_inputs(x)).collect::<Vec<_>>())
}

/// Every order of summing `terms` left to right (`calculatePermutations` then `reduce`).
fn permutations(terms: &[Option<Interval>]) -> Vec<Vec<Option<Interval>>> {
    if terms.len() <= 1 {
        return vec![terms.to_vec()];
    }
    let mut out = Vec::new();
    for i in 0..terms.len() {
        let mut rest = terms.to_vec();
        let first = rest.remove(i);
        for mut p in permutations(&rest) {
            p.insert(0, first);
            out.push(p);
        }
    }
    out
}

/// `dot(x, y)` of f32 vectors (`DotIntervalOp`): the products correctly rounded, summed in
/// every order (one order for vec2: `a + b = b + a`), inputs rounded and flushed.
pub fn dot(x: &[f64], y: &[f64]) -> Option<Interval> {
    let xs = vector_inputs(x);
    let ys = vector_inputs(y);
    span_all(xs.iter().flat_map(|a| {
        ys.iter().map(move |b| {
            let products: Vec<Option<Interval>> = a
                .iter()
                .zip(b)
                .map(|(&p, &q)| mul(Some(Interval::point(p)), Some(Interval::point(q))))
                .collect();
            span_all(
                permutations(&products)
                    .into_iter()
                    .map(|order| order[1..].iter().fold(order[0], |s, &t| add(s, t))),
            )
        })
    }))
}

/// `length(v)` (`LengthIntervalVectorOp`): `sqrt(dot(v, v))`, so unbounded where the dot
/// product may be 0.
pub fn length(v: &[f64]) -> Option<Interval> {
    span_all(vector_inputs(v).iter().map(|w| sqrt(dot(w, w))))
}

/// `normalize(v)` (`NormalizeIntervalOp`): each lane `e / length(v)`, per lane.
pub fn normalize(v: &[f64]) -> Option<Vec<Interval>> {
    let mut out: Option<Vec<Interval>> = None;
    for w in vector_inputs(v) {
        let len = length(&w);
        let lanes: Option<Vec<Interval>> = w
            .iter()
            .map(|&e| div(Some(Interval::point(e)), len))
            .collect();
        let lanes = lanes?;
        out = Some(match out {
            None => lanes,
            Some(o) => o.iter().zip(&lanes).map(|(a, b)| a.span(*b)).collect(),
        });
    }
    out
}

/// Row `r` of `m · v` for a column-major 3×3 `m` (`multiplicationMatrixVectorIntervalImpl`:
/// each row dotted with `v`).
pub fn mat3_vec3_row(cols: &[[f64; 3]; 3], v: &[f64; 3], r: usize) -> Option<Interval> {
    dot(&[cols[0][r], cols[1][r], cols[2][r]], v)
}

/// `log2(x)` (`Log2IntervalOp`): absolute 2^-21 on `[0.5, 2]`, 3 ULP elsewhere; unbounded
/// unless every rounded and flushed input is positive.
pub fn log2(x: f64) -> Option<Interval> {
    let ins = rounded_inputs(x);
    if ins.iter().any(|&m| !(m >= 2f64.powi(-149) && m <= F32_MAX)) {
        return None;
    }
    span_all(ins.into_iter().map(|m| {
        if (0.5..=2.0).contains(&m) {
            absolute_interval(m.log2(), 2f64.powi(-21))
        } else {
            ulp_interval(m.log2(), 3.0)
        }
    }))
}

/// `exp2(x)` (`Exp2IntervalOp`): `3 + 2|x|` ULP of `2^x`.
pub fn exp2(x: f64) -> Option<Interval> {
    unary(Some(Interval::point(x)), |m| {
        ulp_interval(m.exp2(), 3.0 + 2.0 * m.abs())
    })
}

/// `floor(x)` (`FloorIntervalOp`): correctly rounded, input flushed or not.
pub fn floor(x: f64) -> Option<Interval> {
    unary(Some(Interval::point(x)), |m| correctly_rounded(m.floor()))
}

/// `abs(x)` (`AbsIntervalOp`).
pub fn abs(x: f64) -> Option<Interval> {
    unary(Some(Interval::point(x)), |m| correctly_rounded(m.abs()))
}

/// `min` or `max` (`pick`) of two f32: correctly rounded, either input where both are
/// subnormal (`MinIntervalOp`, `MaxIntervalOp`).
fn min_or_max(x: f64, y: f64, pick: fn(f64, f64) -> f64) -> Option<Interval> {
    binary(
        Some(Interval::point(x)),
        Some(Interval::point(y)),
        |a, b| {
            if is_subnormal(a) && is_subnormal(b) {
                correctly_rounded(a)
                    .zip(correctly_rounded(b))
                    .map(|(p, q)| p.span(q))
            } else {
                correctly_rounded(pick(a, b))
            }
        },
    )
}

/// `min(x, y)` (`MinIntervalOp`): either input where both are subnormal.
pub fn min(x: f64, y: f64) -> Option<Interval> {
    min_or_max(x, y, f64::min)
}

/// `max(x, y)` (`MaxIntervalOp`): either input where both are subnormal.
pub fn max(x: f64, y: f64) -> Option<Interval> {
    min_or_max(x, y, f64::max)
}

/// `fract(x)` (`FractIntervalOp`): `x − floor(x)`, widened to the float below 1 where it
/// reaches 1.
pub fn fract(x: f64) -> Option<Interval> {
    unary(Some(Interval::point(x)), |m| {
        let r = sub(Some(Interval::point(m)), floor(m))?;
        if r.contains(1.0) {
            Some(r.span(Interval::point(f64::from(1.0f32.next_down()))))
        } else {
            Some(r)
        }
    })
}

/// One lane of `unpack4x8unorm` (`unpack4x8unormIntervalImpl`): 3 ULP of `v / 255`.
pub fn unpack_unorm8(v: u8) -> Option<Interval> {
    ulp_interval(f64::from(v) / 255.0, 3.0)
}

/// One lane of `unpack4x8snorm` (`unpack4x8snormIntervalImpl`): 3 ULP of `max(v / 127, −1)`.
pub fn unpack_snorm8(v: i8) -> Option<Interval> {
    ulp_interval((f64::from(v) / 127.0).max(-1.0), 3.0)
}

/// One lane of `unpack2x16unorm` (`unpack2x16unormIntervalImpl`): 3 ULP of `v / 65535`.
pub fn unpack_unorm16(v: u16) -> Option<Interval> {
    ulp_interval(f64::from(v) / 65535.0, 3.0)
}

/// One lane of `unpack2x16snorm` (`unpack2x16snormIntervalImpl`): 3 ULP of
/// `max(v / 32767, −1)`.
pub fn unpack_snorm16(v: i16) -> Option<Interval> {
    ulp_interval((f64::from(v) / 32767.0).max(-1.0), 3.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ulp_is_the_ctss() {
        assert_eq!(one_ulp(0.0), MIN_NORMAL);
        assert_eq!(one_ulp(1e-40), MIN_NORMAL);
        assert_eq!(one_ulp(1.0), 2f64.powi(-24)); // the spacing below
        assert_eq!(one_ulp(1.5), 2f64.powi(-23));
        assert_eq!(one_ulp(MIN_NORMAL), 2f64.powi(-149));
    }

    #[test]
    fn ulp_interval_is_around_the_neighbours() {
        // 1/3: neighbours a < 1/3 < b one spacing apart; 2.5 ULP around each.
        let iv = ulp_interval(1.0 / 3.0, 2.5).unwrap();
        let n = neighbours(1.0 / 3.0);
        let u = 2f64.powi(-25);
        assert_eq!(
            iv,
            Interval {
                lo: n[0] - 2.5 * u,
                hi: n[1] + 2.5 * u
            }
        );
        // At 0: ±k·2^-126.
        assert_eq!(
            ulp_interval(0.0, 3.0).unwrap(),
            Interval {
                lo: -3.0 * MIN_NORMAL,
                hi: 3.0 * MIN_NORMAL
            }
        );
    }

    #[test]
    fn sqrt_of_zero_and_subnormals_is_unbounded() {
        assert_eq!(sqrt(Some(Interval::point(0.0))), None);
        assert_eq!(sqrt(Some(Interval::point(1e-40))), None);
        assert_eq!(length(&[0.0, 0.0, 0.0]), None);
        let s = sqrt(Some(Interval::point(4.0))).unwrap();
        assert!(s.contains(2.0) && s.lo < 2.0 && s.hi > 2.0);
    }
}
