//! Error metrics shared by every precision test and by `errplot`.
//!
//! All distances are measured against an *exact* reference: an `f64` (which carries 29 more
//! significand bits than `f32`, so its own rounding is ≤ 2^-29 of an `f32` ULP) or an exact
//! integer/rational computed by the caller.

/// Position of an `f32` on the ordered integer line of finite floats: consecutive floats differ
/// by 1 and `+0.0` and `-0.0` both map to 0. NaN has no position.
pub fn ordinal(x: f32) -> Option<i64> {
    if x.is_nan() {
        return None;
    }
    let bits = x.to_bits();
    let magnitude = i64::from(bits & 0x7fff_ffff);
    Some(if bits >> 31 == 1 {
        -magnitude
    } else {
        magnitude
    })
}

/// Distance in ULPs between two `f32`s: how many representable floats lie between them, plus
/// one (0 when equal; `+0.0` and `-0.0` are 0 apart). `None` if either is NaN.
/// Infinities count as the float one past `f32::MAX`.
pub fn ulp_distance(a: f32, b: f32) -> Option<u64> {
    Some((ordinal(a)? - ordinal(b)?).unsigned_abs())
}

/// The `f32` that lies `steps` ULPs from `x` on the ordered line (through zero, saturating at
/// ±Inf). Used to build inputs perturbed by an exact number of ULPs.
pub fn step_ulps(x: f32, steps: i64) -> f32 {
    let Some(o) = ordinal(x) else { return x };
    let inf = i64::from(f32::INFINITY.to_bits());
    let target = (o + steps).clamp(-inf, inf);
    let bits = target.unsigned_abs() as u32;
    if target < 0 {
        f32::from_bits(bits | 0x8000_0000)
    } else {
        f32::from_bits(bits)
    }
}

/// Size of one `f32` ULP at the magnitude of `exact`: `2^(e-23)` for `|exact|` in `[2^e, 2^(e+1))`,
/// `2^-149` below the normal range. Errors are expressed in this unit ("ULPs of the true value").
pub fn f32_ulp_at(exact: f64) -> f64 {
    let a = exact.abs();
    if !a.is_finite() {
        return f64::NAN;
    }
    let min_normal = f64::from(f32::MIN_POSITIVE);
    if a < min_normal {
        return f64::from_bits((1023 - 149) << 52);
    }
    // floor(log2(a)) is a's f64 exponent field; 2^(e − 23) is built in that field directly
    // (exact, and no `powi` loop: this runs once per element of every 2^24 sweep).
    let biased = (a.to_bits() >> 52) & 0x7ff;
    f64::from_bits((biased.min(1023 + 127) - 23) << 52)
}

/// Error of `got` against the exact value, in `f32` ULPs of the exact value.
/// Exact infinities match only themselves (0 or `+Inf`); NaN on either side gives NaN.
pub fn ulp_error(got: f32, exact: f64) -> f64 {
    if got.is_nan() || exact.is_nan() {
        return f64::NAN;
    }
    if exact.is_infinite() || got.is_infinite() {
        return if f64::from(got) == exact {
            0.0
        } else {
            f64::INFINITY
        };
    }
    // × 1/ulp, not ÷ ulp: the same value (ulp is a power of two, its reciprocal exact in
    // f64), without a division in the sweeps' per-element loop.
    let inverse = f64::from_bits(((2 * 1023) - (f32_ulp_at(exact).to_bits() >> 52)) << 52);
    (f64::from(got) - exact).abs() * inverse
}

/// Relative error `|got − exact| / |exact|`; 0 when both are 0, `+Inf` when only `exact` is 0,
/// NaN when either is NaN.
pub fn relative_error(got: f64, exact: f64) -> f64 {
    if got.is_nan() || exact.is_nan() {
        return f64::NAN;
    }
    if exact.is_infinite() || got.is_infinite() {
        return if got == exact { 0.0 } else { f64::INFINITY };
    }
    if exact == 0.0 {
        return if got == 0.0 { 0.0 } else { f64::INFINITY };
    }
    ((got - exact) / exact).abs()
}

/// Angle in degrees between two directions (neither need be unit length), computed as
/// `atan2(|a×b|, a·b)` in f64, which stays accurate for tiny and near-180° angles where
/// `acos(a·b)` loses half its digits. Zero or non-finite vectors give NaN. Vectors of any other
/// length are directions: lanes below `10^-150` or above `10^150` are first scaled by `2^±600`
/// (exactly), so squares neither underflow nor overflow.
pub fn angle_degrees(a: [f64; 3], b: [f64; 3]) -> f64 {
    let (Some(a), Some(b)) = (rescaled(a), rescaled(b)) else {
        return f64::NAN;
    };
    let cross = [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ];
    let sin = (cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]).sqrt();
    let cos = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    sin.atan2(cos).to_degrees()
}

/// `v` scaled by a power of two (exact) so its largest lane is within `10^±150`; `None` for zero
/// or non-finite vectors.
fn rescaled(v: [f64; 3]) -> Option<[f64; 3]> {
    if !v.iter().all(|x| x.is_finite()) {
        return None;
    }
    let m = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if m == 0.0 {
        return None;
    }
    let k = if m < 1e-150 {
        600
    } else if m > 1e150 {
        -600
    } else {
        0
    };
    Some(v.map(|x| x * 2f64.powi(k)))
}

/// Widen an `f32` vector for [`angle_degrees`].
pub fn widen3(v: [f32; 3]) -> [f64; 3] {
    v.map(f64::from)
}

/// Mismatches between a result column and its expectation, with the first few kept as
/// `(index, got, expected)` so a failure message can show them.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mismatches<T> {
    /// How many entries differ.
    pub count: u64,
    /// How many entries were compared.
    pub total: u64,
    /// The first differing entries: `(index, got, expected)`.
    pub first: Vec<(u64, T, T)>,
}

/// How many mismatches [`Mismatches::first`] keeps.
pub const MISMATCH_EXAMPLES: usize = 8;

impl<T: PartialEq + Copy> Mismatches<T> {
    /// Compare `got[i]` with `expected(i)` for every `i`.
    pub fn count(got: &[T], mut expected: impl FnMut(usize) -> T) -> Self {
        let mut m = Mismatches {
            count: 0,
            total: got.len() as u64,
            first: Vec::new(),
        };
        for (i, &g) in got.iter().enumerate() {
            let e = expected(i);
            if g != e {
                m.count += 1;
                if m.first.len() < MISMATCH_EXAMPLES {
                    m.first.push((i as u64, g, e));
                }
            }
        }
        m
    }

    /// Fold another column's mismatches (indices offset by `base`) into these.
    pub fn merge(&mut self, other: Mismatches<T>, base: u64) {
        self.count += other.count;
        self.total += other.total;
        for (i, g, e) in other.first {
            if self.first.len() < MISMATCH_EXAMPLES {
                self.first.push((i + base, g, e));
            }
        }
    }
}

/// Compare two `f32` columns bit for bit (NaN payloads and the sign of zero included): the test of
/// "the Rust twin is bit-identical to the WGSL".
pub fn bit_mismatches(got: &[f32], expected: &[f32]) -> Mismatches<u32> {
    let got_bits: Vec<u32> = got.iter().map(|x| x.to_bits()).collect();
    Mismatches::count(&got_bits, |i| expected[i].to_bits())
}

/// Running max / mean / RMS of an error, with the input index of the maximum.
/// NaN errors are counted separately and never hide inside a max.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ErrorStats {
    /// Number of finite samples folded in.
    pub count: u64,
    /// Number of NaN samples (each one is a failure for a measured function).
    pub nan_count: u64,
    /// Largest error seen (may be `+Inf`).
    pub max: f64,
    /// Index (caller's numbering) of the largest error.
    pub argmax: u64,
    sum: f64,
    sum_sq: f64,
}

impl ErrorStats {
    /// Fold one error sample taken at input `index`.
    pub fn add(&mut self, index: u64, err: f64) {
        if err.is_nan() {
            self.nan_count += 1;
            return;
        }
        if self.count == 0 || err > self.max {
            self.max = err;
            self.argmax = index;
        }
        self.count += 1;
        self.sum += err;
        self.sum_sq += err * err;
    }

    /// Combine with statistics gathered over another part of the inputs.
    pub fn merge(&mut self, other: &ErrorStats) {
        if other.count > 0 && (self.count == 0 || other.max > self.max) {
            self.max = other.max;
            self.argmax = other.argmax;
        }
        self.count += other.count;
        self.nan_count += other.nan_count;
        self.sum += other.sum;
        self.sum_sq += other.sum_sq;
    }

    /// Mean error (0 when empty).
    pub fn mean(&self) -> f64 {
        if self.count == 0 {
            0.0
        } else {
            self.sum / self.count as f64
        }
    }

    /// Root-mean-square error (0 when empty).
    pub fn rms(&self) -> f64 {
        if self.count == 0 {
            0.0
        } else {
            (self.sum_sq / self.count as f64).sqrt()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ulp_distance_counts_representable_floats() {
        assert_eq!(ulp_distance(1.0, 1.0), Some(0));
        assert_eq!(
            ulp_distance(1.0, f32::from_bits(1.0f32.to_bits() + 3)),
            Some(3)
        );
        assert_eq!(ulp_distance(0.0, -0.0), Some(0));
        // Across zero: smallest subnormal on each side is 2 apart.
        assert_eq!(ulp_distance(f32::from_bits(1), -f32::from_bits(1)), Some(2));
        assert_eq!(ulp_distance(f32::MAX, f32::INFINITY), Some(1));
        assert_eq!(ulp_distance(f32::NAN, 1.0), None);
    }

    #[test]
    fn step_ulps_inverts_distance() {
        for x in [0.0f32, -0.0, 1.0, -1.0, 1e-40, 3.0e38, 1.0 / 255.0] {
            for s in [-3i64, -1, 1, 3] {
                let y = step_ulps(x, s);
                assert_eq!(ulp_distance(x, y), Some(s.unsigned_abs()), "{x} {s}");
            }
        }
        assert_eq!(step_ulps(f32::MAX, 5), f32::INFINITY);
        assert_eq!(step_ulps(0.0, -1), -f32::from_bits(1));
    }

    #[test]
    fn ulp_of_exact_values() {
        assert_eq!(f32_ulp_at(1.0), 2f64.powi(-23));
        assert_eq!(f32_ulp_at(0.999), 2f64.powi(-24));
        assert_eq!(f32_ulp_at(-3.0), 2f64.powi(-22));
        assert_eq!(f32_ulp_at(0.0), 2f64.powi(-149));
        // The exponent-field construction is 2^(e − 23) at every f32 binade and past it.
        for e in -126..=200 {
            let want = 2f64.powi(e.min(127) - 23);
            assert_eq!(f32_ulp_at(2f64.powi(e)), want, "2^{e}");
            assert_eq!(f32_ulp_at(-2f64.powi(e) * 1.75), want, "-1.75·2^{e}");
        }
        assert_eq!(ulp_error(1.0 + f32::EPSILON, 1.0), 1.0);
        // Multiplying by the reciprocal is dividing by the ULP, bit for bit, at every binade.
        for e in -160..=140 {
            for m in [1.0, 1.3, 1.999_999] {
                let exact = m * 2f64.powi(e);
                let got = (exact * 1.000_1) as f32;
                let want = (f64::from(got) - exact).abs() / f32_ulp_at(exact);
                assert_eq!(ulp_error(got, exact).to_bits(), want.to_bits(), "{exact:e}");
            }
        }
        assert_eq!(ulp_error(f32::INFINITY, f64::INFINITY), 0.0);
        assert!(ulp_error(f32::MAX, f64::INFINITY).is_infinite());
    }

    #[test]
    fn relative_error_edges() {
        assert_eq!(relative_error(1.5, 1.0), 0.5);
        assert_eq!(relative_error(0.0, 0.0), 0.0);
        assert!(relative_error(1.0, 0.0).is_infinite());
        assert!(relative_error(f64::NAN, 1.0).is_nan());
    }

    #[test]
    fn angles_are_accurate_at_both_ends() {
        let tiny = 1e-9f64;
        let a = angle_degrees([1.0, 0.0, 0.0], [1.0, tiny, 0.0]);
        crate::assert_within_abs!(
            a,
            tiny.atan().to_degrees(),
            < 1e-22,
            "literal: ≈ 15 f64 ULPs of 5.7e-8°, no cancellation at small angles",
            "angle of 1e-9"
        );
        let b = angle_degrees([1.0, 0.0, 0.0], [-1.0, tiny, 0.0]);
        crate::assert_within_abs!(
            b,
            180.0 - tiny.atan().to_degrees(),
            < 1e-12,
            "literal: ≈ 35 f64 ULPs of 180°, no cancellation near 180°",
            "angle of 180° less 1e-9"
        );
        assert!(angle_degrees([0.0; 3], [1.0, 0.0, 0.0]).is_nan());
        // Lengths whose squares leave f64's range are still directions.
        assert_eq!(angle_degrees([1e-320, 0.0, 0.0], [0.0, 1e300, 0.0]), 90.0);
        assert!(angle_degrees([f64::INFINITY, 0.0, 0.0], [1.0, 0.0, 0.0]).is_nan());
    }

    #[test]
    fn stats_track_max_mean_rms_and_nans() {
        let mut s = ErrorStats::default();
        s.add(0, 1.0);
        s.add(1, 3.0);
        s.add(2, f64::NAN);
        assert_eq!((s.max, s.argmax, s.count, s.nan_count), (3.0, 1, 2, 1));
        assert_eq!(s.mean(), 2.0);
        crate::assert_within_abs!(
            s.rms(),
            5f64.sqrt(),
            < 1e-15,
            "literal: ≈ 2 f64 ULPs of √5 (the mean square and its sqrt round)",
            "rms of 1 and 3"
        );
        let mut t = ErrorStats::default();
        t.add(7, 4.0);
        s.merge(&t);
        assert_eq!((s.max, s.argmax, s.count), (4.0, 7, 3));
    }

    #[test]
    fn mismatches_keep_first_examples() {
        let got = [1u32, 2, 3, 4];
        let m = Mismatches::count(&got, |i| if i == 2 { 9 } else { got[i] });
        assert_eq!(m.count, 1);
        assert_eq!(m.first, vec![(2, 3, 9)]);
    }
}
