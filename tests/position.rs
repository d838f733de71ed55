//! `wgsl/position.wgsl` on the adapter: position rebuild error over the whole screen and fov
//! 1°…179°, world-space error against camera distance, the right-handed spelling, and the
//! full-screen triangle's corner rays interpolated by the real rasteriser.

mod common;

use common::{gpu, run_kernel};
use glam::{Mat3, Vec2, Vec3};
use prepass::assert_within;
use prepass::harness::Arg;
use prepass::linear_depth::exact;
use prepass::position as pos;
use prepass::precision::metrics::relative_error;
use prepass::wgsl::{LINEAR_DEPTH, POSITION};

const U: f64 = 1.0 / 16_777_216.0; // 2^-24: relative error of one correctly rounded operation

fn rebuild_source() -> String {
    format!(
        "{LINEAR_DEPTH}\n{POSITION}\n\
         fn rebuild(ndc: vec2<f32>, tan_half_fov: vec2<f32>, d: u32, nf: vec2<f32>) -> vec3<f32> {{\n\
             return view_position(frustum_ray(ndc, tan_half_fov), view_z_from_depth24(d, nf.x, nf.y));\n\
         }}\n\
         fn rebuild_rh(ndc: vec2<f32>, tan_half_fov: vec2<f32>, d: u32, nf: vec2<f32>) -> vec3<f32> {{\n\
             return view_position(frustum_ray_rh(ndc, tan_half_fov), view_z_from_depth24(d, nf.x, nf.y));\n\
         }}\n\
         fn vz_only(d: u32, nf: vec2<f32>) -> f32 {{ return view_z_from_depth24(d, nf.x, nf.y); }}\n"
    )
}

/// A `side`×`side` screen: each pixel's NDC centre, and a different depth code per pixel spread
/// over the whole range.
fn screen(side: usize) -> (Vec<[f32; 2]>, Vec<u32>) {
    let mut ndc = Vec::with_capacity(side * side);
    let mut codes = Vec::with_capacity(side * side);
    for j in 0..side {
        for i in 0..side {
            let x = (i as f32 + 0.5) / side as f32 * 2.0 - 1.0;
            let y = 1.0 - (j as f32 + 0.5) / side as f32 * 2.0;
            ndc.push([x, y]);
            codes.push(((i * side + j) as u32).wrapping_mul(0x9e37_79b9) >> 8);
        }
    }
    (ndc, codes)
}

/// The exact view-space position of pixel `ndc` at view distance `vz` (f64), left-handed.
fn exact_position(ndc: [f32; 2], tan: [f32; 2], vz: f64) -> [f64; 3] {
    [
        f64::from(ndc[0]) * f64::from(tan[0]) * vz,
        f64::from(ndc[1]) * f64::from(tan[1]) * vz,
        vz,
    ]
}

#[test]
fn view_position_within_view_z_error_plus_two_roundings_over_screen_and_fov() {
    let src = rebuild_source();
    let (near, far) = (0.1f32, 1.0e5f32);
    let side = 256usize;
    let mut worst = 0.0f64;
    for fov_deg in [1.0f64, 5.0, 30.0, 60.0, 90.0, 120.0, 150.0, 179.0] {
        let ty = (fov_deg.to_radians() / 2.0).tan() as f32;
        let tan = [ty * 16.0 / 9.0, ty];
        let (ndc, codes) = screen(side);
        let n = ndc.len() as u64;
        let args = [
            Arg::column(&ndc),
            Arg::splat_vec(&tan),
            Arg::column(&codes),
            Arg::splat_vec(&[near, far]),
        ];
        let p = run_kernel(&src, "rebuild", &args, n);
        let p_rh = run_kernel(&src, "rebuild_rh", &args, n);
        let vz = run_kernel(
            &src,
            "vz_only",
            &[Arg::column(&codes), Arg::splat_vec(&[near, far])],
            n,
        );
        for k in 0..ndc.len() {
            let vz_exact = exact::view_z_from_depth24(codes[k], near, far);
            let e_vz = relative_error(f64::from(vz.as_f32()[k]), vz_exact);
            let exact_p = exact_position(ndc[k], tan, vz_exact);
            // Bound: x and y pass two correctly rounded products (ndc·tan, then ·vz), each
            // ≤ 2^-24 relative, on top of vz's own error; second-order terms ≤ 2^-44.
            // z is 1·vz (exact): vz's error alone. In ULPs, 2·2^-24 relative is ≤ 2 ULP.
            for (c, exact_c) in exact_p.iter().enumerate() {
                let got = p.as_vec3()[k][c];
                let e = relative_error(f64::from(got), *exact_c);
                let (xy, which) = common::bound_here(
                    pos::bounds::XY_CORRECTLY_ROUNDED,
                    pos::bounds::XY_CONFORMING,
                );
                let bound = e_vz + if c < 2 { xy } else { 0.0 };
                assert_within!(
                    e,
                    bound,
                    format_args!(
                        "derived above: vz's own error + two rounded products \
                         (pos::bounds::XY_*, {which})"
                    ),
                    "fov {fov_deg}°, pixel {k}, component {c}: relative error"
                );
                worst = worst.max(e - e_vz);
                // Right-handed: the same x, y; z = −vz exactly.
                let rh = p_rh.as_vec3()[k][c];
                let want_rh = if c == 2 { -got } else { got };
                assert_eq!(rh.to_bits(), want_rh.to_bits(), "rh component {c}");
            }
            // The Rust twins give the same bits where the adapter evaluates like them (pure
            // products: nothing to fuse).
            let twin = pos::view_position(
                pos::frustum_ray(Vec2::from(ndc[k]), Vec2::from(tan)),
                prepass::linear_depth::view_z_from_depth24(codes[k], near, far),
            );
            if common::evaluates_like_the_twins() {
                assert_eq!(twin.to_array(), p.as_vec3()[k], "twin, pixel {k}");
            }
        }
    }
    eprintln!(
        "position rebuild: worst error beyond view z's own = {:.3} × 2^-24 relative",
        worst / U
    );
}

fn camera_rotation() -> Mat3 {
    // An arbitrary yaw/pitch/roll so that every world component mixes all three ray components.
    Mat3::from_euler(glam::EulerRot::YXZ, 0.7, -0.4, 0.25)
}

/// World-space and camera-relative rebuild: absolute error against camera distance, on the
/// adapter and on the emulated worst conforming adapter (every policy of `Policy::WORST`; the
/// matrix × vector product emulated as three dot products), each within the bound every
/// conforming adapter keeps (`position::bounds::world_abs`, `camera_relative_abs`). 64×64 rays of
/// a 53°-wide frustum, view distances 0.1…1000, one camera rotation mixing every component.
/// Published: docs/figures.md, block `position`.
#[test]
fn world_and_camera_relative_rebuild_on_the_adapter_and_under_emulation() {
    use prepass::conforming::{EmulatedKernel, Emulation, Policy};
    use std::fmt::Write as _;
    let src = format!(
        "{POSITION}\n\
         fn world_rebuild(ray: vec3<f32>, vz: f32, cam: vec3<f32>, c0: vec3<f32>, c1: vec3<f32>, c2: vec3<f32>) -> vec3<f32> {{\n\
             return world_position(world_ray(ray, mat3x3<f32>(c0, c1, c2)), vz, cam);\n\
         }}\n\
         fn relative_rebuild(ray: vec3<f32>, vz: f32, c0: vec3<f32>, c1: vec3<f32>, c2: vec3<f32>) -> vec3<f32> {{\n\
             return camera_relative_position(world_ray(ray, mat3x3<f32>(c0, c1, c2)), vz);\n\
         }}\n"
    );
    let m = camera_rotation();
    let cols = [m.x_axis, m.y_axis, m.z_axis].map(|c| c.to_array());
    let rows: [[f64; 3]; 3] =
        std::array::from_fn(|c| [cols[0][c], cols[1][c], cols[2][c]].map(f64::from));
    let dir = Vec3::new(0.6, 0.3, -0.742).normalize();
    let side = 64usize;
    let mut rays = Vec::new();
    let mut vzs = Vec::new();
    for j in 0..side {
        for i in 0..side {
            let ndc = Vec2::new(
                (i as f32 + 0.5) / side as f32 * 2.0 - 1.0,
                1.0 - (j as f32 + 0.5) / side as f32 * 2.0,
            );
            rays.push(pos::frustum_ray_rh(ndc, Vec2::new(1.0, 0.75)).to_array());
            vzs.push(10f32.powf(-1.0 + 4.0 * ((i * side + j) as f32 / (side * side) as f32)));
        }
    }
    let n = rays.len() as u64;
    // Per pixel and component: the exact offset, its rounding scale vz·Σ|m r|.
    let exact: Vec<[(f64, f64); 3]> = (0..rays.len())
        .map(|k| {
            let r = rays[k].map(f64::from);
            let vz = f64::from(vzs[k]);
            std::array::from_fn(|c| {
                let row = rows[c];
                let offset = (row[0] * r[0] + row[1] * r[1] + row[2] * r[2]) * vz;
                let scale =
                    ((row[0] * r[0]).abs() + (row[1] * r[1]).abs() + (row[2] * r[2]).abs()) * vz;
                (offset, scale)
            })
        })
        .collect();
    let emulated: Vec<(Policy, EmulatedKernel<'_>, EmulatedKernel<'_>)> = Policy::WORST
        .iter()
        .map(|&p| {
            let emu = Emulation::new(p);
            (
                p,
                EmulatedKernel::new(gpu(), &src, "world_rebuild", &emu).unwrap(),
                EmulatedKernel::new(gpu(), &src, "relative_rebuild", &emu).unwrap(),
            )
        })
        .collect();
    // The worst-case search (conforming::search::climb) runs on one module per function,
    // which every direction table shares.
    let searched = (
        EmulatedKernel::new(
            gpu(),
            &src,
            "world_rebuild",
            &Emulation::new(Policy::Searched),
        )
        .unwrap(),
        EmulatedKernel::new(
            gpu(),
            &src,
            "relative_rebuild",
            &Emulation::new(Policy::Searched),
        )
        .unwrap(),
    );
    let mut searched_slots = (u32::MAX, 0u32, true);
    // (searched pairs whose worst table beat every start table, pairs searched)
    let mut searched_beyond = (0usize, 0usize);
    let mut table = String::from(
        "| camera distance | world: this adapter | world: worst emulated (greedy policies) | world: worst found by the search | world: machine-derived bound | world: bound | camera-relative: this adapter | camera-relative: worst emulated (greedy policies) | camera-relative: worst found by the search | camera-relative: machine-derived bound | camera-relative: bound |\n|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    // The interval enclosure of every result a conforming adapter may give
    // (prepass::conforming::interval, flushing allowed), per pixel: each run must lie in it,
    // and the hand bound must hold its farther end.
    let enclosure = prepass::conforming::interval::Enclosure::new(&src, true).unwrap();
    let lanes_of = |name: &str, args: Vec<prepass::conforming::interval::Value>| {
        let v = enclosure
            .of(name, &args)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        v.f32_lanes().expect("vec3<f32>").to_vec()
    };
    let f = prepass::conforming::interval::Value::f32s;
    for exp10 in 0..=7 {
        let dist = 10f32.powi(exp10);
        let cam = (dir * dist).to_array();
        let world_args = [
            Arg::column(&rays),
            Arg::column(&vzs),
            Arg::splat_vec(&cam),
            Arg::splat_vec(&cols[0]),
            Arg::splat_vec(&cols[1]),
            Arg::splat_vec(&cols[2]),
        ];
        let rel_args = [
            Arg::column(&rays),
            Arg::column(&vzs),
            Arg::splat_vec(&cols[0]),
            Arg::splat_vec(&cols[1]),
            Arg::splat_vec(&cols[2]),
        ];
        // (name, world results, camera-relative results), the adapter's first.
        let mut runs = vec![(
            "this adapter".to_string(),
            run_kernel(&src, "world_rebuild", &world_args, n),
            run_kernel(&src, "relative_rebuild", &rel_args, n),
        )];
        for (p, w, r) in &emulated {
            let (wo, wf) = w.run(&world_args, n).unwrap();
            let (ro, rf) = r.run(&rel_args, n).unwrap();
            assert!(
                !wf.iter().chain(&rf).any(|&f| f),
                "{p}: an operation left the spec's domain on finite, normal inputs"
            );
            runs.push((format!("emulated {p}"), wo, ro));
        }
        let (mut world_max, mut rel_max) = (vec![0.0f64; runs.len()], vec![0.0f64; runs.len()]);
        let (mut world_bound_max, mut rel_bound_max) = (0.0f64, 0.0f64);
        let (mut world_machine, mut rel_machine) = (0.0f64, 0.0f64);
        let world_lanes = |k: usize| {
            lanes_of(
                "world_rebuild",
                vec![
                    f(&rays[k]),
                    f(&[vzs[k]]),
                    f(&cam),
                    f(&cols[0]),
                    f(&cols[1]),
                    f(&cols[2]),
                ],
            )
        };
        let relative_lanes = |k: usize| {
            lanes_of(
                "relative_rebuild",
                vec![
                    f(&rays[k]),
                    f(&[vzs[k]]),
                    f(&cols[0]),
                    f(&cols[1]),
                    f(&cols[2]),
                ],
            )
        };
        for (k, lanes) in exact.iter().enumerate() {
            let (w, r) = (world_lanes(k), relative_lanes(k));
            for (c, &(offset, scale)) in lanes.iter().enumerate() {
                let exact_w = f64::from(cam[c]) + offset;
                let far = |iv: prepass::conforming::interval::Iv, e: f64| {
                    (f64::from(iv.lo) - e)
                        .abs()
                        .max((f64::from(iv.hi) - e).abs())
                };
                let (mw, mr) = (far(w[c], exact_w), far(r[c], offset));
                assert_within!(
                    mw,
                    pos::bounds::world_abs(scale, exact_w.abs(), true),
                    "position::bounds::world_abs, against the machine-derived enclosure",
                    "world, cam {dist} m, pixel {k}, component {c}: {:?}",
                    w[c]
                );
                assert_within!(
                    mr,
                    pos::bounds::camera_relative_abs(scale, true),
                    "position::bounds::camera_relative_abs, against the machine-derived enclosure",
                    "camera-relative, cam {dist} m, pixel {k}, component {c}: {:?}",
                    r[c]
                );
                for (who, world, rel) in &runs {
                    let (gw, gr) = (world.as_vec3()[k][c], rel.as_vec3()[k][c]);
                    assert!(
                        w[c].lo <= gw && gw <= w[c].hi && r[c].lo <= gr && gr <= r[c].hi,
                        "{who}, cam {dist} m, pixel {k}, component {c}: world {gw:e} in {:?}, \
                         camera-relative {gr:e} in {:?}? Outside the enclosure of every allowed \
                         result: a flaw of the emulation or of conforming::interval",
                        w[c],
                        r[c]
                    );
                }
                world_machine = world_machine.max(mw);
                rel_machine = rel_machine.max(mr);
            }
        }
        for (slot, (who, world, rel)) in runs.iter().enumerate() {
            for (k, lanes) in exact.iter().enumerate() {
                for (c, &(offset, scale)) in lanes.iter().enumerate() {
                    let exact_w = f64::from(cam[c]) + offset;
                    let world_bound = pos::bounds::world_abs(scale, exact_w.abs(), true);
                    let rel_bound = pos::bounds::camera_relative_abs(scale, true);
                    let ew = (f64::from(world.as_vec3()[k][c]) - exact_w).abs();
                    let er = (f64::from(rel.as_vec3()[k][c]) - offset).abs();
                    assert_within!(
                        ew,
                        world_bound,
                        "position::bounds::world_abs (every conforming adapter)",
                        "{who}, world, cam {dist} m, pixel {k}, component {c}: absolute error"
                    );
                    assert_within!(
                        er,
                        rel_bound,
                        "position::bounds::camera_relative_abs (every conforming adapter)",
                        "{who}, camera-relative, cam {dist} m, pixel {k}, component {c}: absolute error"
                    );
                    world_max[slot] = world_max[slot].max(ew);
                    rel_max[slot] = rel_max[slot].max(er);
                    world_bound_max = world_bound_max.max(world_bound);
                    rel_bound_max = rel_bound_max.max(rel_bound);
                }
            }
        }
        // The search, at the SEARCHED (pixel, component) pairs the policies erred most on: the
        // worst table per pair, each result checked against the enclosure and the bound.
        let mut search = |world: bool| -> f64 {
            const SEARCHED: usize = 16;
            let exact_of = |k: usize, c: usize| {
                let offset = exact[k][c].0;
                if world {
                    f64::from(cam[c]) + offset
                } else {
                    offset
                }
            };
            let mut pairs: Vec<(f64, usize, usize)> = Vec::new();
            for k in 0..exact.len() {
                for c in 0..3 {
                    let e = runs[1..]
                        .iter()
                        .map(|(_, w, r)| {
                            let got = if world { w } else { r }.as_vec3()[k][c];
                            (f64::from(got) - exact_of(k, c)).abs()
                        })
                        .fold(0.0, f64::max);
                    pairs.push((e, k, c));
                }
            }
            pairs.sort_by(|a, b| b.0.total_cmp(&a.0));
            pairs.truncate(SEARCHED);
            let r: Vec<[f32; 3]> = pairs.iter().map(|&(_, k, _)| rays[k]).collect();
            let v: Vec<f32> = pairs.iter().map(|&(_, k, _)| vzs[k]).collect();
            let mut args = vec![Arg::column(&r), Arg::column(&v)];
            if world {
                args.push(Arg::splat_vec(&cam));
            }
            args.extend(cols.iter().map(|c| Arg::splat_vec(c)));
            let kernel = if world { &searched.0 } else { &searched.1 };
            let err = |i: usize, out: &prepass::harness::Output, e: usize| {
                let (_, k, c) = pairs[i];
                (f64::from(out.as_vec3()[e][c]) - exact_of(k, c)).abs()
            };
            let config = prepass::conforming::search::SearchConfig::default();
            let found =
                prepass::conforming::search::climb(kernel, &args, pairs.len(), &err, &config)
                    .unwrap();
            let plan: Vec<_> = found
                .iter()
                .enumerate()
                .map(|(i, f)| (i, f.table))
                .collect();
            let (out, flags) =
                prepass::conforming::search::run_at(kernel, &args, pairs.len(), &plan).unwrap();
            let mut worst = 0.0f64;
            for (i, &(_, k, c)) in pairs.iter().enumerate() {
                let got = out.as_vec3()[i][c];
                let iv = if world {
                    world_lanes(k)
                } else {
                    relative_lanes(k)
                }[c];
                let scale = exact[k][c].1;
                let bound = if world {
                    pos::bounds::world_abs(scale, exact_of(k, c).abs(), true)
                } else {
                    pos::bounds::camera_relative_abs(scale, true)
                };
                let e = (f64::from(got) - exact_of(k, c)).abs();
                assert!(
                    !flags[i] && iv.lo <= got && got <= iv.hi,
                    "searched, world {world}, cam {dist} m, pixel {k}, component {c}: {got:e} \
                     outside the enclosure {iv:?} of every allowed result (or outside the spec's \
                     domain: {}): a flaw of the emulation or of conforming::interval",
                    flags[i]
                );
                assert_within!(
                    e,
                    bound,
                    "position::bounds (every conforming adapter)",
                    "searched, world {world}, cam {dist} m, pixel {k}, component {c}: absolute error"
                );
                worst = worst.max(e);
            }
            for f in &found {
                searched_beyond.0 += usize::from(f.error > f.start_error);
                searched_beyond.1 += 1;
                searched_slots.0 = searched_slots.0.min(f.slots);
                searched_slots.1 = searched_slots.1.max(f.slots);
                searched_slots.2 &= f.slots <= config.exhaustive_slots;
            }
            worst
        };
        let (world_searched, rel_searched) = (search(true), search(false));
        let worst = |v: &[f64]| v[1..].iter().copied().fold(0.0, f64::max);
        let _ = writeln!(
            table,
            "| {dist:e} m | {:.3e} m | {:.3e} m | {world_searched:.3e} m | {world_machine:.3e} m | {world_bound_max:.3e} m | {:.3e} m | {:.3e} m | {rel_searched:.3e} m | {rel_machine:.3e} m | {rel_bound_max:.3e} m |",
            world_max[0],
            worst(&world_max),
            rel_max[0],
            worst(&rel_max)
        );
    }
    let _ = writeln!(
        table,
        "\nSearch: {}–{} slots read per pixel, {}; the climb improved on its best start table at {} of the {} (pixel, component) pairs searched.",
        searched_slots.0,
        searched_slots.1,
        if searched_slots.2 {
            "every assignment of them tried"
        } else {
            "steepest ascent from the upper, lower and two seeded tables"
        },
        searched_beyond.0,
        searched_beyond.1
    );
    eprint!("{table}");
    common::publish_measured("docs/figures.md", "position", &table);
}

#[test]
fn fullscreen_triangle_and_uv_helpers_match_their_twins() {
    let out = run_kernel(
        POSITION,
        "fullscreen_triangle_ndc",
        &[Arg::Index { start: 0 }],
        8,
    );
    for (i, v) in out.as_vec2().iter().enumerate() {
        assert_eq!(
            *v,
            pos::fullscreen_triangle_ndc(i as u32).to_array(),
            "vertex {i}"
        );
    }
    let tan = [0.9f32, 0.55];
    for (f, twin) in [
        (
            "fullscreen_triangle_ray",
            pos::fullscreen_triangle_ray as fn(u32, Vec2) -> Vec3,
        ),
        (
            "fullscreen_triangle_ray_rh",
            pos::fullscreen_triangle_ray_rh,
        ),
    ] {
        let out = run_kernel(
            POSITION,
            f,
            &[Arg::Index { start: 0 }, Arg::splat_vec(&tan)],
            3,
        );
        for (i, v) in out.as_vec3().iter().enumerate() {
            assert_eq!(
                *v,
                twin(i as u32, Vec2::from(tan)).to_array(),
                "{f} vertex {i}"
            );
        }
    }
    let uv: Vec<[f32; 2]> = (0..4096)
        .map(|k| [(k % 64) as f32 / 63.0, (k / 64) as f32 / 63.0])
        .collect();
    let out = run_kernel(
        POSITION,
        "ndc_from_uv",
        &[Arg::column(&uv)],
        uv.len() as u64,
    );
    for (k, v) in out.as_vec2().iter().enumerate() {
        // 2u is exact, so 2u − 1 has one rounding fused or not: bit-identical.
        assert_eq!(*v, pos::ndc_from_uv(Vec2::from(uv[k])).to_array());
    }
}

/// The vertex part through the real rasteriser: a full-screen triangle whose vertex stage emits
/// `fullscreen_triangle_ray`, interpolated by the hardware (or lavapipe) to every pixel.
#[test]
fn rasteriser_interpolates_corner_rays_to_each_pixels_ray() {
    let g = gpu();
    let (w, h) = (64u32, 48u32);
    let tan = Vec2::new(1.2, 0.9);
    let shader = format!(
        "{POSITION}\n\
         struct VsOut {{ @builtin(position) clip: vec4<f32>, @location(0) ray: vec3<f32> }};\n\
         @vertex fn vs(@builtin(vertex_index) i: u32) -> VsOut {{\n\
             return VsOut(vec4<f32>(fullscreen_triangle_ndc(i), 0.0, 1.0), fullscreen_triangle_ray(i, vec2<f32>({}, {})));\n\
         }}\n\
         @fragment fn fs(v: VsOut) -> @location(0) vec4<f32> {{ return vec4<f32>(v.ray, 1.0); }}\n",
        tan.x, tan.y
    );
    prepass::wgsl::parse_and_validate(&shader).unwrap();
    let device = g.device();
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: None,
        source: wgpu::ShaderSource::Wgsl(shader.into()),
    });
    let format = wgpu::TextureFormat::Rgba32Float;
    // Each pixel's interpolated ray is read back in full f32: the adapter must render to it.
    assert!(
        g.adapter()
            .get_texture_format_features(format)
            .allowed_usages
            .contains(wgpu::TextureUsages::RENDER_ATTACHMENT),
        "{} ({:?}) cannot render to Rgba32Float (wgpu's GL backend cannot), which this test \
         reads each pixel's interpolated ray from: run it on a Vulkan, Metal or Direct3D 12 \
         adapter (unset WGPU_BACKEND; lavapipe is one: bash .ci/setup-adapter)",
        g.adapter_info().name,
        g.adapter_info().backend
    );
    let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: None,
        layout: None,
        vertex: wgpu::VertexState {
            module: &module,
            entry_point: Some("vs"),
            compilation_options: Default::default(),
            buffers: &[],
        },
        fragment: Some(wgpu::FragmentState {
            module: &module,
            entry_point: Some("fs"),
            compilation_options: Default::default(),
            targets: &[Some(format.into())],
        }),
        primitive: Default::default(),
        depth_stencil: None,
        multisample: Default::default(),
        multiview_mask: None,
        cache: None,
    });
    let target = device.create_texture(&wgpu::TextureDescriptor {
        label: None,
        size: wgpu::Extent3d {
            width: w,
            height: h,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        view_formats: &[],
    });
    let bytes_per_row = w * 16; // 64 px × 16 B = 1024, a multiple of 256
    let readback = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: u64::from(bytes_per_row * h),
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    let view = target.create_view(&Default::default());
    let mut enc = device.create_command_encoder(&Default::default());
    {
        let mut pass = enc.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: None,
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &view,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
                    store: wgpu::StoreOp::Store,
                },
            })],
            ..Default::default()
        });
        pass.set_pipeline(&pipeline);
        pass.draw(0..3, 0..1);
    }
    enc.copy_texture_to_buffer(
        target.as_image_copy(),
        wgpu::TexelCopyBufferInfo {
            buffer: &readback,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(bytes_per_row),
                rows_per_image: None,
            },
        },
        wgpu::Extent3d {
            width: w,
            height: h,
            depth_or_array_layers: 1,
        },
    );
    g.queue().submit([enc.finish()]);
    let slice = readback.slice(..);
    slice.map_async(wgpu::MapMode::Read, |r| r.expect("map"));
    device.poll(wgpu::PollType::wait_indefinitely()).unwrap();
    let data: Vec<f32> = bytemuck::cast_slice(&slice.get_mapped_range().unwrap()).to_vec();
    // Requirement: the interpolated ray must pick out its own pixel — within 1/16 of the ray
    // step between neighbouring pixels (2·tan/width) — and z must stay exactly 1. Vulkan leaves
    // interpolation precision to the implementation, so this is a functional bound, not a ULP one.
    let step = (2.0 * tan.x / w as f32).min(2.0 * tan.y / h as f32);
    let mut worst = 0.0f32;
    for y in 0..h {
        for x in 0..w {
            let k = ((y * w + x) * 4) as usize;
            let got = Vec3::new(data[k], data[k + 1], data[k + 2]);
            let ndc = Vec2::new(
                (x as f32 + 0.5) / w as f32 * 2.0 - 1.0,
                1.0 - (y as f32 + 0.5) / h as f32 * 2.0,
            );
            let want = pos::frustum_ray(ndc, tan);
            let err = (got - want).abs().max_element();
            worst = worst.max(err);
            assert_within!(
                err,
                step / 16.0,
                "requirement above: 1/16 of the ray step, the ray picks out its own pixel",
                "pixel ({x}, {y}): {got} vs {want}"
            );
        }
    }
    eprintln!(
        "rasterised corner rays: worst error {worst:e} = {:.2e} of a pixel step",
        worst / step
    );
}

/// The same rebuild on the emulated worst conforming adapter: each of x and y is two products
/// (`ndc·tan`, then `·vz`), each rounded to either neighbour (≤ 2·2^-24 relative), on top of view
/// z's own (emulated) error; z is `1·vz`, exact. 64×64 pixels at four fields of view, every
/// worst-case policy.
#[test]
fn view_position_within_view_z_error_plus_two_roundings_under_emulation() {
    use prepass::conforming::{EmulatedKernel, Emulation, Policy};
    let src = rebuild_source();
    let (near, far) = (0.1f32, 1.0e5f32);
    let side = 64usize;
    for policy in Policy::WORST {
        let emu = Emulation::new(policy);
        let rebuild = EmulatedKernel::new(gpu(), &src, "rebuild", &emu).unwrap();
        let vz_only = EmulatedKernel::new(gpu(), &src, "vz_only", &emu).unwrap();
        let mut worst = 0.0f64;
        for fov_deg in [1.0f64, 60.0, 120.0, 179.0] {
            let ty = (fov_deg.to_radians() / 2.0).tan() as f32;
            let tan = [ty * 16.0 / 9.0, ty];
            let (ndc, codes) = screen(side);
            let n = ndc.len() as u64;
            let nf = [near, far];
            let args = [
                Arg::column(&ndc),
                Arg::splat_vec(&tan),
                Arg::column(&codes),
                Arg::splat_vec(&nf),
            ];
            let (p, _) = rebuild.run(&args, n).unwrap();
            let (vz, _) = vz_only
                .run(&[Arg::column(&codes), Arg::splat_vec(&nf)], n)
                .unwrap();
            for k in 0..ndc.len() {
                let vz_exact = exact::view_z_from_depth24(codes[k], near, far);
                let e_vz = relative_error(f64::from(vz.as_f32()[k]), vz_exact);
                let exact_p = exact_position(ndc[k], tan, vz_exact);
                for (c, exact_c) in exact_p.iter().enumerate() {
                    let e = relative_error(f64::from(p.as_vec3()[k][c]), *exact_c);
                    let bound = e_vz
                        + if c < 2 {
                            pos::bounds::XY_CONFORMING
                        } else {
                            0.0
                        };
                    assert_within!(
                        e,
                        bound,
                        "view z's own error + two either-neighbour products, 4·2^-24, + 2^-42",
                        "{policy}, fov {fov_deg}°, pixel {k}, component {c}: relative error (vz's own {e_vz:e})"
                    );
                    worst = worst.max(e - e_vz);
                }
            }
        }
        eprintln!(
            "emulated {policy}: position rebuild worst error beyond view z's own = {:.3} × 2^-24 relative (bound 4)",
            worst / U
        );
    }
}
