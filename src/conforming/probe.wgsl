// prepass conforming-adapter emulation: the host probe. Rust twin and expected results:
// src/conforming/probe.rs (check_host); tests: tests/conforming_probe.rs.
//
// Not valid on its own: it is appended to the PREPASS_CF_* prelude and core.wgsl (the helpers
// the emulation ships), so that the probe runs those very helpers on the host adapter. Every
// operand arrives at run time (columns, and prepass_cf_mode from a uniform), so the host's
// compiler sees the helpers as it sees them in an emulated module and can fold nothing.

// One probe case: kind 0 TwoSum (prepass_cf_two_sum) of x.x + x.y, kind 1 x.x * x.y and
// Dekker's product error (prepass_cf_mul_err), kind 2 the fused x.x * x.y + x.z
// (prepass_cf_fused), kind 3 the pack lane of x.x at scale x.y - 1 (prepass_cf_pack_lane, whose
// tie direction comes from Fast2Sum) with every direction-table word `dirs`; (value, error
// term), the error term 0 where a helper has none. `mode` is the table wrappers' mode: all
// zeros, read at run time.
fn prepass_cf_probe(kind: u32, x: vec4<f32>, dirs: u32, mode: vec4<u32>) -> vec2<f32> {
    prepass_cf_mode = mode;
    prepass_cf_dirs_lo = vec4<u32>(dirs);
    prepass_cf_dirs_hi = vec4<u32>(dirs);
    switch kind {
        case 0u: {
            return prepass_cf_two_sum(x.x, x.y);
        }
        case 1u: {
            let p = prepass_cf_opaque(x.x) * prepass_cf_opaque(x.y);
            return vec2<f32>(p, prepass_cf_mul_err(x.x, x.y, p));
        }
        case 2u: {
            return vec2<f32>(prepass_cf_fused(x.x, x.y, x.z), 0.0);
        }
        case 3u: {
            return vec2<f32>(prepass_cf_pack_lane(0u, x.x, x.y), 0.0);
        }
        default: {
            return vec2<f32>(0.0, 0.0);
        }
    }
}
