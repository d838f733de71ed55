// prepass — God of War III's aggregate vertex lights (Vassily Filippov, "Dynamic lighting in
// GOW3", Sony Santa Monica; Advances in Real-Time Rendering in 3D Graphics and Games, SIGGRAPH
// 2011): per vertex, many lights are folded into one aggregate light whose position is
// interpolated per pixel.
// Rust twin: src/lighting/aggregate_light.rs. Tests: tests/aggregate_light.rs.
// Spaces, handedness, depth conventions, byte order, units, NaN policy: README.md, "Conventions".
//
// Per vertex V, for each light i with position P_i and weight W_i (its intensity at V):
//   acc.xyz = Σ W_i·L_i with L_i = (P_i − V)/|P_i − V|,   acc.w = Σ W_i/|P_i − V|
//   aggregate position  P_agg = V + acc.xyz / acc.w         (Filippov's "back to positions")
//   aggregate direction L_agg = acc.xyz / |acc.xyz|
//   aggregate colour    C_agg = Σ C_i (L_i · L_agg)
// Per pixel: C_agg · max(N · normalize(P_agg − p), 0) with P_agg interpolated.
// For scalar luminances l_i with every N·L_i >= 0 this is exact: (N·L_agg)·l_agg =
// N·(Σ l_i L_i) = Σ l_i (N·L_i), because l_agg = Σ l_i (L_i·L_agg) = |Σ l_i L_i|.
//
// Bad input (same on both sides): a light with any NaN/Inf input, or closer to the vertex than
// 2^-64 in every coordinate (its direction is undefined), is skipped (acc unchanged); weights
// and colours are clamped to [0, 2^40] (negative intensities add nothing). When the
// weighted directions cancel (largest component of acc.xyz zero or subnormal) the direction is
// zero, so every colour term is zero, and the position is the vertex itself; per pixel, a zero-length
// P_agg − p, a bad normal or non-finite input gives 0.

const AGGREGATE_LIGHT_WEIGHT_MAX = 1099511627776.0; // 2^40

// True when no component of v is NaN or ±Inf (judged from the bits).
fn aggregate_light_finite3(v: vec3<f32>) -> bool {
    return all((bitcast<vec3<u32>>(v) & vec3<u32>(0x7fffffffu)) < vec3<u32>(0x7f800000u));
}

// v/|v| scaled by its largest component first (no overflow), or zero when v is non-finite or
// its largest component is below `smallest` (bit pattern of a positive f32).
fn aggregate_light_unit(v: vec3<f32>, smallest: u32) -> vec3<f32> {
    let a = abs(v);
    let m = max(a.x, max(a.y, a.z));
    if (!aggregate_light_finite3(v) || bitcast<u32>(m) < smallest) {
        return vec3<f32>(0.0);
    }
    let s = v / m;
    return s * inverseSqrt(dot(s, s));
}

// Fold light i into a vertex's accumulator (start from vec4(0)).
fn aggregate_light_accumulate(acc: vec4<f32>, vertex: vec3<f32>, light_position: vec3<f32>,
                              weight: f32) -> vec4<f32> {
    let rel = light_position - vertex;
    let w_bits = bitcast<u32>(weight) & 0x7fffffffu;
    let a = abs(rel);
    let m = max(a.x, max(a.y, a.z));
    // 0x1f800000 = 2^-64
    if (!aggregate_light_finite3(vertex) || !aggregate_light_finite3(light_position)
        || !aggregate_light_finite3(rel) || w_bits >= 0x7f800000u || bitcast<u32>(m) < 0x1f800000u) {
        return acc;
    }
    let w = clamp(weight, 0.0, AGGREGATE_LIGHT_WEIGHT_MAX);
    let s = rel / m;
    let inv = inverseSqrt(dot(s, s));
    // |rel| = m/inv, so W/|rel| = W·inv/m.
    return acc + vec4<f32>(w * (s * inv), w * inv / m);
}

// The aggregate light's direction from the vertex, L_agg (zero when the directions cancel).
fn aggregate_light_direction(acc: vec4<f32>) -> vec3<f32> {
    return aggregate_light_unit(acc.xyz, 0x00800000u);
}

// The aggregate light's position V + acc.xyz/acc.w (the vertex when nothing was accumulated or
// the directions cancel).
fn aggregate_light_position(acc: vec4<f32>, vertex: vec3<f32>) -> vec3<f32> {
    let a = abs(acc.xyz);
    let m = max(a.x, max(a.y, a.z));
    if (!aggregate_light_finite3(acc.xyz) || !((bitcast<u32>(acc.w) & 0x7fffffffu) < 0x7f800000u)
        || bitcast<u32>(m) < 0x00800000u || !(acc.w > 0.0)) {
        return vertex;
    }
    return vertex + acc.xyz / acc.w;
}

// Fold light i's colour into the aggregate colour: colour_acc + C_i·(L_i·L_agg), Filippov's
// C_agg = Σ C_i (L_i·L_agg), unclamped (the identity needs every term).
fn aggregate_light_accumulate_colour(colour_acc: vec3<f32>, vertex: vec3<f32>,
                                     light_position: vec3<f32>, colour: vec3<f32>,
                                     aggregate_direction: vec3<f32>) -> vec3<f32> {
    let rel = light_position - vertex;
    let a = abs(rel);
    let m = max(a.x, max(a.y, a.z));
    if (!aggregate_light_finite3(vertex) || !aggregate_light_finite3(light_position)
        || !aggregate_light_finite3(rel) || !aggregate_light_finite3(colour)
        || !aggregate_light_finite3(aggregate_direction) || bitcast<u32>(m) < 0x1f800000u) {
        return colour_acc;
    }
    let l = aggregate_light_unit(rel, 0x1f800000u);
    let c = clamp(colour, vec3<f32>(0.0), vec3<f32>(AGGREGATE_LIGHT_WEIGHT_MAX));
    return colour_acc + c * dot(l, aggregate_direction);
}

// Per pixel: max(C_agg · max(N·normalize(P_agg − p), 0), 0) (an RGB C_agg can have a negative
// channel when lights of different colours oppose; light never subtracts).
fn aggregate_light_diffuse(normal: vec3<f32>, position: vec3<f32>, aggregate_position: vec3<f32>,
                           aggregate_colour: vec3<f32>) -> vec3<f32> {
    if (!aggregate_light_finite3(position) || !aggregate_light_finite3(aggregate_position)
        || !aggregate_light_finite3(aggregate_colour)) {
        return vec3<f32>(0.0);
    }
    let n = aggregate_light_unit(normal, 0x00800000u);
    let l = aggregate_light_unit(aggregate_position - position, 0x00800000u);
    return max(aggregate_colour * max(dot(n, l), 0.0), vec3<f32>(0.0));
}
