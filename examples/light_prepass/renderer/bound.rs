//! How far a diet frame may be from the fat frame, pixel by pixel, in 8-bit output levels:
//! derived from the encodings' maximum errors and the lighting model. The test
//! (`tests/light_prepass.rs`) checks every pixel against it and prints the derivation's terms at
//! the worst pixel when one fails.
//!
//! # Derivation
//!
//! The fat and diet frames share everything but the G-buffer's normals and depth: the same
//! geometry and depth test, the same roughness code (stored exactly in both, in the frame's
//! form: log8 or a GGX byte, decoded to the same exponent `n` by [`power_of_code`]), the same
//! lights, the same volumes and the same WGSL. So a pixel differs only through
//!
//! 1. **the normal**, off by at most an angle `θ` ([`normal_angle`]); for unit vectors the chord
//!    `|n − n'| ≤ θ`, so any dot product with a unit vector moves by at most `θ`;
//! 2. **the position**, rebuilt from depth: view depth off by a relative `E` ([`depth_relative`]),
//!    so the point moves by `ε_p = E·|p|` along its ray.
//!
//! For each light (view-space centre `c`, radius `r`, colour `col`) at fat point `p`, distance
//! `d = |c − p|`, unit `l`, `v = −p/|p|`:
//! - the unit light and view directions move by chords `ε_l ≤ 2ε_p/d`, `ε_v ≤ 2ε_p/|p|`;
//! - the window `A(d) = (1 − (d/r)²)²` is Lipschitz with `max|A'| = 4/r · max x(1 − x²) =
//!   8/(3√3·r) ≈ 1.54/r`, so `ΔA ≤ 1.54·ε_p/r`; the spot ramp `S` (slope `1/(cos_in − cos_out)`)
//!   moves by `ε_l/(cos_in − cos_out)`; `att = A·S`, `Δatt ≤ ΔA·S⁺ + A⁺·ΔS` with the upper values
//!   `A⁺, S⁺` over the moved point;
//! - the diffuse weight `D = max(N·L, 0)·att`: `ΔD ≤ att⁺·(θ + ε_l) + min(1, N·L⁺)·Δatt`;
//! - the half vector `H = (l + v)/|l + v|` moves by a chord `≤ 2(ε_l + ε_v)/|l + v|`, the angle
//!   between `n` and `H` by `Δφ ≤ θ + (π/2)·chord`, and `cos^n φ` by at most `√n·Δφ`
//!   (`max_φ n·sin φ·cos^(n−1) φ ≤ √n` for `n ≥ 1`); the specular weight `S_i = D·(N·H)^n` moves
//!   by `ΔD + D⁺·(√n·Δφ + 2·pow_relative)` (`pow_relative`: WGSL's `exp2(y·log2 x)` allowance,
//!   `prepass::lighting::lpp::bounds::pow_relative`, once per frame); both weights add
//!   `128u·D⁺` (`u = 2^-24`) for the f32 evaluation of P in the two frames.
//!
//! Sums over the lights: the two-buffer layout stores `Σ col·D_i` and `Σ col·S_i`, so each moves
//! by the sum of the moves. The one-buffer layout stores `L = lum(Σ col·D_i)` and
//! `A = Σ lum(col)·S_i`, and the combine rebuilds `S = L·min(A/L, 1)^m`; its gradient is bounded
//! (`|∂S/∂A| ≤ m`, `|∂S/∂L| ≤ max(1, m − 1)` for `m ≥ 1`), so `ΔS ≤ m·ΔA + max(1, m − 1)·ΔL`.
//! The light buffer rounds at every blend, within one unit in the last place whatever the
//! rounding mode (Vulkan leaves it to the implementation): rgba16float to `2^-10` relative of
//! the running sum (`k` blends: `k·2^-10` of the final sum, plus `2^-24` absolute for f16
//! subnormals, for each frame, so twice that between frames), rgba8unorm to `1/255` per blend.
//! The composite `C = albedo·diffuse + gloss·specular` moves
//! by `albedo_max·Δdiffuse + gloss_max·Δspecular`, and the rgba16float output rounds each frame
//! by `2^-10·C`. The tone curve is monotonic, so the level moves by at most
//! `255·(T(C + ΔC) − T(C − ΔC))`, plus 1 for the two roundings to a level.
//!
//! Two things the frames do not share, and why they add nothing: the D24 layout's hardware
//! depth buffer is `depth24plus-stencil8`, not `depth32float`. The scene has no coplanar
//! surfaces, so the same surface wins pass (a)'s depth test in both. A light volume's depth
//! test may decide differently only where the scene lies within one 24-bit depth step of the
//! volume's mesh, which encloses the light's sphere. There the light's attenuation is at most
//! `A(r − ε_p) ≤ 1.54·ε_p/r`, already in `Δatt`, because `ε_p` includes that step.
//!
//! Normals whose view-space `z` is negative are outside xy FP16's and hemi-octahedral codes'
//! domain: they decode mirrored, with no bound — those pixels are excluded from the check and
//! counted, and the test requires the artefact to show there.

use super::render::FatGBuffer;
use super::scene::Material;
use super::volumes::LightGpu;
use super::{Config, LightFormat, Storage};
use glam::{Vec2, Vec3};
use prepass::scene::{DepthStorage, LightBuffers, NormalEncoding, RoughnessChoice};

/// The Blinn-Phong exponent the light pass decodes from roughness code `code` stored in form
/// `r`, as the WGSL computes it (`shaders::roughness_code`), through the decoders' Rust twins:
/// log8's power; for the GGX forms the power `2/α² − 2` of the decoded `α`, at most
/// [`MAX_POWER`](super::MAX_POWER).
pub fn power_of_code(r: RoughnessChoice, code: u32) -> f32 {
    use prepass::roughness_ggx as ggx;
    let from_alpha = |a: f32| 2.0 / (a * a).max(2.0 / (super::MAX_POWER + 2.0)) - 2.0;
    match r {
        RoughnessChoice::None | RoughnessChoice::Log8 => {
            prepass::roughness::decode_log_roughness(code, super::MAX_POWER)
        }
        RoughnessChoice::Ggx8 => from_alpha(ggx::decode_roughness_ggx8_alpha(code)),
        RoughnessChoice::Ggx8Log => from_alpha(ggx::decode_roughness_ggx8_log_alpha(code)),
        RoughnessChoice::Godot8 => {
            let r = ggx::decode_roughness_godot8(code);
            from_alpha(r * r)
        }
    }
}

/// The largest angle (radians) between a unit normal and its decoded code, derived:
/// - **xyz8**: each component rounds to a step of `2/255`, off by `≤ 1/255`; the vector moves by
///   `≤ √3/255`, its direction by `asin(√3/255)` (0.389°; measured 0.380°);
/// - **octahedral, b bits an axis**: each axis rounds off by `δ ≤ 1/(2^b − 1)` (the precise
///   encoder picks the best of four neighbours, which include the rounded code); the decode
///   `(u, v, 1 − |u| − |v|)` (folded below the equator) moves by `≤ √6·δ` (x and y by `δ`, z by
///   `2δ`) and has length `≥ 1/√3`, so the direction moves by `asin(3√2·δ)`;
/// - **xy FP16** (z ≥ 0 only): x and y round to `2^-11` relative (`2^-25` absolute below
///   `2^-14`), so `|Δxy| ≤ 2^-11 + 2^-24.5`; `r² = x² + y²` moves by `q ≤ 2|Δxy| + |Δxy|²`, and
///   `z = √(1 − r²)` by `|Δz| ≤ min(√q, q/z)` (`|z − z'| = |z² − z'²|/(z + z')`): together
///   `asin(|Δxy| + |Δz|)` — 1.8° at the horizon (measured 1.37°), far less above it
///   ([`normal_angle_at`]);
/// - **hemioct24** (z ≥ 0 only): the octahedral bound on its 12-bit lattice.
///
/// Each adds `2^-20` rad for the f32 evaluation of the encoder and decoder (a few ULP).
pub fn normal_angle(e: NormalEncoding) -> f64 {
    normal_angle_at(e, 0.0)
}

/// [`normal_angle`] for a normal whose view-space z is `z`: the same for every encoding but
/// xy FP16, whose error grows towards the horizon (`|Δz| ≤ min(√q, q/|z|)`).
pub fn normal_angle_at(e: NormalEncoding, z: f64) -> f64 {
    let oct = |bits: i32| {
        (3.0 * 2f64.sqrt() / (2f64.powi(bits) - 1.0))
            .min(1.0)
            .asin()
    };
    let a = match e {
        // The best fit's code is never farther than the rounding one's (a candidate).
        NormalEncoding::Xyz8 | NormalEncoding::Xyz8Best => (3f64.sqrt() / 255.0).asin(),
        NormalEncoding::Xyz10 => (3f64.sqrt() / 1023.0).asin(),
        NormalEncoding::Snorm8 => (3f64.sqrt() / 254.0).asin(),
        NormalEncoding::Oct16 => oct(8),
        NormalEncoding::Oct20 => oct(10),
        NormalEncoding::Oct24 | NormalEncoding::Hemioct24 | NormalEncoding::Oct24Unity => oct(12),
        NormalEncoding::Oct32 => oct(16),
        // Substrate's centred 11-bit grid: steps of 1/1023 where oct's are 2/(2^bits − 1).
        NormalEncoding::Substrate => (3.0 * 2f64.sqrt() / 2046.0).asin(),
        // The signed octahedron's hemi-octahedral 10-bit grid: sin ≤ 2√6·h, h = 1/2046
        // (`tests/normal_signed_oct.rs`).
        NormalEncoding::SignedOct => (2.0 * 6f64.sqrt() / 2046.0).asin(),
        NormalEncoding::XyFp16 => {
            let dxy = 2f64.powi(-11) + 2f64.powf(-24.5);
            let q = 2.0 * dxy + dxy * dxy;
            let dz = q.sqrt().min(q / z.abs());
            (dxy + dz).min(1.0).asin()
        }
    };
    a + 2f64.powi(-20)
}

/// Whether the encoding keeps only normals with `z ≥ 0` (view space).
pub fn hemisphere_only(e: NormalEncoding) -> bool {
    matches!(e, NormalEncoding::XyFp16 | NormalEncoding::Hemioct24)
}

/// The relative error of the rebuilt view depth at view depth `vz`, against the fat layout's
/// f32 view depth of the same rasterised window depth:
/// - **D32F**: the depth buffer holds the very f32 window depth the fat layout converted, and
///   the same WGSL function converts it; compiled into two pipelines it may round differently,
///   each within the crate's every-conforming-adapter bound (`linear_depth::bounds`, under 17
///   ULP, `2^-19` relative), so `2^-18` between the two;
/// - **D24 in RGBA8**: the code is `round(z·(2^24 − 1))` of an f32 product, within one code of
///   `z`, so `Δz ≤ 1/(2^24 − 1)`; window depth has `|dz/dvz| = k·n/vz²` (`k = f/(f − n)`, 1 for
///   an infinite far plane, either convention), so `Δvz/vz ≤ vz·Δz/(k·n)`; plus the `2^-18` above.
pub fn depth_relative(storage: Storage, vz: f64, near: f64, far: f64) -> f64 {
    let base = 2f64.powi(-18);
    match storage {
        Storage::Diet {
            depth: DepthStorage::Code24Rgba8 | DepthStorage::Code24,
            ..
        } => {
            let k = if far.is_infinite() {
                1.0
            } else {
                far / (far - near)
            };
            vz / (16_777_215.0 * k * near) + base
        }
        _ => base,
    }
}

/// The frame-wide inputs of the bound.
pub struct Inputs<'a> {
    /// The diet frame's configuration (its storage and light layout).
    pub cfg: &'a Config,
    /// The fat G-buffer.
    pub fat: &'a FatGBuffer,
    /// The fat frame's linear colour.
    pub fat_colour: &'a [[f32; 4]],
    /// The lights, view space, as drawn.
    pub lights: &'a [LightGpu],
    /// Materials (their largest albedo, gloss and exponent `m` enter the bound).
    pub materials: &'a [Material],
    /// `tan(fov/2)`, x and y.
    pub tan_half_fov: Vec2,
    /// Near plane.
    pub near: f32,
}

/// One pixel's bound and the terms it came from.
#[derive(Clone, Copy, Debug, Default)]
pub struct PixelBound {
    /// Level bound per channel.
    pub levels: [f64; 3],
    /// Linear colour bound per channel (before the tone curve).
    pub linear: [f64; 3],
    /// Lights that can reach the pixel.
    pub lights: u32,
    /// The position error `ε_p`.
    pub eps_p: f64,
    /// The normal's angle bound `θ`, radians.
    pub theta: f64,
}

/// The bound at pixel `(x, y)`, or `None` where the fat normal is outside the encoding's domain
/// (`z < 0` for the hemisphere codes).
pub fn pixel(inp: &Inputs, x: u32, y: u32) -> Option<PixelBound> {
    let i = (y * inp.cfg.width + x) as usize;
    let outside = matches!(inp.cfg.storage, Storage::Diet { normal, .. }
        if hemisphere_only(normal) && inp.fat.normal[i][2] < 0.0 && inp.fat.view_z[i] > 0.0);
    (!outside).then(|| in_domain(inp, x, y))
}

/// The bound at pixel `(x, y)` as if its normal were inside the encoding's domain: where it is
/// not, a larger error shows the mirroring artefact.
pub fn in_domain(inp: &Inputs, x: u32, y: u32) -> PixelBound {
    let cfg = inp.cfg;
    let i = (y * cfg.width + x) as usize;
    let t = inp.fat.normal[i];
    let vz = f64::from(inp.fat.view_z[i]);
    let c_fat = inp.fat_colour[i];
    let Storage::Diet { normal, .. } = cfg.storage else {
        return PixelBound {
            levels: [1.0; 3],
            ..Default::default()
        };
    };
    if vz.is_nan() || vz <= 0.0 {
        // Sky: the same in both frames, only the rounding to a level.
        return PixelBound {
            levels: [1.0; 3],
            ..Default::default()
        };
    }
    let n = Vec3::new(t[0], t[1], t[2]).as_dvec3().normalize();
    let theta = normal_angle_at(normal, n.z);
    let power = f64::from(power_of_code(cfg.roughness, t[3] as u32));
    let ndc = Vec2::new(
        (x as f32 + 0.5) / cfg.width as f32 * 2.0 - 1.0,
        1.0 - (y as f32 + 0.5) / cfg.height as f32 * 2.0,
    );
    let ray = prepass::position::frustum_ray_rh(ndc, inp.tan_half_fov).as_dvec3();
    let p = ray * vz;
    let e = depth_relative(cfg.storage, vz, f64::from(inp.near), f64::from(cfg.far));
    let eps_p = e * p.length();
    let v = -p.normalize();
    let eps_v = 2.0 * eps_p / p.length();
    let sqrt_n = power.max(1.0).sqrt();
    // Sums: Σ col·ΔD, Σ col·ΔS, Σ col·D⁺, Σ col·S⁺ per channel, and the luminance versions.
    let (mut dd, mut ds, mut du, mut su) = ([0f64; 3], [0f64; 3], [0f64; 3], [0f64; 3]);
    let (mut ld, mut ls, mut ldu, mut lsu) = (0f64, 0f64, 0f64, 0f64);
    let mut k = 0u32;
    for l in inp.lights {
        let c = glam::DVec3::new(
            f64::from(l.pos_radius[0]),
            f64::from(l.pos_radius[1]),
            f64::from(l.pos_radius[2]),
        );
        let r = f64::from(l.pos_radius[3]);
        let to_l = c - p;
        let d = to_l.length();
        if d >= r + eps_p {
            continue;
        }
        let lu = to_l / d.max(1e-30);
        let eps_l = if d > 2.0 * eps_p {
            (2.0 * eps_p / d).min(2.0)
        } else {
            2.0
        };
        let window = |d: f64| {
            let x = (d / r).clamp(0.0, 1.0);
            (1.0 - x * x).powi(2)
        };
        let a_up = window((d - eps_p).max(0.0));
        let da = 8.0 / (3.0 * 3f64.sqrt() * r) * eps_p;
        let (s_up, ds_spot) = if l.colour_kind[3] > 0.5 {
            let axis = glam::DVec3::new(
                f64::from(l.axis_cos_outer[0]),
                f64::from(l.axis_cos_outer[1]),
                f64::from(l.axis_cos_outer[2]),
            )
            .normalize();
            let (co, ci) = (f64::from(l.axis_cos_outer[3]), f64::from(l.extra[0]));
            let cosang = axis.dot(-lu);
            let ramp = |c: f64| {
                if ci <= co {
                    if c >= co { 1.0 } else { 0.0 }
                } else {
                    ((c - co) / (ci - co)).clamp(0.0, 1.0)
                }
            };
            let slope = if ci > co {
                1.0 / (ci - co)
            } else {
                f64::INFINITY
            };
            (ramp(cosang + eps_l), (eps_l * slope).min(1.0))
        } else {
            (1.0, 0.0)
        };
        let att_up = (a_up * s_up).min(1.0);
        if att_up <= 0.0 {
            continue;
        }
        let datt = (da * s_up + a_up * ds_spot).min(1.0);
        let nl = n.dot(lu).max(0.0);
        let dnl = theta + eps_l;
        let nl_up = (nl + dnl).min(1.0);
        let d_diff = att_up * dnl + nl_up * datt;
        let d_up = nl_up * att_up;
        let hsum = lu + v;
        let hl = hsum.length();
        let h_chord = if hl > 1e-6 {
            (2.0 * (eps_l + eps_v) / hl).min(2.0)
        } else {
            2.0
        };
        let dphi = theta + std::f64::consts::FRAC_PI_2 * h_chord;
        let h = if hl > 1e-6 {
            n.dot(hsum / hl).clamp(1e-9, 1.0 - 1e-9)
        } else {
            0.5
        };
        let pow_rel = prepass::lighting::lpp::bounds::pow_relative(h, power);
        // f32 evaluation of the light's P in each frame, on any conforming adapter: the unit
        // vectors (lpp_direction, ≈ 3 ULP a component), the dot products, the window and the
        // products stay under 32 ULP of their terms: 64u relative, twice for the two frames.
        let eval = 2.0 * 64.0 * 2f64.powi(-24);
        let d_spec = d_diff + d_up * (sqrt_n * dphi + 2.0 * pow_rel + eval);
        let d_diff = d_diff + d_up * eval;
        let col = [
            f64::from(l.colour_kind[0]),
            f64::from(l.colour_kind[1]),
            f64::from(l.colour_kind[2]),
        ];
        let lum = 0.2126 * col[0] + 0.7152 * col[1] + 0.0722 * col[2];
        for ch in 0..3 {
            dd[ch] += col[ch] * d_diff;
            ds[ch] += col[ch] * d_spec;
            du[ch] += col[ch] * d_up;
            su[ch] += col[ch] * d_up;
        }
        ld += lum * d_diff;
        ls += lum * d_spec;
        ldu += lum * d_up;
        lsu += lum * d_up;
        k += 1;
    }
    // Blend rounding, both frames.
    let blend = |sum_up: f64| match cfg.light_format {
        LightFormat::Rgba16Float => 2.0 * f64::from(k) * (2f64.powi(-10) * sum_up + 2f64.powi(-24)),
        LightFormat::Rgba8Unorm => 2.0 * f64::from(k) / 255.0,
    };
    let a_max = inp
        .materials
        .iter()
        .map(|m| m.albedo_power[..3].iter().copied().fold(0f32, f32::max))
        .fold(0f32, f32::max) as f64;
    let g_max = inp
        .materials
        .iter()
        .map(|m| m.gloss_m[..3].iter().copied().fold(0f32, f32::max))
        .fold(0f32, f32::max) as f64;
    let m_max = inp
        .materials
        .iter()
        .map(|m| m.gloss_m[3])
        .fold(1f32, f32::max) as f64;
    let mut out = PixelBound {
        lights: k,
        eps_p,
        theta,
        ..Default::default()
    };
    for ch in 0..3 {
        let diffuse = dd[ch] + blend(du[ch]);
        let specular = match cfg.lights_layout {
            LightBuffers::Two => ds[ch] + blend(su[ch]),
            LightBuffers::One => {
                let d_a = ls + blend(lsu);
                let d_l = ld + blend(ldu);
                m_max * d_a + (m_max - 1.0).max(1.0) * d_l
            }
        };
        let c = f64::from(c_fat[ch]).max(0.0);
        let mut dc = a_max * diffuse + g_max * specular;
        dc += 2f64.powi(-10) * (2.0 * c + dc);
        out.linear[ch] = dc;
        let lo = super::compare::tonemap64((c - dc).max(0.0));
        let hi = super::compare::tonemap64(c + dc);
        // + 1 for the two roundings to a level, + 1e-9 for the f64 evaluation of the curve.
        out.levels[ch] = 255.0 * (hi - lo) + 1.0 + 1e-9;
    }
    out
}

/// The largest errors of a diet G-buffer against the fat one, each against its derived bound.
#[derive(Clone, Copy, Debug)]
pub struct GBufferError {
    /// Largest angle between a decoded and the fat normal (in the encoding's domain), degrees.
    pub angle_deg: f64,
    /// The largest angle / [`normal_angle_at`] over the pixels (≤ 1 when the bound holds).
    pub angle_ratio: f64,
    /// The texel of the largest ratio.
    pub angle_at: usize,
    /// Largest relative error of the rebuilt view depth.
    pub depth_rel: f64,
    /// The largest error / [`depth_relative`] over the pixels.
    pub depth_ratio: f64,
    /// The texel of the largest ratio.
    pub depth_at: usize,
}

/// Decode `row`'s diet G-buffer (read back from its render targets) with the crate's Rust twins
/// — bit-identical to the WGSL decoders — and measure it against the fat G-buffer at every
/// pixel with geometry: the normal against [`normal_angle_at`], the view depth against
/// [`depth_relative`]. The roughness code must be exact (an error names the texel).
pub fn gbuffer_error(
    row: &super::report::Row,
    fat: &FatGBuffer,
    scene: &super::scene::SceneData,
) -> Result<GBufferError, String> {
    use prepass::normal::{hemioct, oct, snorm8, xy_fp16, xyz8, xyz10};
    use prepass::projection::{DepthConvention, Projection};
    let diet = row
        .output
        .diet
        .as_ref()
        .ok_or("no diet G-buffer (multisampled frame)")?;
    let Storage::Diet { normal, depth } = row.cfg.storage else {
        return Err("the fat layout has no diet G-buffer".into());
    };
    let name = row.cfg.layout_name();
    let projection = Projection::new(scene.camera.near, row.cfg.far, row.cfg.convention)
        .map_err(|e| e.to_string())?;
    let free = super::shaders::alpha_free(normal);
    let mut g = GBufferError {
        angle_deg: 0.0,
        angle_ratio: 0.0,
        angle_at: 0,
        depth_rel: 0.0,
        depth_ratio: 0.0,
        depth_at: 0,
    };
    for (i, t) in fat.normal.iter().enumerate() {
        let vz = f64::from(fat.view_z[i]);
        if vz.is_nan() || vz <= 0.0 {
            continue;
        }
        let texel = |k: usize, size: usize| &diet.targets[k][size * i..size * (i + 1)];
        let b: [u8; 4] = match normal {
            NormalEncoding::Oct16 => [texel(0, 2)[0], texel(0, 2)[1], 0, 0],
            _ => texel(0, 4).try_into().map_err(|_| "texel size")?,
        };
        let c = b.map(|x| f32::from(x) / 255.0);
        let p = u32::from_le_bytes(b);
        let n = match normal {
            NormalEncoding::Xyz8 | NormalEncoding::Xyz8Best => xyz8::decode_normal_xyz8_unorm(c),
            NormalEncoding::XyFp16 => xy_fp16::decode_normal_xy_fp16_unorm(c),
            NormalEncoding::Hemioct24 => hemioct::decode_normal_hemioct24_unorm(c),
            NormalEncoding::Oct16 => oct::decode_normal_oct16(p),
            NormalEncoding::Oct24 => oct::decode_normal_oct24(p),
            NormalEncoding::Oct32 => oct::decode_normal_oct32(p),
            // The texel's bits are the code (rgb10a2 packs x low; snorm bytes are the code's).
            NormalEncoding::Xyz10 => xyz10::decode_normal_xyz10(p),
            NormalEncoding::Oct20 => oct::decode_normal_oct20(p),
            // B (bits 20–29) is 1023 or 0: bit 20 is the code's sign bit, bits 21–31 ignored.
            NormalEncoding::SignedOct => prepass::normal::signed_oct::decode_normal_signed_oct(p),
            // The r32uint texel is the word.
            NormalEncoding::Substrate => prepass::normal::substrate::decode_substrate_normal(p),
            NormalEncoding::Snorm8 => snorm8::decode_normal_snorm8(p),
            NormalEncoding::Oct24Unity => oct::decode_normal_oct24_unity(p),
        };
        let code = if free {
            u32::from(b[3])
        } else if normal == NormalEncoding::Substrate {
            // Bits 2–9 of the word: the byte decode_substrate_roughness reads.
            (p >> 2) & 0xff
        } else {
            u32::from(diet.targets.last().ok_or("no roughness target")?[i])
        };
        if code != t[3] as u32 {
            return Err(format!(
                "{name}: roughness code {code} at texel {i}, the fat G-buffer has {}",
                t[3]
            ));
        }
        let f = glam::DVec3::new(f64::from(t[0]), f64::from(t[1]), f64::from(t[2])).normalize();
        if !(hemisphere_only(normal) && f.z < 0.0) {
            let n = n.as_dvec3();
            let angle = f.cross(n).length().atan2(f.dot(n));
            let ratio = angle / normal_angle_at(normal, f.z);
            g.angle_deg = g.angle_deg.max(angle.to_degrees());
            if ratio > g.angle_ratio {
                (g.angle_ratio, g.angle_at) = (ratio, i);
            }
        }
        let vz_diet = match depth {
            DepthStorage::Code24Rgba8 => {
                let d = texel(1, 4);
                let code = (u32::from(d[0]) << 16) | (u32::from(d[1]) << 8) | u32::from(d[2]);
                match row.cfg.convention {
                    DepthConvention::Reversed => projection
                        .view_z_from_depth(prepass::depth24::hyperbolic_depth_from_depth24(code)),
                    DepthConvention::Standard => prepass::linear_depth::view_z_from_depth24_consts(
                        code,
                        projection
                            .depth24_consts()
                            .expect("a projection of the convention these constants read"),
                    ),
                }
            }
            _ => projection.view_z_from_depth(diet.depth.as_ref().ok_or("no depth read back")?[i]),
        };
        let rel = (f64::from(vz_diet) - vz).abs() / vz;
        let bound = depth_relative(
            row.cfg.storage,
            vz,
            f64::from(scene.camera.near),
            f64::from(row.cfg.far),
        );
        g.depth_rel = g.depth_rel.max(rel);
        if rel / bound > g.depth_ratio {
            (g.depth_ratio, g.depth_at) = (rel / bound, i);
        }
    }
    Ok(g)
}
