//! [`BUILDERS`]: arbitrary input → `Ok` with usable constants, or an `Err` naming a field.

use crate::{Entry, projection};
use prepass::projection::DepthConvention;

/// Builders: arbitrary input → `Ok` with usable constants, or an `Err` naming a field; never a
/// panic.
pub const BUILDERS: &[Entry] = &[
    Entry {
        name: "projection::Projection::new",
        check: |i| match projection(i) {
            Ok(p) => {
                // Documented: every per-pixel constant is finite and n·(2^24 − 1), n/f are normal
                // or zero (n/f = 0 exactly when far = +Inf).
                // Every convention's constants come from the one uniform; the per-convention
                // ones only for their own convention.
                let u = p.depth_uniform().to_wgsl();
                let k24 = [u[3].abs(), u[1]];
                assert_eq!(
                    u[3].is_sign_negative(),
                    p.convention() == DepthConvention::Reversed
                );
                for c in u.iter().take(3).chain(&k24) {
                    assert!(c.is_finite() && *c >= 0.0, "{p:?}: constant {c}");
                }
                match p.convention() {
                    DepthConvention::Standard => {
                        assert_eq!(p.depth24_consts().map(|k| k.to_wgsl()), Ok(k24));
                        assert_eq!(
                            p.depth_consts().map(|k| k.to_wgsl()),
                            Ok([u[0], u[1], u[2]])
                        );
                        assert!(p.reversed_depth_consts().is_err());
                    }
                    DepthConvention::Reversed => {
                        assert_eq!(
                            p.reversed_depth_consts().map(|k| k.to_wgsl()),
                            Ok([u[0], u[2], u[1]])
                        );
                        assert!(p.depth_consts().is_err() && p.depth24_consts().is_err());
                    }
                }
                assert!(k24[0].is_normal(), "{p:?}");
                assert_eq!(k24[1] == 0.0, p.is_infinite(), "{p:?}");
                assert!(k24[1] == 0.0 || k24[1].is_normal(), "{p:?}: n/f subnormal");
            }
            Err(e) => {
                assert!(e.field == "near" || e.field == "far", "{e}");
                assert!(e.to_string().contains(e.field));
            }
        },
    },
    Entry {
        name: "scene::Scene::{roots, gbuffer}",
        check: |i| {
            use prepass::scene::{DepthChoice, DepthStorage, PositionChoice, Scene};
            let b = i.u8();
            let storage = [
                DepthStorage::Float32,
                DepthStorage::Code24,
                DepthStorage::Code24Rgba8,
            ][usize::from(b % 3)];
            let convention = if b & 4 == 0 {
                DepthConvention::Standard
            } else {
                DepthConvention::Reversed
            };
            let position = [
                PositionChoice::None,
                PositionChoice::View,
                PositionChoice::World,
                PositionChoice::CameraRelative,
            ][usize::from((b >> 3) % 4)];
            use prepass::scene::{
                LightBuffers, LightingChoice, Lights, NormalChoice, NormalEncoding, NormalInput,
                RoughnessChoice, Specular,
            };
            let (n, l) = (i.u8(), i.u8());
            let scene = Scene {
                depth: DepthChoice {
                    storage,
                    convention,
                    infinite_far: b & 0x40 != 0,
                },
                position,
                normal: NormalChoice {
                    encoding: [None]
                        .into_iter()
                        .chain(NormalEncoding::ALL.map(Some))
                        .nth(usize::from(n % 7))
                        .flatten(),
                    fast_encoder: n & 0x80 != 0,
                },
                normal_input: if n & 0x20 != 0 {
                    NormalInput::Vouched
                } else {
                    NormalInput::Robust
                },
                roughness: if n & 0x40 != 0 {
                    RoughnessChoice::Log8
                } else {
                    RoughnessChoice::None
                },
                lighting: LightingChoice {
                    lights: [
                        Lights::None,
                        Lights::Point,
                        Lights::Spot,
                        Lights::PointAndSpot,
                    ][usize::from(l % 4)],
                    specular: [Specular::None, Specular::BlinnPhong, Specular::Phong]
                        [usize::from((l >> 2) % 3)],
                    buffers: if l & 0x10 != 0 {
                        LightBuffers::Two
                    } else {
                        LightBuffers::One
                    },
                    aggregate_vertex_lights: l & 0x20 != 0,
                    light_volumes: l & 0x40 != 0,
                },
            };
            match (scene.roots(), scene.gbuffer()) {
                (Ok(roots), Ok(g)) => {
                    assert!(!roots.is_empty());
                    let (w, h, s) = (
                        u64::from(i.u32() >> 16),
                        u64::from(i.u32() >> 16),
                        u64::from(i.u8() % 8 + 1),
                    );
                    assert_eq!(g.memory_bytes(w, h, s), g.bytes_per_pixel() * w * h * s);
                }
                (Err(e), Err(_)) => assert!(!e.fields.is_empty(), "{e}"),
                (r, g) => panic!("roots and gbuffer disagree on validity: {r:?} / {g:?}"),
            }
        },
    },
];
