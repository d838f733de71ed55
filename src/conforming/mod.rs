//! The worst conforming adapter, emulated on the one you have (feature `validate`; running it
//! needs `harness`).
//!
//! WGSL pins few f32 results. `+ − ×` may round to either neighbour; `/` may be 2.5 ULP off,
//! `inverseSqrt` 2 ULP, `exp`/`exp2` `3 + 2|x|` ULP, `log`/`log2` 3 ULP (absolute 2^-21 on
//! [0.5, 2]), the `unpack*norm` builtins 3 ULP; `sqrt`, `length`, `normalize`, `distance`, `dot`,
//! `pow`, `fma`, `mix`, `fract`, `cross`, `reflect` and matrix × vector inherit the accuracy of
//! their defining expressions; `pack*norm` may store either integer at a .5 tie; `pack2x16float`
//! may round each lane to either neighbouring f16; `f32` of an integer no f32 holds may be either
//! neighbour; subnormal inputs and outputs may be flushed (of every operation in the accuracy
//! table, comparisons, `min`, `max`, `clamp`, `floor` and the rest included, and of f16 pack and
//! unpack intermediates); `a·b + c` may be fused; and an implementation may reassociate,
//! `(a+b)+c ↔ a+(b+c)`, `(a−b)+c ↔ (a+c)−b`, `(a·b)/c ↔ (a/c)·b` (WGSL spec, "Floating Point
//! Evaluation"). The emulation takes the spec's examples as the rule they illustrate: every
//! grouping of a three-term sum (`(a+b)+c`, `a+(b+c)`, `(a+c)+b`; the same with a difference,
//! `(a−b)+c`, `(a+c)−b`, `a−(b−c)` and `(a+b)−c`, `a+(b−c)`, `(a−c)+b`), of a product over a
//! quotient (`(a·b)/c`, `(a/c)·b`, `a·(b/c)`), and of `dot`'s lanes (written order, reversed,
//! and the outer terms first at three lanes or pairwise at four). A helper's result in a sum or
//! difference counts as its returned expression would after inlining: a product a helper
//! returns may fuse into its caller's sum (`inline.rs`). A correctly rounded adapter such as lavapipe uses none of that freedom, so a
//! figure measured there holds on one adapter.
//!
//! [`emulate`] rewrites any WGSL module at the naga IR level so that every such operation is
//! evaluated at a chosen point of its allowed interval, then writes the module back as WGSL with
//! naga's backend: the result runs through [`crate::harness`] exactly like the original, and
//! [`crate::precision::check::PrecisionCheck::emulated`] runs property checks on it.
//! [`interval`] reads the same rules the other way: it evaluates a function's IR over
//! intervals at one input and returns an enclosure of every result they allow, a
//! machine-derived bound that the emulated results must lie in.
//!
//! ```
//! use prepass::conforming::{emulate, Emulation, Policy};
//! let src = "fn to_unit(d: u32) -> f32 { return f32(d) / 16777215.0; }";
//! let worst = emulate(src, &Emulation::new(Policy::Upper))?;
//! assert!(worst.source.contains("fn to_unit("));
//! assert_eq!(worst.sites, 2); // the conversion f32(d) (exact below 2^24) and the division
//! # Ok::<(), prepass::conforming::EmulateError>(())
//! ```
//!
//! # Policies
//! - [`Policy::Identity`]: every helper evaluates the original operation; the module computes
//!   bit for bit what the unmodified one does (a self-test checks it). Its helpers' freedom
//!   switches are constants, and the branches they rule out are dropped from the IR before the
//!   module is written (`fold.rs`): lavapipe compiled a normal encoder's identity module in
//!   about 1.5 s with them and 0.05 s without. What remains is the host's operation and the
//!   domain checks (the flag below).
//! - [`Policy::Upper`] / [`Policy::Lower`]: every interval at its upper / lower end; where the
//!   freedom is a choice between forms (fused or not, reassociated or not, flushed or not, the
//!   two bytes of a pack tie), the larger / smaller of the two results.
//! - [`Policy::Seeded`]: a choice per operation and per invocation — the hash of the seed, the
//!   operation's site and its operands' bits — among the lower end, the host's result and the
//!   upper end (both ends included), and between the forms.
//!
//! - [`Policy::Searched`]: each site, in each call context (which call of a helper it is in),
//!   at the end a direction table says, the table passed with every element; [`search`] climbs
//!   from the greedy tables to the worst one it finds.
//!
//! [`EmulatedKernel`] runs `Upper` and `Lower` as the searched module given the table of all
//! ones or all zeros (a uniform), which is the same choice at every site, and `Seeded(s)` as
//! the same module in its seeded mode with seed `s`: one compiled pipeline serves every policy
//! but the identity, where a CPU adapter spends far more on compiling than on running. The
//! direction is then a run-time value, and the error-free transformations (Dekker's product
//! error, TwoSum) read their operands through a run-time zero from the same argument
//! (`prepass_cf_opaque` in `core.wgsl`), which keeps the host compiler from folding and
//! rewriting them — SPIR-V does not mark them exact. With a constant direction or a literal
//! operand, lavapipe (Mesa 22.3 and 25.0) computes some error terms wrong, so a module built
//! by [`emulate`] alone (which writes the policy as a constant, for a module used on its own)
//! can leave a product unpushed or push it one step beyond the spec: `tests/conforming.rs`
//! (`every_policy_through_the_searched_module_matches_its_own_module`) counts both and checks
//! that the table's result is allowed (inside [`interval`]'s enclosure, or the exact
//! arithmetic's code) wherever the two differ. Run emulations through [`EmulatedKernel`].
//!
//! The fixed policies are greedy — each operation at its own extreme — which is not always the
//! composite's extreme (errors of opposite sign cancel); the seeded policy explores mixtures,
//! and the search looks for the worst mixture per input. Neither is a proof: the
//! everywhere-bounds in [`crate::linear_depth`] and the other modules are derived by hand from the
//! accuracy table, and the emulation checks that the functions stay inside them.
//!
//! # Results at the ends
//! `/`, `inverseSqrt`, `exp`, `exp2`, `log`, `log2` and the `unpack*norm` builtins are placed
//! at the end of their spec interval from an exact reference, not pushed from the host's
//! result: the helper computes the exact result as a double-f32 `hi + lo` — the quotient with
//! its exact residual `a − q·b` (Dekker), `1/sqrt(x)` refined by the residuals of the host's
//! `sqrt` and `1/y`, `exp2` and `log2` from their own range reduction and series in double-f32
//! (good to about 2^-40 relative), `v/255` with its exact residual — and returns the last float
//! inside `exact ± allowance` on the chosen side. That needs only a host whose `+ − ×` round to
//! nearest and whose `sqrt` and `/` are within a few ULPs; the host's `exp2`, `log2` and
//! `inverseSqrt` are not used where a result is placed. The allowance is shrunk by 2^-12 of
//! itself to cover the references' own error, so an end float closer than that to the edge
//! (at most 2^-12·k ULP, one input in a few thousand) is given up for its neighbour. ULPs are
//! WGSL's: the spacing of the floats around the exact value, the one below at a power of two.
//! The freedom checks (`tests/conforming/freedoms.rs`) compare every placed result with the
//! end computed in f64 and fail when one is not the last float inside.
//!
//! Where no reference is formed — a quotient or product beyond Dekker's range, an `exp2`
//! result below 2^-100, an exact 0 from an unpack — the host's result is pushed by the
//! allowance *less* the host's error, [`HostAccuracy`], counted in the spacing of the floats
//! just below the host's result and rounded back toward it, so the result stays inside
//! `exact ± allowance` without reaching its end. The emulator self-tests
//! (`tests/conforming.rs`) measure the host's error and check every emulated result against
//! the spec interval computed in f64.
//!
//! `sin` and `cos` have an absolute allowance, 2^-11 on `[−π, π]`, and none outside it
//! (indeterminate: the flag below is raised). They are pushed from the host's result by the
//! allowance less [`HOST_TRIG_ABS`] and less the push's own rounding; a conforming adapter's
//! whole reach is 3 % wider than the emulation's there.
//!
//! The either-neighbour rounding of `+ − ×` is found exactly with error-free transformations
//! (TwoSum, Dekker's product, Fast2Sum), and the fused `a·b + c` is built the same way; they need
//! the host to round to nearest without contraction, reassociation or flushing, as lavapipe does
//! where the directions are run-time values (see [`EmulatedKernel`] above for where it does not).
//! [`EmulatedKernel::new`] refuses an adapter on which those helpers come back otherwise
//! ([`check_host`], feature `harness`: it runs them as shipped, at inputs where each freedom
//! changes their results). Lavapipe passes, though its compiler does fuse a product used once
//! into the sum it feeds and folds the pack lanes' Fast2Sum: neither touches what must be exact
//! (`probe.rs` says why).
//! Dekker's split is skipped where it could overflow or underflow (operands beyond 2^±60,
//! products below 2^-100): there the host's rounding, one allowed neighbour, stands.
//!
//! `m * v` and `v * m` are rewritten as one inherited `dot` per result lane (a row of `m`, or
//! a column, with `v`), so every product and sum of them has the freedoms of `dot`.
//!
//! # Exact functions
//! The functions in [`EXACT_FUNCTIONS`] (the octahedral codes' lattices) are left as they are:
//! on the arguments the shipped code passes them every f32 value they compute is an integer of
//! magnitude below 2^24, so every operation (`+ − ×` correctly rounded, `dot` and `m * v`
//! inherited from them, `abs`, `sign`, `min`) is exact on every conforming adapter, up to the
//! sign of a zero, which WGSL lets implementations ignore and no caller of theirs depends on.
//! Emulating them only costs compile time: the emulated normal modules took lavapipe 177 s
//! rather than 85 s to compile and run in `tests/conforming.rs`'s
//! `every_normal_encoding_under_emulation`. `tests/conforming.rs`
//! (`exact_functions_are_exact_on_their_domain`) emulates them anyway
//! ([`Emulation::with_exact_functions_emulated`]) under the upper, lower and seeded policies on
//! their domain and fails unless every result equals the host's.
//!
//! # Not emulated
//! Left at the host's accuracy, and listed in [`Emulated::uncovered`] when a module uses them:
//! trigonometric functions other than `sin` and `cos`, hyperbolic functions, `smoothstep`, `refract`, `faceForward`, `%` on f32,
//! `quantizeToF16`, `ldexp`, `modf`, `frexp`, `determinant`, `inverse`, matrix arithmetic other
//! than matrix × vector, and conversion to f16 — any f32 operation the pass does not rewrite is
//! listed, under naga's name for it, except the exact ones (negation, `select`, `transpose`,
//! bitcasts). `tests/conforming.rs` fails when a shipped module, a composed scene module or the
//! example renderer's shader lists anything. Texel conversions at texture reads and render
//! target writes follow WebGPU's texel-format rules, not WGSL's accuracy table, and are taken as
//! the host does them. `sqrt(±0)` returns 0: the inherited interval `1/inverseSqrt(0)` is
//! unbounded, and every implementation known returns 0.
//!
//! # Indeterminate results
//! An operation outside its domain — a divisor outside ±[2^-126, 2^126], `inverseSqrt`, `log`
//! or `log2` of a value ≤ 0, subnormal or infinite, `sin` or `cos` beyond `[−π, π]`, `exp2`
//! that overflows, a `pack2x16float` lane beyond ±65504 — makes the spec's result indeterminate. The helpers then raise a private flag,
//! [`UNDEFINED_FLAG`]; [`crate::conforming::EmulatedKernel`] reads it after each evaluation as a
//! tail word of the same pipeline ([`crate::harness::Gpu::kernel_with_tail`]), and for every
//! function `f` of the module the emulation also adds `prepass_cf_undefined__f` (same
//! parameters, returns 1 when any operation of that evaluation left its domain), for a module
//! used on its own: a check reports such inputs
//! as "not defined by the spec" instead of failing them. Any result that is not finite, and any
//! operation on a NaN or an infinity, raises the flag too (the spec's finite-math assumption):
//! bit 1 of its word from the arithmetic helpers, bit 2 from the paths they do not see (`min`,
//! `max`, `clamp`, `abs`, `floor`, comparisons, the builtins the
//! identity policy calls unchanged, an infinite or NaN `unpack2x16float` half, `u32` or `i32` of
//! one — exact conversions, so they take no freedom and read no slot);
//! [`crate::conforming::EmulatedKernel::run_flags`] gives the word).
//! The flag is per evaluation, not per data dependency: an operation whose indeterminate result
//! a `select` then discards (as `ld_near_over_far` discards `near / far` for an infinite far
//! plane) still raises it, so the flag over-reports; the suites read values and flags apart.

mod fold;
mod inline;
mod rewrite;

#[cfg(feature = "harness")]
mod kernel;
#[cfg(feature = "harness")]
#[cfg_attr(docsrs, doc(cfg(feature = "harness")))]
pub use kernel::{EmulatedKernel, FIXED_TABLE_AS_COLUMNS, UNDEFINED_FLAG};
#[cfg(feature = "harness")]
mod probe;
#[cfg(feature = "harness")]
#[cfg_attr(docsrs, doc(cfg(feature = "harness")))]
pub mod search;
#[cfg(feature = "harness")]
#[cfg_attr(docsrs, doc(cfg(feature = "harness")))]
pub use probe::{PROBE_FUNCTION, PROBE_WGSL, check_host, check_host_with, probe_source};

pub mod cts;
pub mod interval;

use std::collections::BTreeMap;
use std::fmt::Write as _;

/// Where in its allowed interval every free operation is evaluated.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Policy {
    /// The original operation: bit-identical to the unmodified module.
    Identity,
    /// Every interval at its upper end; every choice of form the larger result.
    Upper,
    /// Every interval at its lower end; every choice of form the smaller result.
    Lower,
    /// A per-operation, per-invocation choice from this seed, both ends included.
    Seeded(u32),
    /// Each site's end read from a direction table passed with every element
    /// ([`search::DirectionTable`], feature `harness`): the policy of the worst-case search,
    /// where one compiled module serves every table.
    Searched,
}

impl Policy {
    /// The policies a suite runs: upper, lower and three seeds.
    pub const WORST: [Policy; 5] = [
        Policy::Upper,
        Policy::Lower,
        Policy::Seeded(1),
        Policy::Seeded(2),
        Policy::Seeded(3),
    ];

    fn code(self) -> (u32, u32) {
        match self {
            Policy::Identity => (0, 0),
            Policy::Upper => (1, 0),
            Policy::Lower => (2, 0),
            Policy::Seeded(s) => (3, s),
            Policy::Searched => (4, 0),
        }
    }
}

impl std::fmt::Display for Policy {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Policy::Identity => write!(f, "identity"),
            Policy::Upper => write!(f, "upper"),
            Policy::Lower => write!(f, "lower"),
            Policy::Seeded(s) => write!(f, "seeded({s})"),
            Policy::Searched => write!(f, "searched"),
        }
    }
}

/// Which freedoms of the spec the emulation uses (all by default); bit values match
/// `core.wgsl`'s `PREPASS_CF_*` constants.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Freedoms(pub u32);

impl Freedoms {
    /// `/` within 2.5 ULP.
    pub const DIVISION: Freedoms = Freedoms(1);
    /// `inverseSqrt` within 2 ULP (and `sqrt` through it).
    pub const INVERSE_SQRT: Freedoms = Freedoms(2);
    /// `exp`, `exp2`, `log`, `log2` (and `pow` through them).
    pub const EXP_LOG: Freedoms = Freedoms(4);
    /// `unpack4x8unorm/snorm`, `unpack2x16unorm/snorm` within 3 ULP.
    pub const UNPACK: Freedoms = Freedoms(8);
    /// `pack4x8unorm/snorm`, `pack2x16unorm/snorm`: either integer at a .5 tie;
    /// `pack2x16float`: either neighbouring f16 per lane.
    pub const PACK: Freedoms = Freedoms(16);
    /// `+ − ×` rounded to either neighbour.
    pub const ROUNDING: Freedoms = Freedoms(32);
    /// Subnormal inputs and outputs flushed to zero (f32, and the f16 lanes of
    /// `pack2x16float`/`unpack2x16float`), at every operation of the accuracy table: comparisons,
    /// `min`, `max`, `clamp`, `floor` and the other exactly rounded ones included.
    pub const FLUSH: Freedoms = Freedoms(64);
    /// `a·b + c` fused into one rounding.
    pub const FUSION: Freedoms = Freedoms(128);
    /// The spec's reassociations.
    pub const REASSOCIATION: Freedoms = Freedoms(256);
    /// `sqrt`, `length`, `normalize`, `distance`, `dot`, `pow`, `fma`, `mix`, `fract`,
    /// `cross`, `reflect`, matrix × vector evaluated as their defining expressions.
    pub const INHERITED: Freedoms = Freedoms(512);
    /// `f32(u32)`, `f32(i32)`: either neighbour where the integer is not an f32 (above 2^24).
    pub const CONVERSION: Freedoms = Freedoms(1024);
    /// `sin`, `cos` within their absolute allowance, [`allowance::TRIG_ABS`], on `[−π, π]`.
    pub const TRIG: Freedoms = Freedoms(2048);
    /// Every freedom.
    pub const ALL: Freedoms = Freedoms(4095);

    /// Both sets.
    pub const fn union(self, other: Freedoms) -> Freedoms {
        Freedoms(self.0 | other.0)
    }

    /// The constant's name for a single freedom (`FUSION`), `None` for a set of several.
    pub const fn name(self) -> Option<&'static str> {
        Some(match self.0 {
            1 => "DIVISION",
            2 => "INVERSE_SQRT",
            4 => "EXP_LOG",
            8 => "UNPACK",
            16 => "PACK",
            32 => "ROUNDING",
            64 => "FLUSH",
            128 => "FUSION",
            256 => "REASSOCIATION",
            512 => "INHERITED",
            1024 => "CONVERSION",
            2048 => "TRIG",
            _ => return None,
        })
    }
}

/// The host adapter's own error where the emulation starts from the host's result, in ULPs of
/// the exact result: the push is the spec's allowance less this. That is only where no exact
/// reference is formed (see "Results at the ends" in the module docs): a quotient or product
/// beyond Dekker's range (operands beyond 2^±60, results below 2^-100), `exp`/`exp2` results
/// below 2^-100, and an exact 0 from `unpack*norm`. Defaults: lavapipe's, measured by
/// `tests/conforming.rs` (which fails, naming the field, when the running adapter is worse).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HostAccuracy {
    /// `/`: 0.5, correctly rounded.
    pub division_ulp: f64,
    /// `exp`, `exp2`: 2.5 (lavapipe's polynomial `exp2` measured 2.01 ULP off).
    pub exp_ulp: f64,
}

impl Default for HostAccuracy {
    fn default() -> Self {
        HostAccuracy {
            division_ulp: 0.5,
            exp_ulp: 2.5,
        }
    }
}

/// The spec's allowances that the pushes fill (WGSL "Floating Point Accuracy", f32).
pub mod allowance {
    /// `/`, ULP.
    pub const DIVISION_ULP: f64 = 2.5;
    /// `inverseSqrt`, ULP.
    pub const INVERSE_SQRT_ULP: f64 = 2.0;
    /// `log`, `log2` outside [0.5, 2], ULP.
    pub const LOG_ULP: f64 = 3.0;
    /// `log`, `log2` on [0.5, 2], absolute: 2^-21.
    pub const LOG_ABS: f64 = 4.76837158203125e-7;
    /// `unpack*norm`, ULP.
    pub const UNPACK_ULP: f64 = 3.0;
    /// `exp`, `exp2` at `x`, ULP: `3 + 2|x|`.
    pub fn exp_ulp(x: f64) -> f64 {
        3.0 + 2.0 * x.abs()
    }
    /// `sin`, `cos` on `[−π, π]`, absolute: 2^-11. Outside that range the spec states no
    /// accuracy: the result is indeterminate (the emulation raises its flag).
    pub const TRIG_ABS: f64 = 4.8828125e-4;
    /// The largest f32 inside `[−π, π]` (`f32::consts::PI` rounds up, past π): `sin` and `cos`
    /// of a larger magnitude have no accuracy in the spec.
    pub const TRIG_DOMAIN: f32 = 3.141_592_5;
}

/// The host's `sin` and `cos` error, absolute, on `[−π, π]`: the emulation pushes the host's
/// result by [`allowance::TRIG_ABS`] less this (and less the push's own rounding, 2^-24), so
/// the result stays inside the spec's interval. No exact reference is formed for them: this
/// bounds lavapipe's (measured by `tests/conforming.rs`, which fails on an adapter whose error
/// is larger), and costs a conforming adapter's reach 3 % of the allowance.
pub const HOST_TRIG_ABS: f64 = 1.52587890625e-5;

/// Functions every conforming adapter evaluates exactly on the arguments the shipped code
/// passes them, which the emulation therefore leaves as they are (see the module docs, "Exact
/// functions"), each with its reason.
pub const EXACT_FUNCTIONS: &[(&str, &str)] = &[
    (
        "oct_lattice",
        "wgsl/normal_oct.wgsl: called with whole-number codes c <= M, M = 2^N - 1 <= 65535 \
         and mm = vec2(M), every value it computes is an integer of magnitude below 2^17",
    ),
    (
        "hemioct_lattice",
        "wgsl/normal_hemioct.wgsl: called with whole-number codes c <= 4095, every value it \
         computes is an integer of magnitude below 2^14",
    ),
    (
        "signed_oct_lattice",
        "wgsl/normal_signed_oct.wgsl: called with whole-number codes c <= 1023, every value it \
         computes is an integer of magnitude below 2^11",
    ),
];

/// What to emulate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Emulation {
    /// Where each operation lands.
    pub policy: Policy,
    /// Which freedoms are used.
    pub freedoms: Freedoms,
    /// The host adapter's own error.
    pub host: HostAccuracy,
    /// Whether [`EXACT_FUNCTIONS`] are emulated too (only to check that they are exact).
    pub emulate_exact: bool,
}

impl Emulation {
    /// Every freedom, lavapipe's host accuracy, [`EXACT_FUNCTIONS`] left as they are.
    pub fn new(policy: Policy) -> Self {
        Emulation {
            policy,
            freedoms: Freedoms::ALL,
            host: HostAccuracy::default(),
            emulate_exact: false,
        }
    }

    /// [`EXACT_FUNCTIONS`] emulated like every other function: what the check that they are
    /// exact compares with the host.
    pub fn with_exact_functions_emulated(mut self) -> Self {
        self.emulate_exact = true;
        self
    }

    /// Only these freedoms.
    pub fn with_freedoms(mut self, freedoms: Freedoms) -> Self {
        self.freedoms = freedoms;
        self
    }

    /// A different host accuracy.
    pub fn with_host(mut self, host: HostAccuracy) -> Self {
        self.host = host;
        self
    }

    fn halves(allowance: f64, host: f64) -> i32 {
        (2.0 * (allowance - host)).floor().max(0.0) as i32
    }

    fn prelude(&self) -> String {
        let (policy, seed) = self.policy.code();
        let h = &self.host;
        let mut s = String::new();
        let _ = writeln!(s, "const PREPASS_CF_POLICY: u32 = {policy}u;");
        let _ = writeln!(s, "const PREPASS_CF_SEED: u32 = {seed}u;");
        let _ = writeln!(s, "const PREPASS_CF_FREEDOMS: u32 = {}u;", self.freedoms.0);
        let div = Self::halves(allowance::DIVISION_ULP, h.division_ulp);
        let _ = writeln!(s, "const PREPASS_CF_DIV_HALVES: i32 = {div};");
        let exp_host = (2.0 * h.exp_ulp).ceil() as i32;
        let _ = writeln!(s, "const PREPASS_CF_EXP_HOST_HALVES: i32 = {exp_host};");
        let unpack = Self::halves(allowance::UNPACK_ULP, h.division_ulp);
        let _ = writeln!(s, "const PREPASS_CF_UNPACK_HALVES: i32 = {unpack};");
        // 2^-24: the push's own rounding, at most half an ULP of a result below 1 + 2^-11.
        let trig = allowance::TRIG_ABS - HOST_TRIG_ABS - 2f64.powi(-24);
        let _ = writeln!(s, "const PREPASS_CF_TRIG_PUSH: f32 = {trig:e};");
        let _ = writeln!(
            s,
            "const PREPASS_CF_TRIG_DOMAIN: f32 = {:e};",
            allowance::TRIG_DOMAIN
        );
        s
    }
}

/// A module rewritten for emulation.
#[derive(Clone, Debug)]
pub struct Emulated {
    /// The emulating module's WGSL (naga's WGSL backend): the original functions (under the
    /// names [`Emulated::function_name`] gives), the helper library, and one
    /// `prepass_cf_undefined__f` per function `f`.
    pub source: String,
    /// How many operations were rewritten.
    pub sites: usize,
    /// Inexact operations the module uses that are left at the host's accuracy.
    pub uncovered: Vec<String>,
    /// The policy it was built for.
    pub emulation: Emulation,
    undefined: BTreeMap<String, String>,
    tables: BTreeMap<String, [String; 4]>,
    names: BTreeMap<String, String>,
}

impl Emulated {
    /// The name under which `function` stands in [`Emulated::source`]: naga's WGSL backend
    /// respells some identifiers (`view_z_from_depth24` becomes `view_z_from_depth24_`).
    /// `None` when the module has no such function.
    pub fn function_name(&self, function: &str) -> Option<&str> {
        self.names.get(function).map(String::as_str)
    }

    /// Name of the function that returns 1 where `function`'s result is not defined by the spec
    /// (an operation left its domain), 0 elsewhere; `None` for functions whose parameters the
    /// wrapper cannot spell (pointers, arrays).
    pub fn undefined_function(&self, function: &str) -> Option<&str> {
        self.undefined.get(function).map(String::as_str)
    }

    /// Under [`Policy::Searched`]: the names of `function`'s table wrappers, (values, flag),
    /// which take `function`'s parameters, then the two `vec4<u32>` halves of a
    /// [`search::DirectionTable`] and the mode ([`search::TABLE_MODE`] or
    /// [`search::seeded_mode`]). `None` under other policies, and for functions without a
    /// result or with parameters the wrapper cannot spell.
    pub fn table_functions(&self, function: &str) -> Option<(&str, &str)> {
        self.tables
            .get(function)
            .map(|[v, u, ..]| (v.as_str(), u.as_str()))
    }

    /// Under [`Policy::Searched`]: the two wrappers (same parameters as
    /// [`Emulated::table_functions`]) that return which table slots an evaluation reads, as the
    /// `vec4<u32>` halves of a slot mask.
    pub fn touched_functions(&self, function: &str) -> Option<(&str, &str)> {
        self.tables
            .get(function)
            .map(|[_, _, a, b]| (a.as_str(), b.as_str()))
    }
}

/// Why a module could not be emulated.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EmulateError(pub String);

impl std::fmt::Display for EmulateError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "conforming-adapter emulation failed: {}", self.0)
    }
}

impl std::error::Error for EmulateError {}

/// The helper library, `core.wgsl`.
pub const CORE_WGSL: &str = include_str!("core.wgsl");

fn parse(
    source: &str,
    stage: &str,
) -> Result<(naga::Module, naga::valid::ModuleInfo), EmulateError> {
    let checked = crate::wgsl::parse_and_validate(source)
        .map_err(|e| EmulateError(format!("{stage}: {e}")))?;
    Ok((checked.module, checked.info))
}

/// `module` with its helpers' results inlined into its sums ([`inline`]), validated again.
fn with_inlined_sums(
    mut module: naga::Module,
    emulation: &Emulation,
) -> Result<(naga::Module, naga::valid::ModuleInfo), EmulateError> {
    let exact = emulation.emulate_exact;
    inline::inline_sums(&mut module, &|n| rewrite::skipped_exact(n, exact))
        .map_err(EmulateError)?;
    let info = naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::SHADER_FLOAT16_IN_FLOAT32,
    )
    .validate(&module)
    .map_err(|e| EmulateError(format!("the module with inlined sums is invalid: {e:?}")))?;
    Ok((module, info))
}

/// Rewrite `source` so that every f32 operation the WGSL spec leaves free is evaluated as
/// `emulation` says; see the module docs for what is covered and how the host's error is
/// accounted for.
pub fn emulate(source: &str, emulation: &Emulation) -> Result<Emulated, EmulateError> {
    // Pass 1: which vector wrappers the module needs, and the parameter lists of its functions.
    let (m1, i1) = with_inlined_sums(parse(source, "the source")?.0, emulation)?;
    let plan1 = rewrite::plan(&m1, &i1, emulation.emulate_exact);
    let mut text = String::with_capacity(source.len() + CORE_WGSL.len() + 4096);
    // Helpers first: a call may only reach a function earlier in naga's arena, and the front
    // end keeps source order where no dependency decides it.
    text.push_str(&emulation.prelude());
    text.push_str(CORE_WGSL);
    for w in plan1.wrappers.values() {
        text.push_str(w);
    }
    text.push_str(source);
    text.push('\n');
    let mut undefined = BTreeMap::new();
    let mut tables = BTreeMap::new();
    for (_, f) in m1.functions.iter() {
        let Some(name) = f.name.as_deref() else {
            continue;
        };
        if name.starts_with(rewrite::PREFIX) {
            continue;
        }
        let params: Option<Vec<String>> = f
            .arguments
            .iter()
            .enumerate()
            .map(|(k, a)| rewrite::wgsl_type(&m1, a.ty).map(|t| format!("a{k}: {t}")))
            .collect();
        let Some(params) = params else { continue };
        let args: Vec<String> = (0..params.len()).map(|k| format!("a{k}")).collect();
        let wrapper = format!("{}undefined__{name}", rewrite::PREFIX);
        let call = format!("{name}({})", args.join(", "));
        let result = f
            .result
            .as_ref()
            .and_then(|r| rewrite::wgsl_type(&m1, r.ty));
        if let (Policy::Searched, Some(result)) = (emulation.policy, &result) {
            // The table wrappers: the direction table from two trailing vec4<u32> arguments, then
            // the mode (table or seeded, and the seed).
            let p = rewrite::PREFIX;
            let tparams = [
                params.clone(),
                vec![
                    format!("{p}t0: vec4<u32>"),
                    format!("{p}t1: vec4<u32>"),
                    format!("{p}t2: vec4<u32>"),
                ],
            ]
            .concat()
            .join(", ");
            let set = format!("{p}dirs_lo = {p}t0;\n    {p}dirs_hi = {p}t1;\n    {p}mode = {p}t2;");
            let (tv, tu) = (
                format!("{p}table__{name}"),
                format!("{p}table_undefined__{name}"),
            );
            let _ = writeln!(
                text,
                "fn {tv}({tparams}) -> {result} {{\n    {set}\n    return {call};\n}}\n\
                 fn {tu}({tparams}) -> u32 {{\n    {set}\n    {p}undefined = 0u;\n    _ = {call};\n    return {p}undefined;\n}}"
            );
            // The slots the evaluation reads, half by half.
            let mut touched = Vec::new();
            for (h, half) in ["lo", "hi"].into_iter().enumerate() {
                let tt = format!("{p}table_touched{h}__{name}");
                let _ = writeln!(
                    text,
                    "fn {tt}({tparams}) -> vec4<u32> {{\n    {set}\n    {p}touched_lo = vec4<u32>();\n    {p}touched_hi = vec4<u32>();\n    _ = {call};\n    return {p}touched_{half};\n}}"
                );
                touched.push(tt);
            }
            tables.insert(
                name.to_string(),
                [tv, tu, touched[0].clone(), touched[1].clone()],
            );
        }
        let body = if f.result.is_some() {
            format!("_ = {call};")
        } else {
            format!("{call};")
        };
        let _ = writeln!(
            text,
            "fn {wrapper}({}) -> u32 {{\n    prepass_cf_undefined = 0u;\n    {body}\n    return prepass_cf_undefined;\n}}",
            params.join(", ")
        );
        undefined.insert(name.to_string(), wrapper);
    }
    // Pass 2: the same plan on the combined module (its own handles), applied.
    let (mut m2, i2) = with_inlined_sums(
        parse(&text, "the module with the helper library")?.0,
        emulation,
    )?;
    let plan2 = rewrite::plan(&m2, &i2, emulation.emulate_exact);
    let sites = rewrite::apply(&mut m2, &plan2).map_err(EmulateError)?;
    fold::fold(&mut m2);
    let info = naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::SHADER_FLOAT16_IN_FLOAT32,
    )
    .validate(&m2)
    .map_err(|e| EmulateError(format!("the rewritten module is invalid: {e:?}")))?;
    let source = naga::back::wgsl::write_string(&m2, &info, naga::back::wgsl::WriterFlags::empty())
        .map_err(|e| EmulateError(format!("naga's WGSL backend: {e}")))?;
    // naga's namer may respell identifiers (a trailing digit gains `_`, `__` becomes `_`): read
    // the names back, in arena order, to map each original name to the emitted one.
    let (emitted, _) = parse(&source, "naga's WGSL output")?;
    if emitted.functions.len() != m2.functions.len() {
        return Err(EmulateError(
            "naga's WGSL output has a different set of functions".into(),
        ));
    }
    let names: BTreeMap<String, String> = m2
        .functions
        .iter()
        .zip(emitted.functions.iter())
        .filter_map(|((_, a), (_, b))| Some((a.name.clone()?, b.name.clone()?)))
        .collect();
    let undefined = undefined
        .into_iter()
        .filter_map(|(f, w)| Some((f, names.get(&w)?.clone())))
        .collect();
    let tables = tables
        .into_iter()
        .filter_map(|(f, ws): (String, [String; 4])| {
            let mapped: Option<Vec<String>> = ws.iter().map(|w| names.get(w).cloned()).collect();
            Some((f, <[String; 4]>::try_from(mapped?).ok()?))
        })
        .collect();
    Ok(Emulated {
        source,
        sites,
        uncovered: plan1.uncovered.into_iter().collect(),
        emulation: *emulation,
        undefined,
        tables,
        names,
    })
}
